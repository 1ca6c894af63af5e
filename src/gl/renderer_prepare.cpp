// Renderer::prepare: uploading what the CPU load step read, building
// programs, making render targets and the screen.
#include "gl/renderer_internal.h"

#include "shader/uniform_initializers.h"
#include "shader/coverage_hints.h"
#include "gl/clear_texture.h"
#include "gl/unset_uniforms.h"

#include <tuple>

#include <fmt/format.h>

namespace glimmer {
using namespace renderer_detail;

bool Renderer::prepare(const Plan& plan, const Assets& assets, Diagnostics& diags, bool everything) {
    // An error an earlier call left (a front end's own GL, a read-back) is
    // not this script's: cleared, so the check at the end sees only its own.
    for (int i = 0; i < 16 && gl_->GetError() != GL_NO_ERROR; ++i) {
    }
    releaseAll();
    plan_ = std::make_unique<Plan>(plan);
    textures_.assign(plan.textures.size(), {});
    meshes_.resize(plan.meshes.size());
    programs_.resize(plan.programs.size());
    int errorsBefore = diags.errorCount();
    // Each step's wall clock, for glimmer-bench (no glFinish: a step's GPU
    // work may finish during the next).
    prepareSteps_.clear();
    auto mark = [this, at = std::chrono::steady_clock::now()](const char* step) mutable {
        const auto now = std::chrono::steady_clock::now();
        prepareSteps_.push_back({step, std::chrono::duration<double, std::milli>(now - at).count()});
        at = now;
    };
    uploadTextures(plan, assets);
    if (!gl_->es) gl_->Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // ES 3.0: always seamless, and no such enum
    mark("textures");
    uploadMeshes(plan, assets);
    mark("meshes");
    buildPrograms(*plan_, assets, diags);  // its settings point into the kept copy, which outlives the caller's
    mark("programs");
    warnSamplerKinds(plan, everything, diags);
    warnUndrawable(plan, everything, diags);
    mark("checks");
    makeTargets(plan, everything, diags);
    makeScreen(plan, diags);
    mark("targets");
    // A GL error with no error said yet; after one (a target the driver
    // cannot render into) it only follows from it.
    if (GLenum e = gl_->GetError(); e != GL_NO_ERROR && diags.errorCount() == errorsBefore)
        diags.error(plan.scriptFile, {}, fmt::format("OpenGL error 0x{:04x} while loading the script", e));
    return diags.errorCount() == errorsBefore;
}

// Images, cube maps, volumes and empty textures, each on its own target.
void Renderer::uploadTextures(const Plan& plan, const Assets& assets) {
    const std::vector<bool>& texUsed = assets.used.textures;
    for (size_t i = 0; i < plan.textures.size(); ++i) {
        if (!texUsed[i]) continue;
        const TextureDecl& t = plan.textures[i];
        const GLenum target = textureTarget(t.kind);
        const bool fromFile = t.source == TextureDecl::Source::File;
        const bool file3D = t.kind == TextureDecl::Kind::Tex3D && fromFile;
        const TextureFile& loaded = assets.textures[i];
        if (fromFile && !loaded.loaded) continue;  // the load step said why
        const Image& img = loaded.image;
        Volume blank;  // an empty Texture3D: zeros of the size written
        const Volume& vol = file3D ? loaded.volume : blank;
        const std::array<Image, 6>& faces = loaded.faces;
        unsigned id = 0;
        gl_->GenTextures(1, &id);
        gl_->BindTexture(target, id);
        textureParameters(*gl_, target, t.wrap);
        gl_->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
        TextureObject obj{id, target, t.width, t.height};
        if (t.kind == TextureDecl::Kind::Cube) {
            // OpenGL's cube faces have t = 0 at the top as seen from inside
            // (see image/cubemap.h): the faces go up as they are, not flipped.
            for (size_t k = 0; k < 6; ++k) {
                const Image& f = faces[k];
                GLenum face = GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + k);
                if (f.type == Image::Type::U8)
                    gl_->TexImage2D(face, 0, GL_RGBA8, f.width, f.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, f.u8.data());
                else
                    gl_->TexImage2D(face, 0, GL_RGBA32F, f.width, f.height, 0, GL_RGBA, GL_FLOAT, f.f32.data());
            }
            obj.width = faces[0].width;
            obj.height = faces[0].height;
        } else if (t.kind == TextureDecl::Kind::Tex3D) {
            if (!file3D) {
                blank.width = t.width;
                blank.height = t.height;
                blank.depth = t.depth;
                blank.u8.assign(size_t(t.width) * size_t(t.height) * size_t(t.depth) * 4, 0);
            }
            uploadVolume(*gl_, vol);
            obj.width = vol.width;
            obj.height = vol.height;
        } else if (t.source == TextureDecl::Source::File) {
            // Image rows run top-down; OpenGL's t = 0 is the bottom row.
            if (img.type == Image::Type::U8)
                gl_->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                               flipRows(img.u8, img.height).data());
            else
                gl_->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, img.width, img.height, 0, GL_RGBA, GL_FLOAT,
                               flipRows(img.f32, img.height).data());
            obj.floatData = img.type == Image::Type::F32;
            obj.width = img.width;
            obj.height = img.height;
        } else {
            // Start targets black rather than with whatever memory held, in
            // the format the script asked for; cleared on the GPU.
            PixelTransfer tr = transferFor(t.format);
            gl_->TexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat(t.format)), t.width, t.height, 0, tr.format, tr.type,
                            nullptr);
            clearTexture2D(*gl_, id);
            gl_->BindTexture(target, id);
            if (t.mips) {
                gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
                gl_->GenerateMipmap(GL_TEXTURE_2D);
            }
            obj.format = t.format;
            obj.mips = t.mips;
            obj.floatData = isFloatFormat(t.format);
        }
        gl_->BindTexture(target, 0);
        textures_[i] = obj;
    }
}

