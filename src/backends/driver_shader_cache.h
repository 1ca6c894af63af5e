// Turns off Mesa's on-disk shader cache for this process, before the driver
// is loaded, so a shader's compile log never depends on what ran before.
//
// Why: when a shader's source is already in Mesa's disk cache, Mesa links
// the cached program without running the compiler, and the info log is
// empty. A shader with a warning ("`P0' used uninitialized") showed it on a
// cold cache and not on a warm one: a student saw driver warnings on the
// first run and not the next, a grader's report differed between two runs of
// the same class, and a test passed only on a machine that had run it before
// (issue 18). Glimmer reads every log (gl/compiler_log.cpp), so under Mesa it
// compiles for real.
//
// NVIDIA's driver is left alone: measured on an H100, its disk cache keeps
// the compile log with the cached shader (the same warning on a cold and a
// warm run), and turning it off would cost 40 to 130 ms a script there
// against a few ms on llvmpipe. docs/PERFORMANCE.md, "Compile logs and the
// driver's shader cache", has the figures (tools/bench-shader-cache.sh).
//
// The variables, read by Mesa when it creates a screen:
//   MESA_SHADER_CACHE_DISABLE=true   Mesa 21 and later
//   MESA_GLSL_CACHE_DISABLE=true     Mesa before 21 (ignored by later ones)
// GLIMMER_DRIVER_SHADER_CACHE=1 leaves them alone: for measuring what the
// cache saves, not for grading.
#pragma once

namespace glimmer {

// Sets the variables above unless GLIMMER_DRIVER_SHADER_CACHE=1. Each
// backend calls it before it loads a driver. Returns whether it set them.
bool disableMesaShaderCache();

}  // namespace glimmer
