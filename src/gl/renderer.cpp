#include "gl/renderer.h"
#include "gl/clear_texture.h"

#include <array>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "geometry/mesh.h"
#include "gl/shader_build.h"
#include "image/cubemap.h"
#include "image/noise.h"

namespace glimmer {

struct Renderer::Target {
    std::vector<int> textures;  // empty: the screen
    unsigned fbo = 0;
    unsigned depth = 0;         // renderbuffer, only when some pass draws depth into it
    int width = 0, height = 0;
};

struct Renderer::Program {
    unsigned id = 0;
    std::vector<ActiveUniform> uniforms;
    std::vector<const UniformSetting*> settings;  // per uniform: how the script wrote it (null: not set)
    int timerLocation = -1;
    bool usesTangent = false;
    bool noise2 = false, noise3 = false;  // declares the built-in Noise2 / Noise3
    bool tessellated = false;             // has a tessellation evaluation shader: draws patches only
    GLint geometryInput = 0;              // the geometry shader's input primitive; 0: none
    std::string name;
};

struct Renderer::MeshBuffers {
    unsigned vbo = 0, ibo = 0;
    GLsizei count = 0;
    GLenum primitive = GL_TRIANGLES;
};

namespace {

// Reverses the order of `height` rows of `rowLength` values: images are
// top row first, OpenGL's rows start at the bottom.
template <typename T>
std::vector<T> flipRows(const std::vector<T>& rows, int height) {
    std::vector<T> out(rows.size());
    size_t row = height > 0 ? rows.size() / size_t(height) : 0;
    for (int y = 0; y < height; ++y)
        std::copy_n(rows.begin() + std::ptrdiff_t(size_t(y) * row), row,
                    out.begin() + std::ptrdiff_t(size_t(height - 1 - y) * row));
    return out;
}

Image flipRows(Image img) {
    img.u8 = flipRows(img.u8, img.height);
    return img;
}

// Every texture is sampled the same way: linear, and OpenGL's default wrap
// (cube maps clamp, so a face's edge does not blend in its opposite edge).
void textureParameters(const GlApi& gl, GLenum target = GL_TEXTURE_2D) {
    GLint wrap = target == GL_TEXTURE_CUBE_MAP ? GL_CLAMP_TO_EDGE : GL_REPEAT;
    gl.TexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl.TexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.TexParameteri(target, GL_TEXTURE_WRAP_S, wrap);
    gl.TexParameteri(target, GL_TEXTURE_WRAP_T, wrap);
    if (target != GL_TEXTURE_2D) gl.TexParameteri(target, GL_TEXTURE_WRAP_R, wrap);
}

GLenum textureTarget(TextureDecl::Kind k) {
    switch (k) {
    case TextureDecl::Kind::Tex2D: return GL_TEXTURE_2D;
    case TextureDecl::Kind::Tex3D: return GL_TEXTURE_3D;
    case TextureDecl::Kind::Cube: return GL_TEXTURE_CUBE_MAP;
    }
    return GL_TEXTURE_2D;
}

constexpr GLenum kTargets[] = {GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP};

void uploadVolume(const GlApi& gl, const Volume& v) {
    if (v.type == Image::Type::U8)
        gl.TexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, v.width, v.height, v.depth, 0, GL_RGBA, GL_UNSIGNED_BYTE, v.u8.data());
    else
        gl.TexImage3D(GL_TEXTURE_3D, 0, GL_RGBA32F, v.width, v.height, v.depth, 0, GL_RGBA, GL_FLOAT, v.f32.data());
}

std::vector<double> meshPoints(const MeshDecl& m, std::vector<glm::vec3>& out) {
    out.clear();
    for (size_t i = 0; i + 2 < m.points.size(); i += 3)
        out.emplace_back(float(m.points[i]), float(m.points[i + 1]), float(m.points[i + 2]));
    return m.points;
}

GLenum internalFormat(TextureDecl::Format f) {
    switch (f) {
    case TextureDecl::Format::RGBA8: return GL_RGBA8;
    case TextureDecl::Format::RGBA16F: return GL_RGBA16F;
    case TextureDecl::Format::RGBA32F: return GL_RGBA32F;
    case TextureDecl::Format::R11F_G11F_B10F: return GL_R11F_G11F_B10F;
    }
    return GL_RGBA8;
}

bool makeMesh(const MeshDecl& m, Mesh& mesh, std::string& error) {
    const auto& p = m.params;
    auto i = [&](size_t k) { return int(std::lround(p[k])); };
    switch (m.shape) {
    case CommandKind::QuadXY: mesh = makeQuadXY(float(p[0]), float(p[1]), i(2), i(3)); return true;
    case CommandKind::QuadXZ: mesh = makeQuadXZ(float(p[0]), float(p[1]), i(2), i(3)); return true;
    case CommandKind::QuadYZ: mesh = makeQuadYZ(float(p[0]), float(p[1]), i(2), i(3)); return true;
    case CommandKind::Sphere: mesh = makeSphere(float(p[0]), std::max(i(1), 3), std::max(i(2), 2)); return true;
    case CommandKind::Torus: mesh = makeTorus(float(p[0]), float(p[1]), std::max(i(2), 3), std::max(i(3), 3)); return true;
    case CommandKind::Box: mesh = makeBox(float(p[0]), float(p[1]), float(p[2])); return true;
    case CommandKind::Obj: return loadObj(m.path, mesh, error);
    case CommandKind::Cylinder: mesh = makeCylinder(float(p[0]), float(p[1]), std::max(i(2), 3)); return true;
    case CommandKind::Cone: mesh = makeCone(float(p[0]), float(p[1]), std::max(i(2), 3)); return true;
    case CommandKind::DiskXY: mesh = makeDiskXY(float(p[0]), std::max(i(1), 3)); return true;
    case CommandKind::Teapot: mesh = makeTeapot(float(p[0]), std::max(i(1), 1)); return true;
    case CommandKind::QuadBox: mesh = makeQuadBox(float(p[0])); return true;
    case CommandKind::PointCloud: mesh = makePointCloud(i(0), float(p[1])); return true;
    case CommandKind::JitterCloud: mesh = makeJitterCloud(i(0), float(p[1]), float(p[2])); return true;
    case CommandKind::Triangles:
    case CommandKind::LinesAdjacency:
    case CommandKind::GlBegin: {
        std::vector<glm::vec3> pts;
        meshPoints(m, pts);
        if (m.shape == CommandKind::Triangles) mesh = makeTrianglesFrom(pts);
        else if (m.shape == CommandKind::LinesAdjacency) mesh = makeLinesAdjacency(pts);
        else mesh = makeImmediate(ImmediatePrimitive(i(0)), pts);
        return true;
    }
    case CommandKind::ObjAdj:
    case CommandKind::WireObj: {
        Mesh solid;
        if (!loadObj(m.path, solid, error)) return false;
        mesh = m.shape == CommandKind::ObjAdj ? makeObjAdjacency(solid) : makeWire(solid);
        return true;
    }
    case CommandKind::WireBox:
    case CommandKind::WireSphere:
    case CommandKind::WireTorus:
    case CommandKind::WireCylinder:
    case CommandKind::WireCone:
    case CommandKind::WireTeapot: {
        static const std::map<CommandKind, CommandKind> solidOf = {
            {CommandKind::WireBox, CommandKind::Box},           {CommandKind::WireSphere, CommandKind::Sphere},
            {CommandKind::WireTorus, CommandKind::Torus},       {CommandKind::WireCylinder, CommandKind::Cylinder},
            {CommandKind::WireCone, CommandKind::Cone},         {CommandKind::WireTeapot, CommandKind::Teapot}};
        MeshDecl solidDecl = m;
        solidDecl.shape = solidOf.at(m.shape);
        Mesh solid;
        if (!makeMesh(solidDecl, solid, error)) return false;
        mesh = makeWire(solid);
        return true;
    }
    default: error = "no mesh for this command"; return false;
    }
}

GLenum glPrimitive(Mesh::Primitive p) {
    switch (p) {
    case Mesh::Primitive::Triangles: return GL_TRIANGLES;
    case Mesh::Primitive::Lines: return GL_LINES;
    case Mesh::Primitive::Points: return GL_POINTS;
    case Mesh::Primitive::LinesAdjacency: return GL_LINES_ADJACENCY;
    case Mesh::Primitive::TrianglesAdjacency: return GL_TRIANGLES_ADJACENCY;
    case Mesh::Primitive::Patches: return GL_PATCHES;
    }
    return GL_TRIANGLES;
}

const char* primitiveName(GLenum p) {
    switch (p) {
    case GL_POINTS: return "points";
    case GL_LINES: return "lines";
    case GL_LINES_ADJACENCY: return "lines_adjacency";
    case GL_TRIANGLES: return "triangles";
    case GL_TRIANGLES_ADJACENCY: return "triangles_adjacency";
    case GL_PATCHES: return "patches";
    default: return "another primitive";
    }
}

}  // namespace