// Vertex and index buffers of every mesh the load step built.
void Renderer::uploadMeshes(const Plan& plan, const Assets& assets) {
    const std::vector<bool>& meshUsed = assets.used.meshes;
    for (size_t i = 0; i < plan.meshes.size(); ++i) {
        if (!meshUsed[i]) continue;
        if (!assets.meshes[i]) continue;  // the load step said why
        const Mesh& mesh = *assets.meshes[i];
        auto b = std::make_unique<MeshBuffers>();
        gl_->GenBuffers(1, &b->vbo);
        gl_->BindBuffer(GL_ARRAY_BUFFER, b->vbo);
        gl_->BufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(MeshVertex)), mesh.vertices.data(),
                       GL_STATIC_DRAW);
        gl_->GenBuffers(1, &b->ibo);
        gl_->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, b->ibo);
        gl_->BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
                       mesh.indices.data(), GL_STATIC_DRAW);
        b->count = GLsizei(mesh.indices.size());
        b->primitive = glPrimitive(mesh.primitive);
        meshes_[i] = std::move(b);
    }
    gl_->BindBuffer(GL_ARRAY_BUFFER, 0);
    gl_->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

// Compiles and links each used Program and learns what it declares.
void Renderer::buildPrograms(const Plan& plan, const Assets& assets, Diagnostics& diags) {
    const std::vector<bool>& progUsed = assets.used.programs;
    for (size_t i = 0; i < plan.programs.size(); ++i)
        if (progUsed[i]) programs_[i] = makeProgram(plan, plan.programs[i], assets.shaderTexts[i], diags);
}

