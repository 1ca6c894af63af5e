// `glimmer check --web`: will the script's shaders run in WebGL 2? Every
// Program's stages translated to GLSL ES 3.00 (shader/web_translate.h), on
// the CPU, with no OpenGL context: a teacher asks before class.
#pragma once
#include <iosfwd>

#include "pipeline/load_script.h"
#include "pipeline/options.h"

namespace glimmer {

// Translates every stage of every Program of a planned and loaded script.
// A Program with a stage WebGL 2 lacks gets one error at its line in the
// script, naming the stage and the reason; each translation error points at
// the shader's file and line. False when any error was added.
bool checkProgramsForWeb(const LoadedScript& script, Diagnostics& diags);

// The whole command: load, plan, read files, translate, print. The exit code.
// `inputs`: where to list every file the script reads after a clean check
// (check --list-inputs), or null.
int runWebCheck(const CommonOptions& options, std::ostream* inputs = nullptr);

}  // namespace glimmer