std::unique_ptr<Renderer> Renderer::create(const GetProcAddress& getProc, std::string& error) {
    std::unique_ptr<Renderer> r(new Renderer());
    if (!loadGlApi(r->gl_, getProc, error)) return nullptr;
    return r;
}

Renderer::~Renderer() {
    releaseAll();
    for (auto* cache : {&noise2_, &noise3_})
        for (auto& [res, id] : *cache) gl_.DeleteTextures(1, &id);
}

unsigned Renderer::noiseTexture(bool threeD, int res) {
    auto& cache = threeD ? noise3_ : noise2_;
    auto it = cache.find(res);
    if (it != cache.end()) return it->second;
    unsigned id = 0;
    gl_.GenTextures(1, &id);
    gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (threeD) {
        gl_.BindTexture(GL_TEXTURE_3D, id);
        textureParameters(gl_, GL_TEXTURE_3D);
        uploadVolume(gl_, makeNoise3D(res));
        gl_.BindTexture(GL_TEXTURE_3D, 0);
    } else {
        Image img = makeNoise2D(res);
        gl_.BindTexture(GL_TEXTURE_2D, id);
        textureParameters(gl_, GL_TEXTURE_2D);
        gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                       flipRows(img.u8, img.height).data());
        gl_.BindTexture(GL_TEXTURE_2D, 0);
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
        gpuTimers_ = software ? 0 : 1;
    }
    return gpuTimers_ == 1;
}