std::unique_ptr<Renderer::Program> Renderer::makeProgram(const Plan& plan, const ProgramDecl& decl,
                                                         const std::vector<std::optional<std::string>>& texts,
                                                         Diagnostics& diags) {
    const std::string& file = plan.scriptFile;
    unsigned id = buildProgram(*gl_, decl, texts, file, diags);
    if (!id) return nullptr;
    auto p = std::make_unique<Program>();
    p->texts = texts;
    p->id = id;
    p->uniforms = activeUniforms(*gl_, id);
    p->timerLocation = gl_->GetUniformLocation(id, "Timer");
    p->feed = findBuiltinFeed(*gl_, id);
    p->usesTangent = gl_->GetAttribLocation(id, "Tangent") == kTangentLocation;
    p->name = decl.name;
    p->paintsAllItCovers = true;
    for (size_t k = 0; k < decl.stages.size(); ++k) {
        const ShaderStage& st = decl.stages[k];
        const std::string text = k < texts.size() && texts[k] ? *texts[k] : "";
        if (st.kind == ShaderStage::Kind::TessEvaluation) p->tessellated = true;
        if (st.kind == ShaderStage::Kind::Geometry) gl_->GetProgramiv(id, GL_GEOMETRY_INPUT_TYPE, &p->geometryInput);
        bool vouched = st.kind == ShaderStage::Kind::Vertex     ? keepsPlainTransform(text)
                       : st.kind == ShaderStage::Kind::Fragment ? !mayDiscard(text)
                                                                : false;
        p->paintsAllItCovers = p->paintsAllItCovers && vouched;
        UniformInitializers own = takeUniformInitializers(text);
        for (const auto* list : {&own.values, &own.unreadable})
            for (const auto& u : *list) p->initialized.insert(u.name);
    }
    checkUniformSettings(decl, p->uniforms, file, diags);
    warnUnsetUniforms(decl, p->uniforms, p->initialized, texts, file, diags);
    for (const auto& u : p->uniforms) {
        const UniformSetting* setting = nullptr;
        for (const auto& st : decl.uniforms)
            if (st.name == u.name) setting = &st;
        p->settings.push_back(setting);
        // glman's built-in noise: Noise2 on unit 2, Noise3 on unit 3,
        // made only for programs that declare them.
        bool is2 = u.name == "Noise2", is3 = u.name == "Noise3";
        if (!is2 && !is3) continue;
        GLenum want = is2 ? GL_SAMPLER_2D : GL_SAMPLER_3D;
        if (u.type != want) {
            diags.warning(file, decl.loc, fmt::format("Program {} declares {} as another type; the built-in noise "
                                                      "is a {}", decl.name, u.name, is2 ? "sampler2D" : "sampler3D"));
            continue;
        }
        (is2 ? p->noise2 : p->noise3) = true;
        noiseTexture(is3, is2 ? plan.noise2DRes : plan.noise3DRes);
        if (!setting) {
            gl_->UseProgram(id);
            gl_->Uniform1i(u.location, is2 ? 2 : 3);
            gl_->UseProgram(0);
        }
    }
    return p;
}

namespace {

const char* kindPhrase(TextureDecl::Kind k) {
    switch (k) {
    case TextureDecl::Kind::Tex2D: return "a 2-D texture";
    case TextureDecl::Kind::Tex3D: return "a 3-D texture";
    case TextureDecl::Kind::Cube: return "a cube map";
    }
    return "a texture";
}

// Samplers of two kinds (a sampler2D and a samplerCube) set to one unit in
// one Program: each target of the unit may hold its texture, but OpenGL
// refuses to draw with such a program (GL_INVALID_OPERATION), so nothing
// it draws appears.
void warnMixedSamplerUnits(const std::vector<ActiveUniform>& uniforms, const std::vector<const UniformSetting*>& settings,
                           const ProgramDecl& decl, const std::string& file, Diagnostics& diags) {
    std::map<int, std::pair<const ActiveUniform*, GLenum>> first;  // unit -> its first sampler
    std::set<int> told;
    for (size_t k = 0; k < uniforms.size() && k < settings.size(); ++k) {
        const ActiveUniform& u = uniforms[k];
        const UniformSetting* setting = settings[k];
        if (!samplerTypeName(u.type) || !setting || setting->values.empty()) continue;
        int unit = int(std::round(setting->values[0]));
        auto [it, added] = first.try_emplace(unit, &u, u.type);
        TextureDecl::Kind a{}, b{};
        if (added || !samplerTextureKind(u.type, a) || !samplerTextureKind(it->second.second, b) || a == b) continue;
        if (!told.insert(unit).second) continue;
        diags.warning(file, decl.loc,
                      fmt::format("Program {}: {} {} and {} {} both read unit {}; OpenGL draws nothing with samplers "
                                  "of two kinds on one unit: give them different units", decl.name,
                                  samplerTypeName(it->second.second), it->second.first->name, samplerTypeName(u.type),
                                  u.name, unit));
    }
}

}  // namespace

