#include "shader/web_translate.h"

#include <algorithm>
#include <exception>
#include <mutex>
#include <vector>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv_glsl.hpp>

#include "shader/compat_builtins.h"
#include "shader/compat_rewrite.h"
#include "shader/glsl_lexer.h"
#include "shader/glsl_scan.h"
#include "shader/glslang_log.h"

namespace glimmer {
namespace {

void initializeGlslangOnce() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

// Step 2: the rewritten desktop text -> SPIR-V for OpenGL, as
// `glslangValidator -G --aml --amb`. False (with diagnostics against the
// user's text) when it does not compile.
bool compileToSpirv(const CompatRewrite& rewritten, EShLanguage language, const WebTranslateInput& in,
                    std::vector<unsigned>& spirv, Diagnostics& diags) {
    glslang::TShader shader(language);
    const char* text = rewritten.text.c_str();
    shader.setStrings(&text, 1);  // unnamed: the log then says "0:LINE:", which glslang_log reads
    shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientOpenGL, 100);
    shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    shader.setAutoMapLocations(true);
    shader.setAutoMapBindings(true);
    // Relaxed: what glslang can accept with a warning it does not refuse
    // (classroom shaders lean on drivers' leniency).
    const auto messages = EShMessages(EShMsgSpvRules | EShMsgRelaxedErrors);
    GlslangLogContext cx{in.file, in.text, &rewritten.renames, ""};
    bool parsed = shader.parse(GetDefaultResources(), 110, false, messages);
    mapGlslangLog(shader.getInfoLog(), cx, diags);
    if (!parsed) return false;
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages) || !program.mapIO()) {
        cx.prefix = "linking for WebGL 2: ";
        if (!mapGlslangLog(program.getInfoLog(), cx, diags))
            diags.error(in.file, {}, "linking for WebGL 2 failed, and glslang said nothing");
        return false;
    }
    glslang::SpvOptions options;
    options.disableOptimizer = true;  // SPIRV-Cross reads it back: names matter, speed does not
    options.generateDebugInfo = false;
    spv::SpvBuildLogger logger;
    glslang::GlslangToSpv(*program.getIntermediate(language), spirv, &logger, &options);
    if (std::string messagesOut = logger.getAllMessages(); !messagesOut.empty() && spirv.empty()) {
        diags.error(in.file, {}, "SPIR-V generation failed: " + messagesOut);
        return false;
    }
    return !spirv.empty();
}

// The identifier that ends just before column `col` of line `line`, blanks
// between (the name a "global const initializers" error stands after): "k2".
// Read from the lexer's tokens, so a number ("2.5") or a comment before the
// column is no name; a word the column cuts is taken up to the column.
std::string nameBefore(std::string_view text, int line, int col) {
    std::string_view name;
    GlslLexer lexer(text);  // only up to the column
    for (GlslToken t{}; lexer.next(t);) {
        if (t.line > line || (t.line == line && t.col >= col)) break;
        if (t.line < line || t.kind == GlslTokenKind::Space) continue;
        name = t.kind == GlslTokenKind::Word ? tokenText(text, t).substr(0, size_t(col - t.col)) : std::string_view();
    }
    return std::string(name);
}

// NVIDIA's leniency, as the desktop has it (gl/shader_build.cpp): a const
// outside any function set from a non-constant expression (FogDragon's
// dragon.vert:29) loses its 'const' (blanked: columns stay) and is set when
// the shader starts. When `said` holds only such errors and the relaxed text
// compiles: true, `said` its warnings, `spirv` the program (issue 37).
bool dropGlobalConsts(const std::string& text, bool vertex, const WebTranslateInput& in, EShLanguage language,
                      Diagnostics& said, std::vector<unsigned>& spirv) {
    std::vector<SourceLoc> globals;
    for (const auto& d : said.all())
        if (d.severity == Severity::Error && d.message.find("global const initializers must be constant") != std::string::npos)
            globals.push_back(d.loc);
    if (globals.empty()) return false;
    std::string relaxed = text;
    for (const SourceLoc& at : globals) relaxed = withoutConstBefore(relaxed, at.line, at.col);
    CompatRewrite again = rewriteCompatBuiltins(relaxed, vertex ? CompatStage::Vertex : CompatStage::Fragment,
                                                definesOf(in.prelude));
    Diagnostics second;
    std::vector<unsigned> relaxedSpirv;
    if (!compileToSpirv(again, language, in, relaxedSpirv, second)) return false;
    said = std::move(second);
    for (const SourceLoc& at : globals)
        said.warning(in.file, at, globalConstDropped("`" + nameBefore(in.text, at.line, at.col) + "'"));
    spirv = std::move(relaxedSpirv);
    return true;
}

bool standInAttribute(const std::string& name) {
    for (const CompatBuiltin& b : kCompatBuiltins)
        if (b.attribute && b.name == name) return true;
    return false;
}