std::string Renderer::rendererName() const {
    const GLubyte* s = gl_.GetString(GL_RENDERER);
    return s ? reinterpret_cast<const char*>(s) : "unknown";
}

void Renderer::releaseAll() {
    for (auto& t : textures_)
        if (t.id) gl_.DeleteTextures(1, &t.id);
    textures_.clear();
    for (auto& m : meshes_) {
        if (!m) continue;
        gl_.DeleteBuffers(1, &m->vbo);
        gl_.DeleteBuffers(1, &m->ibo);
    }
    meshes_.clear();
    for (auto& p : programs_)
        if (p && p->id) gl_.DeleteProgram(p->id);
    programs_.clear();
    auto freeTarget = [&](Target* t) {
        if (!t) return;
        if (t->fbo) gl_.DeleteFramebuffers(1, &t->fbo);
        if (t->depth) gl_.DeleteRenderbuffers(1, &t->depth);
    };
    for (auto& t : targets_) freeTarget(t.get());
    targets_.clear();
    freeTarget(screen_.get());
    screen_.reset();
    if (screenTexture_) gl_.DeleteTextures(1, &screenTexture_);
    screenTexture_ = 0;
    plan_.reset();
}

bool Renderer::prepare(const Plan& plan, Diagnostics& diags, SourceTexts& sources, bool everything) {
    releaseAll();
    plan_ = std::make_unique<Plan>(plan);
    const std::string& file = plan.scriptFile;
    textures_.assign(plan.textures.size(), {});
    meshes_.resize(plan.meshes.size());
    programs_.resize(plan.programs.size());

    // What the passes that will run actually use.
    std::vector<bool> texUsed(plan.textures.size(), everything), meshUsed(plan.meshes.size(), everything),
        progUsed(plan.programs.size(), everything);
    for (const auto& pass : plan.passes) {
        if (!pass.needed && !everything) continue;
        for (int t : pass.targets) texUsed[t] = true;
        for (int t : pass.reads) texUsed[t] = true;
        for (const auto& s : pass.steps) {
            if (s.kind != Step::Kind::Draw) continue;
            meshUsed[s.draw.mesh] = true;
            if (s.draw.program >= 0) progUsed[s.draw.program] = true;
        }
    }

    int errorsBefore = diags.errorCount();
    for (size_t i = 0; i < plan.textures.size(); ++i) {
        if (!texUsed[i]) continue;
        const TextureDecl& t = plan.textures[i];
        const GLenum target = textureTarget(t.kind);
        const bool file3D = t.kind == TextureDecl::Kind::Tex3D && t.source == TextureDecl::Source::File;
        Image img;
        Volume vol;
        std::array<Image, 6> faces;
        std::string why;
        bool loaded = true;
        if (t.kind == TextureDecl::Kind::Cube) {
            std::array<std::string, 6> paths;
            for (size_t k = 0; k < 6; ++k) paths[k] = t.facePaths.at(k);
            loaded = loadCubeMap(paths, faces, why);
        } else if (file3D) {
            loaded = loadVolume(t.path, vol, why);
        } else if (t.source == TextureDecl::Source::File) {
            loaded = loadImage(t.path, img, why);
        }
        if (!loaded) {
            diags.error(file, t.loc, fmt::format("cannot load '{}': {}", t.shown, why));
            continue;
        }
        unsigned id = 0;
        gl_.GenTextures(1, &id);
        gl_.BindTexture(target, id);
        textureParameters(gl_, target);
        gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
        TextureObject obj{id, target, t.width, t.height};
        if (t.kind == TextureDecl::Kind::Cube) {
            // OpenGL's cube faces have t = 0 at the top as seen from inside
            // (see image/cubemap.h): the faces go up as they are, not flipped.
            for (size_t k = 0; k < 6; ++k) {
                const Image& f = faces[k];
                GLenum face = GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + k);
                if (f.type == Image::Type::U8)
                    gl_.TexImage2D(face, 0, GL_RGBA8, f.width, f.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, f.u8.data());
                else
                    gl_.TexImage2D(face, 0, GL_RGBA32F, f.width, f.height, 0, GL_RGBA, GL_FLOAT, f.f32.data());
            }
            obj.width = faces[0].width;
            obj.height = faces[0].height;
        } else if (t.kind == TextureDecl::Kind::Tex3D) {
            if (!file3D) {
                vol.width = t.width;
                vol.height = t.height;
                vol.depth = t.depth;
                vol.u8.assign(size_t(t.width) * size_t(t.height) * size_t(t.depth) * 4, 0);
            }
            uploadVolume(gl_, vol);
            obj.width = vol.width;
            obj.height = vol.height;
        } else if (t.source == TextureDecl::Source::File) {
            // Image rows run top-down; OpenGL's t = 0 is the bottom row.
            if (img.type == Image::Type::U8)
                gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                               flipRows(img.u8, img.height).data());
            else
                gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, img.width, img.height, 0, GL_RGBA, GL_FLOAT,
                               flipRows(img.f32, img.height).data());
            obj.floatData = img.type == Image::Type::F32;
            obj.width = img.width;
            obj.height = img.height;
        } else {
            // Start targets black rather than with whatever memory held, in
            // the format the script asked for; cleared on the GPU.
            gl_.TexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat(t.format)), t.width, t.height, 0, GL_RGBA, GL_FLOAT,
                           nullptr);
            clearTexture2D(gl_, id);
            gl_.BindTexture(target, id);
            if (t.mips) {
                gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
                gl_.GenerateMipmap(GL_TEXTURE_2D);
            }
            obj.format = t.format;
            obj.mips = t.mips;
            obj.floatData = isFloatFormat(t.format);
        }
        gl_.BindTexture(target, 0);
        textures_[i] = obj;
    }
    gl_.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

    for (size_t i = 0; i < plan.meshes.size(); ++i) {
        if (!meshUsed[i]) continue;
        Mesh mesh;
        std::string why;
        if (!makeMesh(plan.meshes[i], mesh, why)) {
            diags.error(file, plan.meshes[i].loc, why);
            continue;
        }
        auto b = std::make_unique<MeshBuffers>();
        gl_.GenBuffers(1, &b->vbo);
        gl_.BindBuffer(GL_ARRAY_BUFFER, b->vbo);
        gl_.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(MeshVertex)), mesh.vertices.data(),
                       GL_STATIC_DRAW);
        gl_.GenBuffers(1, &b->ibo);
        gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, b->ibo);
        gl_.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
                       mesh.indices.data(), GL_STATIC_DRAW);
        b->count = GLsizei(mesh.indices.size());
        b->primitive = glPrimitive(mesh.primitive);
        meshes_[i] = std::move(b);
    }
    gl_.BindBuffer(GL_ARRAY_BUFFER, 0);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);

    for (size_t i = 0; i < plan.programs.size(); ++i) {
        if (!progUsed[i]) continue;
        const ProgramDecl& decl = plan.programs[i];
        unsigned id = buildProgram(gl_, decl, file, diags, sources);
        if (!id) continue;
        auto p = std::make_unique<Program>();
        p->id = id;
        p->uniforms = activeUniforms(gl_, id);
        p->timerLocation = gl_.GetUniformLocation(id, "Timer");
        p->usesTangent = gl_.GetAttribLocation(id, "Tangent") == kTangentLocation;
        p->name = decl.name;
        for (const auto& st : decl.stages) {
            if (st.kind == ShaderStage::Kind::TessEvaluation) p->tessellated = true;
            if (st.kind == ShaderStage::Kind::Geometry) gl_.GetProgramiv(id, GL_GEOMETRY_INPUT_TYPE, &p->geometryInput);
        }
        checkUniformSettings(decl, p->uniforms, file, diags);
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
                gl_.UseProgram(id);
                gl_.Uniform1i(u.location, is2 ? 2 : 3);
                gl_.UseProgram(0);
            }
        }
        programs_[i] = std::move(p);
    }

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
        gl_.GenFramebuffers(1, &t->fbo);
        gl_.BindFramebuffer(GL_FRAMEBUFFER, t->fbo);
        for (size_t k = 0; k < pass.targets.size(); ++k)
            gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + k), GL_TEXTURE_2D,
                                     textures_[pass.targets[k]].id, 0);
        if (depth) t->depth = attachDepth(t->width, t->height);
        if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            diags.error(file, pass.loc, "the driver cannot render into these textures");
        targets_.push_back(std::move(t));
    }

    // The screen is an offscreen framebuffer of the output size, so every
    // backend reads back the same way.
    screen_ = std::make_unique<Target>();
    screen_->width = plan.width;
    screen_->height = plan.height;
    bool screenDepth = false;
    for (const auto& pass : plan.passes)
        if (pass.targets.empty()) screenDepth |= pass.needsDepth;
    gl_.GenTextures(1, &screenTexture_);
    gl_.BindTexture(GL_TEXTURE_2D, screenTexture_);
    textureParameters(gl_);
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, plan.width, plan.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl_.GenFramebuffers(1, &screen_->fbo);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, screen_->fbo);
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, screenTexture_, 0);
    if (screenDepth) screen_->depth = attachDepth(plan.width, plan.height);
    if (gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        diags.error(file, {}, fmt::format("the driver cannot make a {}x{} screen", plan.width, plan.height));
    gl_.ClearColor(0, 0, 0, 1);
    gl_.Clear(GL_COLOR_BUFFER_BIT);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_.BindTexture(GL_TEXTURE_2D, 0);

    if (GLenum e = gl_.GetError(); e != GL_NO_ERROR)
        diags.error(file, {}, fmt::format("OpenGL error 0x{:04x} while loading the script", e));
    return diags.errorCount() == errorsBefore;
}

