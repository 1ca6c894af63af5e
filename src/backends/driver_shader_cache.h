// Turns off the GL driver's on-disk shader cache for this process, before
// the driver is loaded, so a shader's compile log never depends on what ran
// before.
//
// Why: Mesa (and NVIDIA's driver likewise) skips the compiler when a
// shader's source is already in its disk cache, and then the info log is
// empty. A shader with a warning ("`P0' used uninitialized") showed it on a
// cold cache and not on a warm one: a student saw driver warnings on the
// first run and not the next, a grader's report differed between two runs of
// the same class, and a test passed only on a machine that had run it before.
// Glimmer reads every log (gl/compiler_log.cpp), so it compiles for real.
//
// The cost, measured (docs/PERFORMANCE.md, "Compile logs without the driver's
// disk cache"): a few milliseconds per program on llvmpipe and on a GPU.
//
// The variables, each read by its driver when it loads:
//   MESA_SHADER_CACHE_DISABLE=true   Mesa 21 and later
//   MESA_GLSL_CACHE_DISABLE=true     Mesa before 21 (ignored by later ones)
//   __GL_SHADER_DISK_CACHE=0         NVIDIA's proprietary driver
// GLIMMER_DRIVER_SHADER_CACHE=1 leaves them alone: for measuring what the
// cache saves (tools/bench-shader-cache.sh), not for grading.
#pragma once

namespace glimmer {

// Sets the variables above unless GLIMMER_DRIVER_SHADER_CACHE=1. Call it
// before the first context of the process is made (each backend does).
// Returns whether the cache is off.
bool disableDriverShaderCache();

}  // namespace glimmer
