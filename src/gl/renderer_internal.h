// What the renderer's files share and nobody else sees: its GL objects and
// small GL helpers. Private to src/gl.
#pragma once
#include "gl/renderer.h"

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
#include "image/cubemap.h"
#include "image/noise.h"
#include "gl/builtin_feed.h"

namespace glimmer {

struct Renderer::Target {
    std::vector<int> textures;  // empty: the screen
    unsigned fbo = 0;
    unsigned depth = 0;         // renderbuffer, only when some pass draws depth into it
    int width = 0, height = 0;
};

// The watch on the GPU (gl/watch_gpu.cpp): the two float targets the
// watched pass draws into, the levels of the reduction that counts them,
// and the three programs that reduce and colour.
struct Renderer::WatchGpu {
    unsigned fbo = 0, depth = 0;
    unsigned textures[2] = {0, 0};  // the value, what is known of it (WatchCapture)
    int width = 0, height = 0;
    bool drawn = false;  // renderWatch drew into them since they were made
    struct Level {       // lo, hi (RGBA32F), counts, more counts (RGBA32UI) per block
        unsigned fbo = 0;
        unsigned textures[4] = {0, 0, 0, 0};
        int width = 0, height = 0;
    };
    std::vector<Level> levels;
    unsigned leaf = 0, merge = 0, colour = 0;  // made on first use, kept for the renderer's life
    bool built = false;                        // tried to build them
};

struct Renderer::Program {
    unsigned id = 0;
    std::vector<ActiveUniform> uniforms;
    std::vector<const UniformSetting*> settings;  // per uniform: how the script wrote it (null: not set)
    int timerLocation = -1;
    BuiltinFeed feed;  // fed the compatibility built-ins by name (gl/builtin_feed.h), not by fixed-function state
    bool usesTangent = false;
    bool noise2 = false, noise3 = false;  // declares the built-in Noise2 / Noise3
    bool tessellated = false;             // has a tessellation evaluation shader: draws patches only
    GLint geometryInput = 0;              // the geometry shader's input primitive; 0: none
    // Its draws land where the fixed-function transform puts them and write
    // every pixel they cover (no discard, no geometry or tessellation stage):
    // a Clear such a draw covers can be skipped (plan/hidden_clears.h).
    bool paintsAllItCovers = false;
    std::string name;
    std::set<std::string> initialized;  // uniforms its shaders give a value of their own (`uniform float a = 1.;`)
    std::vector<std::optional<std::string>> texts;  // each stage's text as compiled: a watch rewrites one of them
};

struct Renderer::MeshBuffers {
    unsigned vbo = 0, ibo = 0;
    GLsizei count = 0;
    GLenum primitive = GL_TRIANGLES;
};

namespace renderer_detail {


// Reverses the order of `height` rows of `rowLength` values: images are
// top row first, OpenGL's rows start at the bottom.
template <typename T>
inline std::vector<T> flipRows(const std::vector<T>& rows, int height) {
    std::vector<T> out(rows.size());
    size_t row = height > 0 ? rows.size() / size_t(height) : 0;
    for (int y = 0; y < height; ++y)
        std::copy_n(rows.begin() + std::ptrdiff_t(size_t(y) * row), row,
                    out.begin() + std::ptrdiff_t(size_t(height - 1 - y) * row));
    return out;
}

inline Image flipRows(Image img) {
    img.u8 = flipRows(img.u8, img.height);
    return img;
}

// Every texture is sampled linearly; it wraps as the script's Wrap said
// (OpenGL's default GL_REPEAT without one). Cube maps always clamp, so a
// face's edge does not blend in its opposite edge.
inline GLint glWrap(TextureDecl::Wrap w) {
    switch (w) {
    case TextureDecl::Wrap::Repeat: return GL_REPEAT;
    case TextureDecl::Wrap::Clamp: return GL_CLAMP_TO_EDGE;
    case TextureDecl::Wrap::Mirror: return GL_MIRRORED_REPEAT;
    }
    return GL_REPEAT;
}

inline void textureParameters(const GlApi& gl, GLenum target = GL_TEXTURE_2D,
                              TextureDecl::Wrap how = TextureDecl::Wrap::Repeat) {
    GLint wrap = target == GL_TEXTURE_CUBE_MAP ? GL_CLAMP_TO_EDGE : glWrap(how);
    gl.TexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl.TexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.TexParameteri(target, GL_TEXTURE_WRAP_S, wrap);
    gl.TexParameteri(target, GL_TEXTURE_WRAP_T, wrap);
    if (target != GL_TEXTURE_2D) gl.TexParameteri(target, GL_TEXTURE_WRAP_R, wrap);
}

inline GLenum textureTarget(TextureDecl::Kind k) {
    switch (k) {
    case TextureDecl::Kind::Tex2D: return GL_TEXTURE_2D;
    case TextureDecl::Kind::Tex3D: return GL_TEXTURE_3D;
    case TextureDecl::Kind::Cube: return GL_TEXTURE_CUBE_MAP;
    }
    return GL_TEXTURE_2D;
}

constexpr GLenum kTargets[] = {GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP};

inline void uploadVolume(const GlApi& gl, const Volume& v) {
    if (v.type == Image::Type::U8)
        gl.TexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, v.width, v.height, v.depth, 0, GL_RGBA, GL_UNSIGNED_BYTE, v.u8.data());
    else
        gl.TexImage3D(GL_TEXTURE_3D, 0, GL_RGBA32F, v.width, v.height, v.depth, 0, GL_RGBA, GL_FLOAT, v.f32.data());
}

inline GLenum internalFormat(TextureDecl::Format f) {
    switch (f) {
    case TextureDecl::Format::RGBA8: return GL_RGBA8;
    case TextureDecl::Format::RGBA16F: return GL_RGBA16F;
    case TextureDecl::Format::RGBA32F: return GL_RGBA32F;
    case TextureDecl::Format::R11F_G11F_B10F: return GL_R11F_G11F_B10F;
    }
    return GL_RGBA8;
}

// A format and type glTexImage2D accepts with that internal format on
// OpenGL ES 3.0 as well as on the desktop (ES takes only the matching
// pairs: RGBA8 wants bytes, R11F_G11F_B10F wants RGB).
struct PixelTransfer {
    GLenum format, type;
};
inline PixelTransfer transferFor(TextureDecl::Format f) {
    switch (f) {
    case TextureDecl::Format::RGBA8: return {GL_RGBA, GL_UNSIGNED_BYTE};
    case TextureDecl::Format::RGBA16F: return {GL_RGBA, GL_FLOAT};
    case TextureDecl::Format::RGBA32F: return {GL_RGBA, GL_FLOAT};
    case TextureDecl::Format::R11F_G11F_B10F: return {GL_RGB, GL_FLOAT};
    }
    return {GL_RGBA, GL_UNSIGNED_BYTE};
}

inline GLenum glPrimitive(Mesh::Primitive p) {
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

inline const char* primitiveName(GLenum p) {
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

// The RGBA8 picture of framebuffer `fbo`'s first attachment, row 0 at the top.
inline Image readPicture(const GlApi& gl, unsigned fbo, int width, int height) {
    Image img = Image::rgba8(width, height);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, img.u8.data());
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    return flipRows(std::move(img));
}

// Reads a 2-D texture whole through a framebuffer of its own with
// glReadPixels, rows bottom first as glGetTexImage gives them: OpenGL ES has
// no glGetTexImage, and a watch's targets are read this way on both.
inline void readThroughFramebuffer(const GlApi& gl, unsigned texture, int width, int height, GLenum type, void* out) {
    unsigned fbo = 0;
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl.ReadPixels(0, 0, width, height, GL_RGBA, type, out);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.DeleteFramebuffers(1, &fbo);
}

}  // namespace renderer_detail
}  // namespace glimmer
