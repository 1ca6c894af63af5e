// Compiling and linking a Program's shaders, with compiler messages mapped
// back to the shader file and line the user wrote.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "gl/gl_api.h"
#include "lang/diagnostics.h"
#include "plan/plan.h"

namespace glimmer {

// glman's GSTAP: new-style names for the old built-ins, put after #version.
extern const char* const kGstapPrelude;

// The shader text as compiled: `prelude` inserted after the #version line
// (or at the top). `insertedAfter` is the line it went after (0 = top) and
// `insertedLines` how many lines it holds, so log lines map back.
struct PreparedSource {
    std::string text;
    int insertedAfter = 0;
    int insertedLines = 0;
    int originalLine(int compiledLine) const;
};
PreparedSource prepareSource(const std::string& source, const std::string& prelude);

// Turns a driver's info log (Mesa "0:12(5): error: ..." or NVIDIA
// "0(12) : error C1008: ...") into diagnostics against `file`. Lines that
// match neither form are kept as one message at `fallback`.
void mapCompilerLog(const std::string& log, const PreparedSource& src, const std::string& file,
                    const std::string& fallbackFile, SourceLoc fallback, Severity defaultSeverity,
                    Diagnostics& diags);

// Compiles and links every stage of `decl` from its text (read by the CPU
// load step, assets/; nullopt for a stage that could not be read, which is
// already an error). Returns the program (0 on failure, with diagnostics).
unsigned buildProgram(const GlApi& gl, const ProgramDecl& decl,
                      const std::vector<std::optional<std::string>>& stageTexts, const std::string& scriptFile,
                      Diagnostics& diags);

// A vertex + fragment program from two texts, with no script behind it (the
// hand-written texel-rate probe, gl/texel_rate.cpp): 0 when either stage
// fails to compile or the program to link. glimmer-bench's hand-written
// reference keeps its own unchecked compile on purpose: its compile time is
// the figure Glimmer's is compared with, measured as it always was.
unsigned buildPlainProgram(const GlApi& gl, const std::string& vertex, const std::string& fragment);

// The attribute location glman's `Tangent` is bound to before linking.
constexpr int kTangentLocation = 7;

}  // namespace glimmer
