#include "gl/shader_build.h"
#include "shader/watch_rewrite.h"
#include "gl/builtin_feed.h"
#include "shader/glsl_scan.h"
#include "shader/uninitialized_globals.h"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "shader/translation_cache.h"
#include "shader/web_stage.h"

namespace glimmer {

const char* const kGstapPrelude =
    "#define uModelViewMatrix gl_ModelViewMatrix\n"
    "#define uProjectionMatrix gl_ProjectionMatrix\n"
    "#define uModelViewProjectionMatrix gl_ModelViewProjectionMatrix\n"
    "#define uNormalMatrix gl_NormalMatrix\n"
    "#define uModelViewMatrixInverse gl_ModelViewMatrixInverse\n"
    "#define aVertex gl_Vertex\n"
    "#define aNormal gl_Normal\n"
    "#define aColor gl_Color\n"
    "#define aTexCoord0 gl_MultiTexCoord0\n"
    "#define aTexCoord1 gl_MultiTexCoord1\n"
    "#define aTexCoord2 gl_MultiTexCoord2\n"
    "#define aTexCoord3 gl_MultiTexCoord3\n"
    "#define aTexCoord4 gl_MultiTexCoord4\n"
    "#define aTexCoord5 gl_MultiTexCoord5\n"
    "#define aTexCoord6 gl_MultiTexCoord6\n"
    "#define aTexCoord7 gl_MultiTexCoord7\n";

int PreparedSource::originalLine(int compiledLine) const {
    if (compiledLine <= insertedAfter) return compiledLine;
    if (compiledLine <= insertedAfter + insertedLines) return insertedAfter;  // inside the prelude
    return compiledLine - insertedLines;
}

PreparedSource prepareSource(const std::string& source, const std::string& prelude) {
    PreparedSource out;
    if (prelude.empty()) {
        out.text = source;
        return out;
    }
    // #version must stay the first thing the compiler sees, so the prelude
    // goes after it. Line numbers are mapped back rather than fixed with
    // #line, whose meaning changed between GLSL versions.
    // The one #version reader (shader/glsl_scan.h): one in a comment does not count.
    const int versionLine = glslVersionOf(source).line;
    out.insertedAfter = versionLine;
    for (char ch : prelude) out.insertedLines += ch == '\n';
    size_t cut = 0;
    for (int i = 0; i < versionLine; ++i) cut = source.find('\n', cut) + 1;
    if (versionLine > 0 && cut == 0) {  // #version on the last line without a newline
        out.text = source + "\n" + prelude;
        return out;
    }
    out.text = source.substr(0, cut) + prelude + source.substr(cut);
    return out;
}

namespace {

GLenum stageEnum(ShaderStage::Kind k) {
    switch (k) {
    case ShaderStage::Kind::Vertex: return GL_VERTEX_SHADER;
    case ShaderStage::Kind::Fragment: return GL_FRAGMENT_SHADER;
    case ShaderStage::Kind::Geometry: return GL_GEOMETRY_SHADER;
    case ShaderStage::Kind::TessControl: return GL_TESS_CONTROL_SHADER;
    case ShaderStage::Kind::TessEvaluation: return GL_TESS_EVALUATION_SHADER;
    }
    return GL_VERTEX_SHADER;
}

std::string infoLog(const GlApi& gl, unsigned object, bool isProgram) {
    GLint length = 0;
    if (isProgram) gl.GetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else gl.GetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    // A driver's log is bounded too: a hostile shader can make it huge.
    length = std::clamp(length, 1, 1 << 20);
    std::string log(size_t(length), '\0');
    if (isProgram) gl.GetProgramInfoLog(object, length, nullptr, log.data());
    else gl.GetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

// Mesa's "`gK' used uninitialized" about a global that main sets before it
// calls any function is a false alarm (shader/uninitialized_globals.h): it
// becomes a note that says so, and the true ones stay warnings.
Diagnostic judgeUninitialized(Diagnostic d, const std::string& text) {
    const std::string tail = "' used uninitialized";
    const std::string& m = d.message;
    if (d.severity != Severity::Warning || m.size() < tail.size() + 2 || m[0] != '`' ||
        m.compare(m.size() - tail.size(), tail.size(), tail) != 0)
        return d;
    const std::string name = m.substr(1, m.size() - tail.size() - 1);
    if (int line = globalSetByMainFirst(text, name, d.loc.line); line > 0) {
        d.severity = Severity::Note;
        d.fromDriver = false;
        d.message = fmt::format("the driver's warning \"{}\" is a false alarm: main sets the global {} (line {}) "
                                "before it calls any function", m, name, line);
    }
    return d;
}

// Mesa's words for a const whose initialiser is not a constant expression.
const char* const kConstInitializer = "initializer of const variable `";
const char* const kLocalConstExtension = "#extension GL_ARB_shading_language_420pack : enable\n";

// Mesa's "initializer of const variable `k2' must be a constant expression".
bool isConstInitializerError(const Diagnostic& d) { return d.message.rfind(kConstInitializer, 0) == 0; }

// "`k2'" from Mesa's "initializer of const variable `k2' must be ...".
std::string constName(const std::string& message) {
    size_t open = message.find('`'), close = message.find('\'', open + 1);
    return open == std::string::npos || close == std::string::npos ? std::string("?")
                                                                    : message.substr(open, close - open + 1);
}

// A `#version N` line with no profile word and N >= 150 (the core profile,
// GLSL 1.50 on): its line (1-based) and number; 0 when the text has none.
// Only the first directive counts, as for the compiler.
int profilelessVersionLine(const std::string& text, int& version) {
    GlslVersion v = glslVersionOf(text);
    if (v.line == 0 || !v.wellFormed) return 0;
    version = v.number;
    return version >= 150 && v.profile.empty() ? v.line : 0;
}

// `text` with " compatibility" after the number of its `#version` on `line`
// (where the lexer read it: a comment before the directive or a continued
// line moves nothing).
std::string withCompatibilityProfile(const std::string& text, int line) {
    const GlslVersion v = glslVersionOf(text);
    if (v.line != line || v.numberEnd == std::string::npos) return text;
    return text.substr(0, v.numberEnd) + " compatibility" + text.substr(v.numberEnd);
}

// The warning for a local const whose initialiser is not constant (Mesa's `message`).
std::string localConstAccepted(const std::string& message) {
    return fmt::format("a local const set from a non-constant expression ({}): accepted, as GLSL 4.20 allows and "
                       "NVIDIA does in any version; GL_ARB_shading_language_420pack turned on for this shader",
                       constName(message));
}


// The first compatibility built-in an error of the log names as undeclared
// ("gl_Vertex"); "" when none does.
std::string undeclaredBuiltin(const Diagnostics& said) {
    for (const auto& d : said.all()) {
        if (d.severity != Severity::Error || d.message.find("undeclared") == std::string::npos) continue;
        if (std::string name = firstWordWithPrefix(d.message, "gl_"); !name.empty()) return name;
    }
    return {};
}

struct Compiled {
    unsigned shader = 0;
    GLint status = 0;
    std::string log;
    Diagnostics said;  // the log, against the user's file and lines
};

Compiled compileStage(const GlApi& gl, const ShaderStage& stage, const std::string& text, const std::string& prelude,
                      const std::string& scriptFile) {
    Compiled c;
    PreparedSource src = prepareSource(text, prelude);
    c.shader = gl.CreateShader(stageEnum(stage.kind));
    const char* p = src.text.c_str();
    gl.ShaderSource(c.shader, 1, &p, nullptr);
    gl.CompileShader(c.shader);
    gl.GetShaderiv(c.shader, GL_COMPILE_STATUS, &c.status);
    c.log = infoLog(gl, c.shader, false);
    if (!c.log.empty())
        mapCompilerLog(c.log, src, stage.path, scriptFile, stage.loc, c.status ? Severity::Warning : Severity::Error,
                       c.said);
    return c;
}

// Sets the uniforms a translation took the initialisers of, as a desktop
// driver would have from the text: once, when the program is made; what the
// script sets is uploaded over them each frame.
void setInitialValues(const GlApi& gl, unsigned program, const std::vector<UniformInitializer>& values) {
    if (values.empty()) return;
    gl.UseProgram(program);
    for (const auto& u : values) {
        GLint at = gl.GetUniformLocation(program, u.name.c_str());
        if (at < 0 || u.values.empty() || u.values.size() > 4) continue;
        const GLsizei n = GLsizei(u.values.size());
        if (u.type.find("vec") == std::string::npos ? u.type != "float" : u.type[0] != 'v') {
            std::vector<GLint> ints(u.values.begin(), u.values.end());
            (n == 1 ? gl.Uniform1iv : n == 2 ? gl.Uniform2iv : n == 3 ? gl.Uniform3iv : gl.Uniform4iv)(at, 1, ints.data());
        } else {
            (n == 1 ? gl.Uniform1fv : n == 2 ? gl.Uniform2fv : n == 3 ? gl.Uniform3fv : gl.Uniform4fv)(at, 1,
                                                                                                 u.values.data());
        }
    }
    gl.UseProgram(0);
}

// Links `shaders` into a new program; 0 with the driver's log in `log`.
unsigned linkShaders(const GlApi& gl, const std::vector<unsigned>& shaders, std::string& log) {
    unsigned program = gl.CreateProgram();
    for (unsigned sh : shaders) gl.AttachShader(program, sh);
    gl.BindAttribLocation(program, kTangentLocation, "Tangent");
    bindBuiltinAttributes(gl, program);  // glimmer_Vertex and the others, where declared
    // A watch's two outputs (shader/watch_rewrite.h) in GLSL 1.30 to 1.50,
    // which cannot say their locations: bound here (a name the program lacks
    // is ignored; ES takes the locations the text gives).
    if (gl.BindFragDataLocation) {
        gl.BindFragDataLocation(program, 0, std::string(kWatchValueOut).c_str());
        gl.BindFragDataLocation(program, 1, std::string(kWatchInfoOut).c_str());
    }
    gl.LinkProgram(program);
    GLint status = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &status);
    if (status) return program;
    log = infoLog(gl, program, true);
    gl.DeleteProgram(program);
    return 0;
}

}  // namespace

unsigned buildProgram(const GlApi& gl, const ProgramDecl& decl,
                      const std::vector<std::optional<std::string>>& stageTexts, const std::string& scriptFile,
                      Diagnostics& diags) {
    std::vector<unsigned> shaders;
    // Desktop stages that say `#version N` (N >= 150) with no profile while
    // compiled as they are: the core profile, whose gl_PerVertex differs
    // from the compatibility one (index into `shaders`, the stage, its text).
    struct CoreStage {
        size_t shader;
        const ShaderStage* stage;
        const std::string* text;
        std::string prelude;
        int line, version;
    };
    std::vector<CoreStage> coreStages;
    bool anyCompatibility = false;
    std::vector<UniformInitializer> initialValues;  // the page: uniform initialisers taken out in translation
    bool ok = true;
    for (size_t k = 0; k < decl.stages.size(); ++k) {
        const ShaderStage& stage = decl.stages[k];
        if (k >= stageTexts.size() || !stageTexts[k]) {  // unreadable: the load step said so
            ok = false;
            continue;
        }
        const std::string& text = *stageTexts[k];
        std::string prelude = decl.gstap ? kGstapPrelude : "";
        // An OpenGL ES context (WebGL 2's level) compiles only GLSL ES: a
        // desktop shader is translated first (shader/web_translate.h), its
        // errors against the user's lines; GSTAP's aliases go with it.
        if (gl.es && !isGlslEs300(text)) {
            WebTranslation t = translateForWebCached({text, webStage(stage.kind), stage.path, prelude}, diags);
            if (!t.ok) {
                ok = false;
                continue;
            }
            initialValues.insert(initialValues.end(), t.initialValues.begin(), t.initialValues.end());
            Compiled c = compileStage(gl, stage, t.text, "", scriptFile);
            // The lines are the translation's, not the user's: the driver's
            // word against the file, and only when it refuses (its warnings
            // on generated text would point nowhere useful).
            if (!c.status) {
                diags.error(stage.path, {}, "the OpenGL ES driver refused the translation for GLSL ES 3.00: " + c.log);
                ok = false;
            }
            shaders.push_back(c.shader);
            continue;
        }
        Compiled c = compileStage(gl, stage, text, prelude, scriptFile);
        // `#version 400` with no profile word is the core profile (GLSL 1.50
        // on), which has no gl_Vertex, gl_ModelViewProjectionMatrix,
        // gl_FragColor...; NVIDIA's driver compiles such a shader in a
        // compatibility context as if it said `compatibility`, and classroom
        // scripts rely on it. Compiled again with the word added (lines keep
        // their numbers), and said.
        int version = 0;
        bool madeCompatibility = false;
        if (int line = !c.status ? profilelessVersionLine(text, version) : 0; line > 0) {
            if (std::string builtin = undeclaredBuiltin(c.said); !builtin.empty()) {
                Compiled again = compileStage(gl, stage, withCompatibilityProfile(text, line), prelude, scriptFile);
                if (again.status) {
                    gl.DeleteShader(c.shader);
                    c = std::move(again);
                    madeCompatibility = true;
                    diags.warning(stage.path, {line, 1},
                                  fmt::format("'#version {0}' with no profile is the core profile, which has no {1}: "
                                              "compiled as '#version {0} compatibility', as NVIDIA's driver does; "
                                              "write 'compatibility' after {0} to run everywhere",
                                              version, builtin));
                } else {
                    gl.DeleteShader(again.shader);
                }
            }
        }
        // NVIDIA accepts a local const initialised from a non-constant
        // expression in any GLSL version; GLSL 4.20 allows it for locals
        // (ARB_shading_language_420pack), so Mesa does too once that is on.
        std::optional<Diagnostic> hint;
        if (!c.status) {
            SourceLoc at;
            std::string what;
            for (const auto& d : c.said.all())
                if (what.empty() && isConstInitializerError(d)) at = d.loc, what = d.message;
            if (!what.empty()) {
                Compiled again = compileStage(gl, stage, text, prelude + kLocalConstExtension, scriptFile);
                if (again.status) {
                    gl.DeleteShader(c.shader);
                    c = std::move(again);
                    diags.warning(stage.path, at, localConstAccepted(what));
                } else {
                    // Outside any function it stays an error in every
                    // version (the extension leaves the same error on the
                    // same line). NVIDIA's driver accepted it anyway, and
                    // the author saw a picture: the 'const' is dropped on
                    // each such line (blanked, so columns stay), which makes
                    // it a global set when the shader starts, as NVIDIA did.
                    gl.DeleteShader(again.shader);
                    std::vector<Diagnostic> globals;
                    for (const auto& d : again.said.all())
                        if (isConstInitializerError(d)) globals.push_back(d);
                    std::string relaxed = text;
                    for (const auto& d : globals) relaxed = withoutConstBefore(relaxed, d.loc.line, d.loc.col);
                    Compiled third = globals.empty() ? Compiled{}
                                                     : compileStage(gl, stage, relaxed, prelude + kLocalConstExtension,
                                                                    scriptFile);
                    if (third.status) {
                        gl.DeleteShader(c.shader);
                        // A local one beside them was accepted by the extension: said as above.
                        for (const auto& d : c.said.all())
                            if (isConstInitializerError(d) &&
                                std::none_of(globals.begin(), globals.end(),
                                             [&](const Diagnostic& g) { return g.loc.line == d.loc.line; })) {
                                diags.warning(stage.path, d.loc, localConstAccepted(d.message));
                                break;
                            }
                        c = std::move(third);
                        for (const auto& d : globals)
                            diags.warning(stage.path, d.loc, globalConstDropped(constName(d.message)));
                    } else {
                        if (!globals.empty()) gl.DeleteShader(third.shader);
                        bool stays = false;
                        for (const auto& d : globals) stays = stays || (d.loc.line == at.line && d.message == what);
                        if (stays)
                            hint = Diagnostic{Severity::Note, stage.path, at,
                                              fmt::format("{} is a const outside any function: its initialiser must "
                                                          "be a constant expression in every GLSL version (4.20 "
                                                          "relaxed it only inside functions); remove 'const' and it "
                                                          "is set when the shader starts",
                                                          constName(what)),
                                              false};
                    }
                }
            }
        }
        if (int v = 0, line = c.status && !madeCompatibility ? profilelessVersionLine(text, v) : 0; line > 0)
            coreStages.push_back({shaders.size(), &stage, &text, prelude, line, v});
        anyCompatibility = anyCompatibility || madeCompatibility || glslVersionOf(text).profile == "compatibility";
        unsigned sh = c.shader;
        GLint status = c.status;
        const std::string& log = c.log;
        for (Diagnostic d : c.said.all()) diags.add(judgeUninitialized(std::move(d), text));
        if (hint) diags.add(*hint);
        if (!status) {
            if (log.empty()) diags.error(stage.path, {}, "the shader did not compile, and the driver said nothing");
            ok = false;
        }
        shaders.push_back(sh);
    }
    unsigned program = 0;
    if (ok && !shaders.empty()) {
        std::string log;
        program = linkShaders(gl, shaders, log);
        // A core stage among compatibility ones: their gl_PerVertex blocks
        // differ and Mesa refuses the link; NVIDIA's driver links it, as if
        // the core stage said `compatibility`. Those stages are compiled
        // again with the word, and the program linked again.
        if (!program && anyCompatibility && !coreStages.empty()) {
            std::vector<unsigned> again = shaders;
            bool compiled = true;
            for (const CoreStage& core : coreStages) {
                Compiled c = compileStage(gl, *core.stage, withCompatibilityProfile(*core.text, core.line),
                                          core.prelude, scriptFile);
                again[core.shader] = c.shader;
                compiled = compiled && c.status;
            }
            std::string secondLog;
            if (compiled) program = linkShaders(gl, again, secondLog);
            for (const CoreStage& core : coreStages) {
                gl.DeleteShader(program ? shaders[core.shader] : again[core.shader]);
                if (program) shaders[core.shader] = again[core.shader];
            }
            if (program)
                for (const CoreStage& core : coreStages)
                    diags.warning(core.stage->path, {core.line, 1},
                                  fmt::format("'#version {0}' (no profile: core) has another gl_PerVertex than "
                                              "the compatibility stages: linked as '#version {0} compatibility', as "
                                              "NVIDIA does; add 'compatibility' to run everywhere",
                                              core.version));
        }
        if (!program) diags.error(scriptFile, decl.loc, fmt::format("Program {} does not link: {}", decl.name, log));
        if (program) setInitialValues(gl, program, initialValues);
    }
    for (unsigned sh : shaders) gl.DeleteShader(sh);
    return program;
}

unsigned buildPlainProgram(const GlApi& gl, const std::string& vertex, const std::string& fragment) {
    unsigned program = gl.CreateProgram();
    bool ok = true;
    for (auto [stage, text] : {std::pair{GLenum(GL_VERTEX_SHADER), &vertex}, {GLenum(GL_FRAGMENT_SHADER), &fragment}}) {
        unsigned sh = gl.CreateShader(stage);
        const char* src = text->c_str();
        gl.ShaderSource(sh, 1, &src, nullptr);
        gl.CompileShader(sh);
        GLint compiled = 0;
        gl.GetShaderiv(sh, GL_COMPILE_STATUS, &compiled);
        ok = ok && compiled;
        gl.AttachShader(program, sh);
        gl.DeleteShader(sh);  // freed with the program
    }
    GLint linked = 0;
    if (ok) {
        gl.LinkProgram(program);
        gl.GetProgramiv(program, GL_LINK_STATUS, &linked);
    }
    if (!linked) {
        gl.DeleteProgram(program);
        return 0;
    }
    return program;
}

}  // namespace glimmer
