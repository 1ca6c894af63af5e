#include "gl/renderer_internal.h"

#include <array>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "assets/assets.h"
#include "geometry/mesh.h"
#include "gl/gl_api.h"
#include "gl/shader_build.h"
#include "gl/uniform_upload.h"
#include "gl/unset_uniforms.h"
#include "image/cubemap.h"
#include "image/noise.h"

namespace glimmer {
using namespace renderer_detail;

Renderer::Renderer() : gl_(std::make_unique<GlApi>()) {}

std::unique_ptr<Renderer> Renderer::create(const GetProcAddress& getProc, std::string& error) {
    std::unique_ptr<Renderer> r(new Renderer());
    if (!loadGlApi(*r->gl_, getProc, error)) return nullptr;
    return r;
}

Renderer::~Renderer() {
    releaseAll();
    if (watchGpu_)
        for (unsigned p : {watchGpu_->leaf, watchGpu_->merge, watchGpu_->colour})
            if (p) gl_->DeleteProgram(p);
    for (auto* cache : {&noise2_, &noise3_})
        for (auto& [res, id] : *cache) gl_->DeleteTextures(1, &id);
}

unsigned Renderer::noiseTexture(bool threeD, int res) {
    auto& cache = threeD ? noise3_ : noise2_;
    auto it = cache.find(res);
    if (it != cache.end()) return it->second;
    unsigned id = 0;
    gl_->GenTextures(1, &id);
    gl_->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (threeD) {
        gl_->BindTexture(GL_TEXTURE_3D, id);
        textureParameters(*gl_, GL_TEXTURE_3D);
        uploadVolume(*gl_, makeNoise3D(res));
        gl_->BindTexture(GL_TEXTURE_3D, 0);
    } else {
        Image img = makeNoise2D(res);
        gl_->BindTexture(GL_TEXTURE_2D, id);
        textureParameters(*gl_, GL_TEXTURE_2D);
        gl_->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                       flipRows(img.u8, img.height).data());
        gl_->BindTexture(GL_TEXTURE_2D, 0);
    }
    cache[res] = id;
    return id;
}

std::string Renderer::drawProblem(const Program* prog, const MeshBuffers* mesh) const {
    bool patches = mesh->primitive == GL_PATCHES;
    if (patches && !(prog && prog->tessellated))
        return "patches (glBegin gl_patches) need a Program with a TessEvaluation shader";
    if (!patches && prog && prog->tessellated)
        return fmt::format("Program {} has tessellation shaders, which draw patches only (glBegin gl_patches)",
                           prog->name);
    if (prog && prog->geometryInput && !prog->tessellated) {
        GLenum want = GLenum(prog->geometryInput);
        if (want != mesh->primitive)
            return fmt::format("the geometry shader of Program {} takes {}, but this shape is {}", prog->name,
                               primitiveName(want), primitiveName(mesh->primitive));
    }
    return {};
}

bool Renderer::gpuTimers() const {
    if (gpuTimers_ < 0) {
        std::string name = rendererName();
        bool software = name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos ||
                        name.find("Software") != std::string::npos;
        // OpenGL ES has no GL_TIME_ELAPSED: a wall clock there too.
        gpuTimers_ = software || gl_->es ? 0 : 1;
    }
    return gpuTimers_ == 1;
}

std::string Renderer::rendererName() const {
    const GLubyte* s = gl_->GetString(GL_RENDERER);
    return s ? reinterpret_cast<const char*>(s) : "unknown";
}

void Renderer::releaseAll() {
    dropWatch();
    for (auto& t : textures_)
        if (t.id) gl_->DeleteTextures(1, &t.id);
    textures_.clear();
    for (auto& m : meshes_) {
        if (!m) continue;
        gl_->DeleteBuffers(1, &m->vbo);
        gl_->DeleteBuffers(1, &m->ibo);
    }
    meshes_.clear();
    for (auto& p : programs_)
        if (p && p->id) gl_->DeleteProgram(p->id);
    programs_.clear();
    auto freeTarget = [&](Target* t) {
        if (!t) return;
        if (t->fbo) gl_->DeleteFramebuffers(1, &t->fbo);
        if (t->depth) gl_->DeleteRenderbuffers(1, &t->depth);
    };
    for (auto& t : targets_) freeTarget(t.get());
    targets_.clear();
    freeTarget(screen_.get());
    screen_.reset();
    freeTarget(watchPicture_.get());
    watchPicture_.reset();
    if (watchPictureTexture_) gl_->DeleteTextures(1, &watchPictureTexture_);
    watchPictureTexture_ = 0;
    if (screenTexture_) gl_->DeleteTextures(1, &screenTexture_);
    screenTexture_ = 0;
    plan_.reset();
}

