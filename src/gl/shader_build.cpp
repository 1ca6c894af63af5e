#include "gl/shader_build.h"
#include "gl/builtin_feed.h"
#include "shader/uninitialized_globals.h"

#include <algorithm>
#include <cstring>
#include <sstream>

#include <fmt/format.h>


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
    std::istringstream in(source);
    std::string line;
    int n = 0, versionLine = 0;
    while (std::getline(in, line)) {
        ++n;
        auto p = line.find_first_not_of(" \t");
        if (p != std::string::npos && line.compare(p, 8, "#version") == 0) {
            versionLine = n;
            break;
        }
    }
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

}  // namespace

unsigned buildProgram(const GlApi& gl, const ProgramDecl& decl,
                      const std::vector<std::optional<std::string>>& stageTexts, const std::string& scriptFile,
                      Diagnostics& diags) {
    std::vector<unsigned> shaders;
    bool ok = true;
    for (size_t k = 0; k < decl.stages.size(); ++k) {
        const ShaderStage& stage = decl.stages[k];
        if (k >= stageTexts.size() || !stageTexts[k]) {  // unreadable: the load step said so
            ok = false;
            continue;
        }
        const std::string& text = *stageTexts[k];
        PreparedSource src = prepareSource(text, decl.gstap ? kGstapPrelude : "");
        unsigned sh = gl.CreateShader(stageEnum(stage.kind));
        const char* p = src.text.c_str();
        gl.ShaderSource(sh, 1, &p, nullptr);
        gl.CompileShader(sh);
        GLint status = 0;
        gl.GetShaderiv(sh, GL_COMPILE_STATUS, &status);
        std::string log = infoLog(gl, sh, false);
        if (!log.empty()) {
            Diagnostics said;
            mapCompilerLog(log, src, stage.path, scriptFile, stage.loc, status ? Severity::Warning : Severity::Error, said);
            for (Diagnostic d : said.all()) diags.add(judgeUninitialized(std::move(d), text));
        }
        if (!status) {
            if (log.empty()) diags.error(stage.path, {}, "the shader did not compile, and the driver said nothing");
            ok = false;
        }
        shaders.push_back(sh);
    }
    unsigned program = 0;
    if (ok && !shaders.empty()) {
        program = gl.CreateProgram();
        for (unsigned sh : shaders) gl.AttachShader(program, sh);
        gl.BindAttribLocation(program, kTangentLocation, "Tangent");
        bindBuiltinAttributes(gl, program);  // glimmer_Vertex and the others, where declared
        gl.LinkProgram(program);
        GLint status = 0;
        gl.GetProgramiv(program, GL_LINK_STATUS, &status);
        if (!status) {
            std::string log = infoLog(gl, program, true);
            diags.error(scriptFile, decl.loc, fmt::format("Program {} does not link: {}", decl.name, log));
            gl.DeleteProgram(program);
            program = 0;
        }
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