void Renderer::warnSamplerKinds(const Plan& plan, bool everything, Diagnostics& diags) {
    // Each sampler's unit as the script set it (unset: unit 0). The unit
    // holds, for each draw, the texture of each kind bound there last (one
    // per OpenGL target); a sampler of a kind the unit lacks reads black.
    std::set<std::tuple<int, std::string, int>> told;  // program, sampler, texture
    for (size_t i = 0; i < programs_.size() && i < plan.programs.size(); ++i)
        if (programs_[i])
            warnMixedSamplerUnits(programs_[i]->uniforms, programs_[i]->settings, plan.programs[i], plan.scriptFile, diags);
    for (const auto& pass : plan.passes) {
        if (!pass.needed && !everything) continue;
        for (const auto& st : pass.steps) {
            if (st.kind != Step::Kind::Draw || st.draw.program < 0) continue;
            const Program* prog = programs_[size_t(st.draw.program)].get();
            if (!prog) continue;
            const ProgramDecl& decl = plan.programs[size_t(st.draw.program)];
            for (size_t k = 0; k < prog->uniforms.size(); ++k) {
                const ActiveUniform& u = prog->uniforms[k];
                const char* typeName = samplerTypeName(u.type);
                if (!typeName) continue;
                const UniformSetting* setting = prog->settings[k];
                // The built-in noise reads its own texture, unless one of its kind is there.
                if (!setting && ((u.name == "Noise2" && prog->noise2) || (u.name == "Noise3" && prog->noise3))) continue;
                int unit = 0;
                if (setting) {
                    if (setting->values.empty()) continue;
                    double v = std::round(setting->values[0]);
                    if (v < 0 || v > 31) continue;
                    unit = int(v);
                }
                auto on = st.draw.units.find(unit);
                if (on == st.draw.units.end()) continue;
                const TextureDecl& tex = plan.textures[size_t(on->second)];
                TextureDecl::Kind reads{};
                if (samplerTextureKind(u.type, reads) && st.draw.textureOn(unit, reads, plan.textures) >= 0) continue;
                if (!told.insert({st.draw.program, u.name, on->second}).second) continue;
                diags.warning(plan.scriptFile, decl.loc,
                              fmt::format("Program {}: {} {} reads unit {}, which holds {} (line {}); it reads black",
                                          decl.name, typeName, u.name, unit, kindPhrase(tex.kind), tex.loc.line));
            }
        }
    }
}

void Renderer::warnUndrawable(const Plan& plan, bool everything, Diagnostics& diags) {
    const std::string& file = plan.scriptFile;
    // Shapes a program cannot draw (GL would refuse them with an error).
    std::set<std::pair<int, int>> told;
    for (const auto& pass : plan.passes) {
        if (!pass.needed && !everything) continue;
        for (const auto& st : pass.steps) {
            if (st.kind != Step::Kind::Draw || !meshes_[st.draw.mesh]) continue;
            const Program* prog = st.draw.program >= 0 ? programs_[st.draw.program].get() : nullptr;
            if (st.draw.program >= 0 && !prog) continue;
            std::string why = drawProblem(prog, meshes_[st.draw.mesh].get());
            if (!why.empty() && told.insert({st.draw.program, st.draw.mesh}).second)
                diags.warning(file, st.draw.loc, why + "; not drawn");
        }
    }
}