unsigned Renderer::attachDepth(int width, int height) {
    unsigned rb = 0;
    gl_.GenRenderbuffers(1, &rb);
    gl_.BindRenderbuffer(GL_RENDERBUFFER, rb);
    gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb);
    return rb;
}

void Renderer::render(const UniformValues& values, double time, std::vector<PassTiming>* timings,
                      const std::vector<bool>* only) {
    if (!plan_ || !screen_) return;
    using Clock = std::chrono::steady_clock;
    std::vector<std::pair<int, unsigned>> pendingQueries;
    for (size_t pi = 0; pi < plan_->passes.size(); ++pi) {
        const Pass& pass = plan_->passes[pi];
        if (!pass.needed || (only && (pi >= only->size() || !(*only)[pi]))) continue;
        Target* target = screen_.get();
        for (auto& t : targets_)
            if (t->textures == pass.targets) target = t.get();
        // On a GPU each pass is timed by the GPU itself (GL_TIME_ELAPSED),
        // with no stall between passes; on a CPU renderer such queries mean
        // nothing, so the pass is fenced with glFinish and a wall clock.
        const bool gpuTimed = timings && gpuTimers();
        if (timings && !gpuTimed) gl_.Finish();
        auto start = Clock::now();
        unsigned query = 0;
        if (gpuTimed) {
            gl_.GenQueries(1, &query);
            gl_.BeginQuery(GL_TIME_ELAPSED, query);
        }

        gl_.BindFramebuffer(GL_FRAMEBUFFER, target->fbo);
        std::vector<GLenum> buffers;
        for (size_t k = 0; k < std::max<size_t>(1, pass.targets.size()); ++k) buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + k));
        gl_.DrawBuffers(GLsizei(buffers.size()), buffers.data());
        gl_.Viewport(0, 0, target->width, target->height);
        if (pass.needsDepth && target->depth) {
            gl_.Enable(GL_DEPTH_TEST);
            gl_.DepthFunc(GL_LESS);
            // Depth from an earlier frame would hide this one's drawing.
            gl_.Clear(GL_DEPTH_BUFFER_BIT);
        } else {
            gl_.Disable(GL_DEPTH_TEST);
        }
        for (const auto& s : pass.steps) {
            if (s.kind == Step::Kind::Clear) {
                gl_.ClearColor(s.clearColor.r, s.clearColor.g, s.clearColor.b, s.clearColor.a);
                gl_.Clear(GL_COLOR_BUFFER_BIT | (target->depth ? GL_DEPTH_BUFFER_BIT : 0));
            } else {
                drawStep(s.draw, values, time, pass.targets);
            }
        }
        // A target with a mip chain gets its levels remade from what the
        // pass drew, so textureLod and minification read this frame.
        for (int t : pass.targets) {
            if (!textures_[size_t(t)].mips) continue;
            gl_.BindTexture(GL_TEXTURE_2D, textures_[size_t(t)].id);
            gl_.GenerateMipmap(GL_TEXTURE_2D);
            gl_.BindTexture(GL_TEXTURE_2D, 0);
        }
        if (gpuTimed) {
            gl_.EndQuery(GL_TIME_ELAPSED);
            pendingQueries.push_back({int(pi), query});
        } else if (timings) {
            gl_.Finish();
            timings->push_back({int(pi), std::chrono::duration<double, std::milli>(Clock::now() - start).count()});
        }
    }
    for (auto [pass, query] : pendingQueries) {  // waits for the GPU once, after the frame
        GLuint64 ns = 0;
        gl_.GetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
        gl_.DeleteQueries(1, &query);
        timings->push_back({pass, double(ns) / 1e6});
    }
    gl_.UseProgram(0);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
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
    gl_.MatrixMode(GL_PROJECTION);
    gl_.LoadMatrixf(glm::value_ptr(projection));
    gl_.MatrixMode(GL_MODELVIEW);
    gl_.LoadMatrixf(glm::value_ptr(d.modelView));
    gl_.Color4f(d.color.r, d.color.g, d.color.b, d.color.a);
    gl_.LineWidth(d.lineWidth);
    gl_.PointSize(d.pointSize);
    gl_.ShadeModel(d.flatShading ? GL_FLAT : GL_SMOOTH);

    if (!drawProblem(prog, mesh).empty()) return;  // told in prepare

    // Each unit holds the texture the script bound there last, on its own
    // target; the unit's other targets are emptied, so a sampler of the
    // wrong kind reads nothing rather than an older texture.
    for (const auto& [unit, tex] : d.units) {
        gl_.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
        const TextureObject& t = textures_[tex];
        // A texture this pass draws into stays unbound: sampling it would be
        // a feedback loop, and a driver may copy or flush it just for being
        // bound (measured on an H100: a 1920x1080 pass took 4 to 8 times as
        // long with its own target bound on another unit).
        bool drawnInto = std::find(targets.begin(), targets.end(), tex) != targets.end();
        for (GLenum target : kTargets) gl_.BindTexture(target, target == t.target && !drawnInto ? t.id : 0);
    }
    // The built-in noise, on units 2 and 3, unless the script put a texture
    // of the same kind there.
    if (prog && (prog->noise2 || prog->noise3)) {
        for (bool three : {false, true}) {
            if (!(three ? prog->noise3 : prog->noise2)) continue;
            int unit = three ? 3 : 2;
            GLenum target = three ? GL_TEXTURE_3D : GL_TEXTURE_2D;
            auto it = d.units.find(unit);
            if (it != d.units.end() && textures_[it->second].target == target) continue;
            gl_.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
            gl_.BindTexture(target, noiseTexture(three, three ? plan_->noise3DRes : plan_->noise2DRes));
        }
    }
    gl_.ActiveTexture(GL_TEXTURE0);
    if (mesh->primitive == GL_PATCHES) gl_.PatchParameteri(GL_PATCH_VERTICES, d.patchVertices);

    gl_.UseProgram(prog ? prog->id : 0);
    if (prog) {
        for (size_t k = 0; k < prog->uniforms.size(); ++k) {
            const ActiveUniform& u = prog->uniforms[k];
            const auto& v = values.get(d.program, u.name);
            if (v.empty()) continue;
            const UniformSetting* setting = prog->settings[k];
            uploadUniform(gl_, u, setting ? convertUniform(setting->form, u, v) : v);
        }
        if (prog->timerLocation >= 0) {
            double t = std::fmod(time / plan_->timerPeriod, 1.0);
            gl_.Uniform1f(prog->timerLocation, float(t < 0 ? t + 1 : t));
        }
    }

    const GLsizei stride = sizeof(MeshVertex);
    gl_.BindBuffer(GL_ARRAY_BUFFER, mesh->vbo);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh->ibo);
    gl_.EnableClientState(GL_VERTEX_ARRAY);
    gl_.VertexPointer(3, GL_FLOAT, stride, reinterpret_cast<void*>(offsetof(MeshVertex, position)));
    gl_.EnableClientState(GL_NORMAL_ARRAY);
    gl_.NormalPointer(GL_FLOAT, stride, reinterpret_cast<void*>(offsetof(MeshVertex, normal)));
    gl_.ClientActiveTexture(GL_TEXTURE0);
    gl_.EnableClientState(GL_TEXTURE_COORD_ARRAY);
    gl_.TexCoordPointer(2, GL_FLOAT, stride, reinterpret_cast<void*>(offsetof(MeshVertex, st)));
    if (prog && prog->usesTangent) {
        gl_.EnableVertexAttribArray(kTangentLocation);
        gl_.VertexAttribPointer(kTangentLocation, 3, GL_FLOAT, GL_FALSE, stride,
                                reinterpret_cast<void*>(offsetof(MeshVertex, tangent)));
    }
    gl_.DrawElements(mesh->primitive, mesh->count, GL_UNSIGNED_INT, nullptr);
    if (prog && prog->usesTangent) gl_.DisableVertexAttribArray(kTangentLocation);
    gl_.DisableClientState(GL_TEXTURE_COORD_ARRAY);
    gl_.DisableClientState(GL_NORMAL_ARRAY);
    gl_.DisableClientState(GL_VERTEX_ARRAY);
    gl_.BindBuffer(GL_ARRAY_BUFFER, 0);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

