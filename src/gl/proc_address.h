// How a backend hands the renderer its GL entry points: a function from a
// name to an address (OSMesaGetProcAddress, eglGetProcAddress,
// glfwGetProcAddress). Kept apart from gl_api.h so front ends and backends
// can pass one along without including any OpenGL header.
#pragma once
#include <functional>

namespace glimmer {

using GetProcAddress = std::function<void*(const char* name)>;

}  // namespace glimmer