void Renderer::makeTargets(const Plan& plan, bool everything, Diagnostics& diags) {
    const std::string& file = plan.scriptFile;
    // Targets: one framebuffer per distinct set of textures written at once.
    for (const auto& pass : plan.passes) {
        if (pass.targets.empty() || (!pass.needed && !everything)) continue;
        bool known = false;
        for (const auto& t : targets_) known |= t->textures == pass.targets;
        if (known) continue;
        auto t = std::make_unique<Target>();
        t->textures = pass.targets;
        const TextureDecl& first = plan.textures[pass.targets.front()];
        t->width = first.width;
        t->height = first.height;
        bool depth = false;
        for (int tex : pass.targets) depth |= plan.textures[tex].needsDepth;
        gl_->GenFramebuffers(1, &t->fbo);
        gl_->BindFramebuffer(GL_FRAMEBUFFER, t->fbo);
        for (size_t k = 0; k < pass.targets.size(); ++k)
            gl_->FramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + k), GL_TEXTURE_2D,
                                     textures_[pass.targets[k]].id, 0);
        if (depth) t->depth = attachDepth(t->width, t->height);
        if (gl_->CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            // OpenGL ES 3.0 (WebGL 2) renders into float textures only with
            // EXT_color_buffer_float: the reason, at the texture's line.
            const TextureDecl* floating = nullptr;
            for (int tex : pass.targets)
                if (!floating && isFloatFormat(plan.textures[tex].format)) floating = &plan.textures[tex];
            if (gl_->es && floating)
                diags.error(file, floating->loc,
                            fmt::format("WebGL 2 renders into {} only with EXT_color_buffer_float, which this "
                                        "browser lacks; make it RGBA8, or use a desktop browser (all have it)",
                                        textureFormatName(floating->format)));
            else
                diags.error(file, pass.loc, "the driver cannot render into these textures");
        }
        targets_.push_back(std::move(t));
    }
}

void Renderer::makeScreen(const Plan& plan, Diagnostics& diags) {
    const std::string& file = plan.scriptFile;
    // The screen is an offscreen framebuffer of the output size, so every
    // backend reads back the same way.
    screen_ = std::make_unique<Target>();
    screen_->width = plan.width;
    screen_->height = plan.height;
    bool screenDepth = false;
    for (const auto& pass : plan.passes)
        if (pass.targets.empty()) screenDepth |= pass.needsDepth;
    gl_->GenTextures(1, &screenTexture_);
    gl_->BindTexture(GL_TEXTURE_2D, screenTexture_);
    textureParameters(*gl_);
    gl_->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, plan.width, plan.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl_->GenFramebuffers(1, &screen_->fbo);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, screen_->fbo);
    gl_->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, screenTexture_, 0);
    if (screenDepth) screen_->depth = attachDepth(plan.width, plan.height);
    if (gl_->CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        diags.error(file, {}, fmt::format("the driver cannot make a {}x{} screen", plan.width, plan.height));
    // Black, so a script that never clears the screen reads back defined
    // pixels; not when its first screen pass starts with a Clear of its own
    // (the seed bloom: at 512x512 on llvmpipe the clear was a sixth of the set-up).
    bool firstScreenPassClears = false;
    for (const auto& pass : plan.passes) {
        if (!pass.targets.empty() || !pass.needed) continue;
        firstScreenPassClears = !pass.steps.empty() && pass.steps.front().kind == Step::Kind::Clear;
        break;
    }
    if (!firstScreenPassClears) {
        gl_->ClearColor(0, 0, 0, 1);
        gl_->Clear(GL_COLOR_BUFFER_BIT);
    }
    gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_->BindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace glimmer