void Renderer::present(int texture, int windowWidth, int windowHeight) const {
    const Target* source = screen_.get();
    if (texture >= 0) {
        source = nullptr;
        for (const auto& t : targets_)
            if (t->textures.front() == texture) source = t.get();
    }
    if (!source || windowWidth <= 0 || windowHeight <= 0) return;
    // Fit inside the window keeping the picture's shape.
    double scale = std::min(double(windowWidth) / source->width, double(windowHeight) / source->height);
    int w = int(source->width * scale), h = int(source->height * scale);
    int x = (windowWidth - w) / 2, y = (windowHeight - h) / 2;
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, source->fbo);
    gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    gl_.BlitFramebuffer(0, 0, source->width, source->height, x, y, x + w, y + h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

const std::vector<ActiveUniform>* Renderer::activeUniformsOf(int program) const {
    if (program < 0 || size_t(program) >= programs_.size() || !programs_[size_t(program)]) return nullptr;
    return &programs_[size_t(program)]->uniforms;
}

bool Renderer::usesTimer(int program) const {
    return program >= 0 && size_t(program) < programs_.size() && programs_[size_t(program)] &&
           programs_[size_t(program)]->timerLocation >= 0;
}

Image Renderer::readScreen() const {
    if (!screen_) return {};
    Image img = Image::rgba8(screen_->width, screen_->height);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, screen_->fbo);
    gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.ReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.u8.data());
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    return flipRows(std::move(img));
}