unsigned Renderer::attachDepth(int width, int height) {
    unsigned rb = 0;
    gl_->GenRenderbuffers(1, &rb);
    gl_->BindRenderbuffer(GL_RENDERBUFFER, rb);
    gl_->RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    gl_->FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb);
    return rb;
}

Renderer::Target* Renderer::passTarget(const Pass& pass) const {
    for (auto& t : targets_)
        if (t->textures == pass.targets) return t.get();
    return screen_.get();
}

void Renderer::bindForPass(const Target& target, size_t colourBuffers, bool depth) {
    gl_->BindFramebuffer(GL_FRAMEBUFFER, target.fbo);
    std::vector<GLenum> buffers;
    for (size_t k = 0; k < colourBuffers; ++k) buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + k));
    gl_->DrawBuffers(GLsizei(buffers.size()), buffers.data());
    gl_->Viewport(0, 0, target.width, target.height);
    if (depth) {
        gl_->Enable(GL_DEPTH_TEST);
        gl_->DepthFunc(GL_LESS);
    } else {
        gl_->Disable(GL_DEPTH_TEST);
    }
}

void Renderer::drawPass(const Pass& pass, Target* target, const UniformValues& values, double time) {
    const bool depth = pass.needsDepth && target->depth;
    bindForPass(*target, std::max<size_t>(1, pass.targets.size()), depth);
    if (depth) gl_->Clear(GL_DEPTH_BUFFER_BIT);  // depth from an earlier frame would hide this one's drawing
    for (const auto& s : pass.steps) {
        if (s.kind == Step::Kind::Clear) {
            if (clearIsHidden(pass, s, target)) continue;
            gl_->ClearColor(s.clearColor.r, s.clearColor.g, s.clearColor.b, s.clearColor.a);
            gl_->Clear(GL_COLOR_BUFFER_BIT | (target->depth ? GL_DEPTH_BUFFER_BIT : 0));
        } else {
            drawStep(s.draw, values, time, pass.targets);
        }
    }
}

bool Renderer::clearIsHidden(const Pass& pass, const Step& clear, const Target* target) const {
    if (clear.hiddenBy < 0 || size_t(clear.hiddenBy) >= pass.steps.size()) return false;
    // The viewer's turn and zoom move what is drawn to the screen: the plan's
    // coverage then no longer holds.
    if (target == screen_.get() && scene_ != glm::mat4(1.f)) return false;
    const Draw& d = pass.steps[size_t(clear.hiddenBy)].draw;
    const MeshBuffers* mesh = d.mesh >= 0 && size_t(d.mesh) < meshes_.size() ? meshes_[size_t(d.mesh)].get() : nullptr;
    if (!mesh) return false;
    if (d.program < 0) return true;  // fixed function: the plain transform, every pixel written
    const Program* prog = programs_[size_t(d.program)].get();
    return prog && prog->paintsAllItCovers && drawProblem(prog, mesh).empty();
}

void Renderer::finishPass(const Pass& pass) {
    // A target with a mip chain gets its levels remade from what the
    // pass drew, so textureLod and minification read this frame.
    for (int t : pass.targets) {
        if (!textures_[size_t(t)].mips) continue;
        gl_->BindTexture(GL_TEXTURE_2D, textures_[size_t(t)].id);
        gl_->GenerateMipmap(GL_TEXTURE_2D);
        gl_->BindTexture(GL_TEXTURE_2D, 0);
    }
}

