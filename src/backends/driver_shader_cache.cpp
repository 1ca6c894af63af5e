#include "backends/driver_shader_cache.h"

#include <cstdlib>
#include <cstring>

namespace glimmer {

bool disableMesaShaderCache() {
    const char* keep = std::getenv("GLIMMER_DRIVER_SHADER_CACHE");
    if (keep && std::strcmp(keep, "1") == 0) return false;
    // Overwritten even when the user set them: a log that depends on an
    // earlier run is what this prevents.
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    setenv("MESA_GLSL_CACHE_DISABLE", "true", 1);
    return true;
}

}  // namespace glimmer