Image Renderer::readTextureFloat(int texture) const {
    if (texture < 0 || size_t(texture) >= textures_.size() || !textures_[size_t(texture)].id) return {};
    const TextureObject& t = textures_[size_t(texture)];
    if (t.target != GL_TEXTURE_2D) return {};
    Image img = Image::rgbaF32(t.width, t.height);
    gl_.BindTexture(GL_TEXTURE_2D, t.id);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl_.GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, img.f32.data());
    gl_.BindTexture(GL_TEXTURE_2D, 0);
    img.f32 = flipRows(img.f32, img.height);
    return img;
}

bool Renderer::isFloatTexture(int texture) const {
    return texture >= 0 && size_t(texture) < textures_.size() && textures_[size_t(texture)].floatData;
}

std::vector<int> Renderer::renderTargets() const {
    std::vector<int> out;
    if (!plan_) return out;
    for (const auto& p : plan_->passes)
        if (p.needed)
            for (int t : p.targets)
                if (std::find(out.begin(), out.end(), t) == out.end()) out.push_back(t);
    return out;
}

Image Renderer::readTexture(int texture) const {
    if (texture < 0 || size_t(texture) >= textures_.size() || !textures_[size_t(texture)].id) return {};
    const TextureObject& t = textures_[size_t(texture)];
    if (t.target != GL_TEXTURE_2D) return {};  // 3-D textures and cube maps are not pictures
    Image img = Image::rgba8(t.width, t.height);
    gl_.BindTexture(GL_TEXTURE_2D, t.id);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.u8.data());
    gl_.BindTexture(GL_TEXTURE_2D, 0);
    return flipRows(std::move(img));
}

}  // namespace glimmer