void Renderer::render(const UniformValues& values, double time, std::vector<PassTiming>* timings,
                      const std::vector<bool>* only) {
    if (!plan_ || !screen_) return;
    using Clock = std::chrono::steady_clock;
    std::vector<std::pair<int, unsigned>> pendingQueries;
    gl_->Disable(GL_SCISSOR_TEST);  // a front end's UI may have left it on
    for (size_t pi = 0; pi < plan_->passes.size(); ++pi) {
        const Pass& pass = plan_->passes[pi];
        if (!pass.needed || (only && (pi >= only->size() || !(*only)[pi]))) continue;
        if (passListener_) passListener_(int(pi));
        // On a GPU each pass is timed by the GPU itself (GL_TIME_ELAPSED),
        // with no stall between passes; on a CPU renderer such queries mean
        // nothing, so the pass is fenced with glFinish and a wall clock.
        const bool gpuTimed = timings && gpuTimers();
        if (timings && !gpuTimed) gl_->Finish();
        auto start = Clock::now();
        unsigned query = 0;
        if (gpuTimed) {
            gl_->GenQueries(1, &query);
            gl_->BeginQuery(GL_TIME_ELAPSED, query);
        }
        drawPass(pass, passTarget(pass), values, time);
        finishPass(pass);
        if (passListener_) gl_->Finish();  // the pass is done before the next is announced
        if (gpuTimed) {
            gl_->EndQuery(GL_TIME_ELAPSED);
            pendingQueries.push_back({int(pi), query});
        } else if (timings) {
            gl_->Finish();
            timings->push_back({int(pi), std::chrono::duration<double, std::milli>(Clock::now() - start).count()});
        }
    }
    for (auto [pass, query] : pendingQueries) {  // waits for the GPU once, after the frame
        GLuint64 ns = 0;
        gl_->GetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
        gl_->DeleteQueries(1, &query);
        timings->push_back({pass, double(ns) / 1e6});
    }
    gl_->UseProgram(0);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::drawStep(const Draw& d, const UniformValues& values, double time, const std::vector<int>& targets) {
    const bool toScreen = targets.empty();
    const MeshBuffers* mesh = meshes_[d.mesh].get();
    if (!mesh) return;
    const Program* prog = d.program >= 0 ? programs_[d.program].get() : nullptr;
    if (d.program >= 0 && !prog) return;  // it failed to build; already reported

    // The legacy matrix stacks feed gl_ModelViewProjectionMatrix and friends.
    // P * V * scene * V^-1 * (V * M) = P * V * scene * M: the mouse turns
    // the world, the ModelView matrix stays the script's.
    glm::mat4 projection = d.projection;
    if (toScreen && scene_ != glm::mat4(1.f)) projection = d.projection * d.view * scene_ * glm::inverse(d.view);
    // A program that declares the built-ins' stand-ins (glimmer_Vertex, ...:
    // shader/compat_builtins.h) gets them as uniforms and attributes, the
    // way WebGL 2 draws; any other gets the fixed-function state.
    const bool fed = prog && prog->feed.any;
    const BuiltinValues builtins{projection, d.modelView, d.color, d.pointSize};
    if (!fed && !gl_->es) {
        gl_->MatrixMode(GL_PROJECTION);
        gl_->LoadMatrixf(glm::value_ptr(projection));
        gl_->MatrixMode(GL_MODELVIEW);
        gl_->LoadMatrixf(glm::value_ptr(d.modelView));
        gl_->Color4f(d.color.r, d.color.g, d.color.b, d.color.a);
        gl_->ShadeModel(d.flatShading ? GL_FLAT : GL_SMOOTH);
    }
    gl_->LineWidth(d.lineWidth);
    if (gl_->PointSize) gl_->PointSize(d.pointSize);  // ES: gl_PointSize from glimmer_PointSize

    if (!drawProblem(prog, mesh).empty()) return;  // told in prepare

    // Each unit holds, on each target (2-D, 3-D, cube map), the texture of
    // that kind the script bound there last, as OpenGL does; a target the
    // script never gave a texture is emptied, so a sampler of a kind the unit
    // lacks reads nothing rather than an older draw's texture.
    for (const auto& [unit, last] : d.units) {
        gl_->ActiveTexture(GLenum(GL_TEXTURE0 + unit));
        GLuint onTarget[std::size(kTargets)] = {};
        for (int tex : d.texturesOn(unit)) {
            const TextureObject& t = textures_[tex];
            // A texture this pass draws into stays unbound: sampling it would be
            // a feedback loop, and a driver may copy or flush it just for being
            // bound (measured on an H100: a 1920x1080 pass took 4 to 8 times as
            // long with its own target bound on another unit).
            if (std::find(targets.begin(), targets.end(), tex) != targets.end()) continue;
            for (size_t k = 0; k < std::size(kTargets); ++k)
                if (kTargets[k] == t.target) onTarget[k] = t.id;
        }
        for (size_t k = 0; k < std::size(kTargets); ++k) gl_->BindTexture(kTargets[k], onTarget[k]);
    }
    // The built-in noise, on units 2 and 3, unless the script put a texture
    // of the same kind there.
    if (prog && (prog->noise2 || prog->noise3)) {
        for (bool three : {false, true}) {
            if (!(three ? prog->noise3 : prog->noise2)) continue;
            int unit = three ? 3 : 2;
            GLenum target = three ? GL_TEXTURE_3D : GL_TEXTURE_2D;
            bool scripts = false;
            for (int tex : d.texturesOn(unit)) scripts = scripts || textures_[tex].target == target;
            if (scripts) continue;
            gl_->ActiveTexture(GLenum(GL_TEXTURE0 + unit));
            gl_->BindTexture(target, noiseTexture(three, three ? plan_->noise3DRes : plan_->noise2DRes));
        }
    }
    gl_->ActiveTexture(GL_TEXTURE0);
    if (mesh->primitive == GL_PATCHES) {
        if (!gl_->PatchParameteri) return;  // OpenGL ES 3.0: no tessellation (told in prepare)
        gl_->PatchParameteri(GL_PATCH_VERTICES, d.patchVertices);
    }

    gl_->UseProgram(prog ? prog->id : 0);
    if (prog) {
        for (size_t k = 0; k < prog->uniforms.size(); ++k) {
            const ActiveUniform& u = prog->uniforms[k];
            const auto& v = values.get(d.program, u.name);
            if (v.empty()) continue;
            const UniformSetting* setting = prog->settings[k];
            uploadUniform(*gl_, u, setting ? convertUniform(setting->form, u, v) : v);
        }
        if (fed) feedBuiltinUniforms(*gl_, prog->feed, builtins);
        if (prog->timerLocation >= 0) {
            double t = std::fmod(time / plan_->timerPeriod, 1.0);
            gl_->Uniform1f(prog->timerLocation, float(t < 0 ? t + 1 : t));
        }
    }

    const GLsizei stride = sizeof(MeshVertex);
    gl_->BindBuffer(GL_ARRAY_BUFFER, mesh->vbo);
    gl_->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh->ibo);
    if (fed) {
        enableBuiltinAttributes(*gl_, prog->feed, builtins);
    } else if (!gl_->es) {
        gl_->EnableClientState(GL_VERTEX_ARRAY);
        gl_->VertexPointer(3, GL_FLOAT, stride, reinterpret_cast<void*>(offsetof(MeshVertex, position)));
        gl_->EnableClientState(GL_NORMAL_ARRAY);
        gl_->NormalPointer(GL_FLOAT, stride, reinterpret_cast<void*>(offsetof(MeshVertex, normal)));
        gl_->ClientActiveTexture(GL_TEXTURE0);
        gl_->EnableClientState(GL_TEXTURE_COORD_ARRAY);
        gl_->TexCoordPointer(2, GL_FLOAT, stride, reinterpret_cast<void*>(offsetof(MeshVertex, st)));
    }
    if (prog && prog->usesTangent) {
        gl_->EnableVertexAttribArray(kTangentLocation);
        gl_->VertexAttribPointer(kTangentLocation, 3, GL_FLOAT, GL_FALSE, stride,
                                reinterpret_cast<void*>(offsetof(MeshVertex, tangent)));
    }
    gl_->DrawElements(mesh->primitive, mesh->count, GL_UNSIGNED_INT, nullptr);
    if (prog && prog->usesTangent) gl_->DisableVertexAttribArray(kTangentLocation);
    if (fed) {
        disableBuiltinAttributes(*gl_, prog->feed);
    } else if (!gl_->es) {
        gl_->DisableClientState(GL_TEXTURE_COORD_ARRAY);
        gl_->DisableClientState(GL_NORMAL_ARRAY);
        gl_->DisableClientState(GL_VERTEX_ARRAY);
    }
    gl_->BindBuffer(GL_ARRAY_BUFFER, 0);
    gl_->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

void Renderer::present(int texture, int windowWidth, int windowHeight) const {
    presentIn(texture, windowHeight, 0, 0, windowWidth, windowHeight);
}

void Renderer::presentIn(int texture, int windowHeight, int rx, int ry, int rw, int rh, float u0, float u1) const {
    const Target* source = texture == kWatchPicture ? watchPicture_.get() : screen_.get();
    if (texture >= 0) {
        source = nullptr;
        for (const auto& t : targets_)
            if (t->textures.front() == texture) source = t.get();
    }
    if (!source || rw <= 0 || rh <= 0 || !(u1 > u0)) return;
    // Fit inside the rectangle keeping the picture's shape.
    double scale = std::min(double(rw) / source->width, double(rh) / source->height);
    int w = int(source->width * scale), h = int(source->height * scale);
    int x = rx + (rw - w) / 2, y = (windowHeight - ry - rh) + (rh - h) / 2;
    int sx0 = int(std::lround(u0 * source->width)), sx1 = int(std::lround(u1 * source->width));
    int dx0 = x + int(std::lround(u0 * w)), dx1 = x + int(std::lround(u1 * w));
    gl_->BindFramebuffer(GL_READ_FRAMEBUFFER, source->fbo);
    gl_->ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl_->BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    gl_->BlitFramebuffer(sx0, 0, sx1, source->height, dx0, y, dx1, y + h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
}

unsigned Renderer::textureName(int texture) const {
    if (texture < 0) return screenTexture_;
    if (size_t(texture) >= textures_.size()) return 0;
    return textures_[size_t(texture)].id;
}

std::vector<UnsetUniform> Renderer::unsetUniforms(int program) const {
    if (program < 0 || size_t(program) >= programs_.size() || !programs_[size_t(program)] ||
        size_t(program) >= plan_->programs.size())
        return {};
    const Program& p = *programs_[size_t(program)];
    return glimmer::unsetUniforms(plan_->programs[size_t(program)], p.uniforms, p.initialized);
}

Renderer::UniformKind Renderer::uniformKind(int program, const std::string& name) const {
    if (program < 0 || size_t(program) >= programs_.size() || !programs_[size_t(program)]) return UniformKind::Unknown;
    for (const auto& u : programs_[size_t(program)]->uniforms) {
        if (u.name != name) continue;
        if (isSamplerType(u.type)) return UniformKind::Sampler;
        switch (u.type) {
        case GL_FLOAT: return UniformKind::Float;
        case GL_INT: return UniformKind::Int;
        case GL_BOOL: return UniformKind::Bool;
        default: return UniformKind::Other;
        }
    }
    return UniformKind::Unknown;
}

void Renderer::finish(int texture) const {
#ifdef __EMSCRIPTEN__
    GLint draw = 0, read = 0;
    gl_->GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    gl_->GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
    const bool target = texture >= 0 && size_t(texture) < textures_.size() && textures_[size_t(texture)].id &&
                        textures_[size_t(texture)].target == GL_TEXTURE_2D;
    unsigned fbo = 0;
    if (target) {
        gl_->GenFramebuffers(1, &fbo);
        gl_->BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
        gl_->FramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                  textures_[size_t(texture)].id, 0);
    } else {
        gl_->BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    }
    if (target && textures_[size_t(texture)].floatData) {  // OpenGL ES reads a float target only as floats
        float pixel[4];
        gl_->ReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, pixel);
    } else {
        unsigned char pixel[4];
        gl_->ReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    }
    gl_->BindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read));
    gl_->BindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(draw));
    if (fbo) gl_->DeleteFramebuffers(1, &fbo);
#else
    (void)texture;
    gl_->Finish();
#endif
}

bool Renderer::usesTimer(int program) const {
    return program >= 0 && size_t(program) < programs_.size() && programs_[size_t(program)] &&
           programs_[size_t(program)]->timerLocation >= 0;
}

}  // namespace glimmer
