// OpenGL ES precision qualifiers in desktop GLSL below 1.30, as text.
// NVIDIA's drivers accept `precision highp float;` and `highp`, `mediump`,
// `lowp` on declarations in any version; Mesa refuses them before GLSL 1.30
// ("illegal use of reserved word `precision'"). On desktop GL they never
// change anything (GLSL 1.30 section 4.5: "no semantic meaning"), so they
// are blanked out where the version has none.
//
// Contract: only for a shader whose #version is below 130 (none: 110); the
// output has the input's lines and columns (blanked text becomes spaces);
// comments, strings and preprocessor lines are left alone.
#pragma once
#include <string>
#include <string_view>

namespace glimmer {

struct PrecisionStripResult {
    std::string text;
    int firstLine = 0;  // 1-based line of the first qualifier blanked; 0: none (text is the input)
    bool changed() const { return firstLine > 0; }
};

PrecisionStripResult stripPrecisionQualifiers(std::string_view source);

}  // namespace glimmer