// Step 3: SPIR-V -> GLSL ES 3.00. Throws spirv_cross::CompilerError.
std::string writeEs300(std::vector<unsigned> spirv, WebStage stage) {
    spirv_cross::CompilerGLSL glsl(std::move(spirv));
    spirv_cross::CompilerGLSL::Options options = glsl.get_common_options();
    options.es = true;
    options.version = 300;
    options.vulkan_semantics = false;
    options.enable_420pack_extension = false;
    options.fragment.default_float_precision = spirv_cross::CompilerGLSL::Options::Highp;
    options.fragment.default_int_precision = spirv_cross::CompilerGLSL::Options::Highp;
    glsl.set_common_options(options);
    // ES 3.00 has no layout for uniforms, samplers or varyings: the linker
    // matches varyings by name and the renderer finds uniforms by name. The
    // attributes the renderer feeds keep the table's locations; the other
    // attributes are bound by the renderer before linking (Tangent) or by
    // the linker.
    spirv_cross::ShaderResources resources = glsl.get_shader_resources();
    for (const spirv_cross::Resource& r : resources.sampled_images) {
        glsl.unset_decoration(r.id, spv::DecorationBinding);
        glsl.unset_decoration(r.id, spv::DecorationDescriptorSet);
    }
    for (const spirv_cross::Resource& r : resources.stage_inputs)
        if (stage != WebStage::Vertex || !standInAttribute(glsl.get_name(r.id)))
            glsl.unset_decoration(r.id, spv::DecorationLocation);
    if (stage == WebStage::Vertex)
        for (const spirv_cross::Resource& r : resources.stage_outputs) glsl.unset_decoration(r.id, spv::DecorationLocation);
    for (spirv_cross::VariableID id : glsl.get_active_interface_variables())
        if (glsl.get_storage_class(id) == spv::StorageClassUniformConstant) {
            glsl.unset_decoration(id, spv::DecorationLocation);
            glsl.unset_decoration(id, spv::DecorationBinding);
            glsl.unset_decoration(id, spv::DecorationDescriptorSet);
        }
    return glsl.compile();
}

// Step 4: the result compiled as GLSL ES 3.00. Empty when valid, else the log.
std::string checkEs300(const std::string& text, EShLanguage language) {
    glslang::TShader shader(language);
    const char* p = text.c_str();
    shader.setStrings(&p, 1);
    if (shader.parse(GetDefaultResources(), 300, false, EShMsgDefault)) return {};
    return shader.getInfoLog();
}

}  // namespace

bool isGlslEs300(std::string_view text) {
    GlslVersion v = glslVersionOf(text);
    return v.number == 300 && v.profile == "es";
}

const char* webStageName(WebStage stage) {
    switch (stage) {
    case WebStage::Vertex: return "vertex shader";
    case WebStage::Fragment: return "fragment shader";
    case WebStage::Geometry: return "geometry shader";
    case WebStage::TessControl: return "tessellation control shader";
    case WebStage::TessEvaluation: return "tessellation evaluation shader";
    }
    return "shader";
}

std::string webRefusal(WebStage stage) {
    switch (stage) {
    case WebStage::Vertex:
    case WebStage::Fragment: return {};
    case WebStage::Geometry:
    case WebStage::TessControl:
    case WebStage::TessEvaluation: break;
    }
    return std::string("WebGL 2 has no ") + webStageName(stage) +
           "s (GLSL ES 3.00 has only vertex and fragment shaders)";
}

WebTranslation translateForWeb(const WebTranslateInput& in, Diagnostics& diags) {
    WebTranslation out;
    if (std::string why = webRefusal(in.stage); !why.empty()) {
        diags.error(in.file, {}, why);
        return out;
    }
    const bool vertex = in.stage == WebStage::Vertex;
    const EShLanguage language = vertex ? EShLangVertex : EShLangFragment;
    initializeGlslangOnce();
    if (isGlslEs300(in.text)) {  // written for WebGL 2 already: checked, passed on as it is
        std::string log = checkEs300(std::string(in.text), language);
        if (!log.empty()) {
            GlslangLogContext cx{in.file, in.text, nullptr, ""};
            if (!mapGlslangLog(log, cx, diags)) diags.error(in.file, {}, "not valid GLSL ES 3.00");
            return out;
        }
        out.text = std::string(in.text);
        out.ok = true;
        return out;
    }
    // Uniform initialisers (GLSL 1.20 on) have no ES 3.00 form: taken out,
    // same lines and columns, and handed to the renderer to set.
    UniformInitializers initializers = takeUniformInitializers(in.text);
    for (const auto& u : initializers.unreadable)
        diags.error(in.file, {u.line, u.col},
                    "WebGL 2 has no uniform initialisers, and the page carries only numbers and constructors of "
                    "them ('vec3(0., .5, 1.)'): set uniform " + u.name + " on its Program line instead");
    if (!initializers.unreadable.empty()) return out;
    out.initialValues = std::move(initializers.values);
    CompatRewrite rewritten = rewriteCompatBuiltins(initializers.text, vertex ? CompatStage::Vertex : CompatStage::Fragment,
                                                    definesOf(in.prelude));
    std::vector<unsigned> spirv;
    Diagnostics said;
    if (!compileToSpirv(rewritten, language, in, spirv, said) &&
        !dropGlobalConsts(initializers.text, vertex, in, language, said, spirv)) {
        for (const auto& d : said.all()) diags.add(d);
        return out;
    }
    for (const auto& d : said.all()) diags.add(d);
    try {
        out.text = writeEs300(std::move(spirv), in.stage);
    } catch (const std::exception& e) {
        // What SPIR-V holds but ES 3.00 cannot say (double precision,
        // gl_ClipDistance, ...): SPIRV-Cross names it.
        diags.error(in.file, {}, std::string("cannot be written as GLSL ES 3.00 for WebGL 2: ") + e.what());
        return out;
    }
    if (std::string log = checkEs300(out.text, language); !log.empty()) {
        // A translation glslang itself refuses as ES: a limit of the route,
        // not the user's mistake; say what, against the file.
        diags.error(in.file, {}, "the translation to GLSL ES 3.00 is not valid there: " + log);
        out.text.clear();
        return out;
    }
    out.ok = true;
    return out;
}

}  // namespace glimmer
