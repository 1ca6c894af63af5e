// A watch counted and coloured where it was drawn (issue 36): reading two
// float targets back and walking them on the CPU cost 86x a frame at 1920
// on an H200 and 288x at 3840, so the GPU reduces them instead and only the
// counts come back (a few hundred bytes), and it colours the picture into
// the texture the window shows. The floats are read back only when asked
// (a float file, the probed pixel, a saved picture).
//
// The numbers are pipeline/watch_picture.h's, which computes them on the CPU
// from the read-back floats; tests/render/watch_gpu_test.cpp holds these to
// those, count for count and byte for byte. NaN and Inf are told by their
// bits, not isnan/isinf, which a driver's fast maths may fold away.
#include "gl/renderer_internal.h"

namespace glimmer {
using namespace renderer_detail;
namespace {

// Each fragment of a reduction level sums a block this many texels square
// of the level below: 3840 x 3840 is counted in four levels (960, 240, 60,
// 15). Small blocks keep the GPU full: with 16 x 16 a fragment walked 256
// texels one after another and the first level took 6 ms at 1920 on an H200.
constexpr int kBlock = 4;

const char* const kVertex = R"(
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(p * 2. - 1., 0., 1.);
}
)";

// What marks a pixel's value (as watchPicture marks it): a component that
// is NaN, Inf, below or above the range; only its first n components count.
const char* const kMarks = R"(
void marksOf(vec4 v, int n, vec2 range, out bool nan, out bool inf, out bool below, out bool above) {
    nan = false; inf = false; below = false; above = false;
    for (int c = 0; c < 4; ++c) {
        if (c >= n) break;
        uint bits = floatBitsToUint(v[c]);
        if ((bits & 0x7f800000u) == 0x7f800000u) {
            if ((bits & 0x007fffffu) != 0u) nan = true; else inf = true;
            continue;
        }
        below = below || v[c] < range.x;
        above = above || v[c] > range.y;
    }
}
)";

// Both reduction programs: per block of the level below, each component's
// finite minimum and maximum and the counts (as watchStats counts them),
// each texel of the block handed to take(), which each program defines.
const char* const kOutputs = R"(
layout(location = 0) out vec4 oLo;
layout(location = 1) out vec4 oHi;
layout(location = 2) out uvec4 oCount;  // drawn, line ran, NaN, Inf
layout(location = 3) out uvec4 oMore;   // below, above, most components, largest kind
const int kBlock = 4;
const float kMax = 3.402823466e38;
uniform ivec2 uSize;  // of the level read
)";
const char* const kWalk = R"(
void main() {
    ivec2 base = ivec2(gl_FragCoord.xy) * kBlock;
    vec4 lo = vec4(kMax), hi = vec4(-kMax);
    uvec4 count = uvec4(0u), more = uvec4(0u);
    for (int j = 0; j < kBlock; ++j) {
        for (int i = 0; i < kBlock; ++i) {
            ivec2 p = base + ivec2(i, j);
            if (p.x < uSize.x && p.y < uSize.y) take(p, lo, hi, count, more);
        }
    }
    oLo = lo; oHi = hi; oCount = count; oMore = more;
}
)";

// The first level: the watched pass's two targets.
const char* const kLeaf = R"(
uniform highp sampler2D uValue;
uniform highp sampler2D uInfo;  // what is known, as fractions (shader/watch_rewrite.h)
uniform vec2 uRange;  // below and above are counted against it
void take(ivec2 p, inout vec4 lo, inout vec4 hi, inout uvec4 count, inout uvec4 more) {
    vec4 info = texelFetch(uInfo, p, 0);
    if (!(info.x > 0.5)) return;
    count.x += 1u;
    int n = clamp(int(floor(info.y * 4. + 0.5)), 0, 4);
    if (n == 0) return;
    count.y += 1u;
    more.z = max(more.z, uint(n));
    more.w = max(more.w, uint(clamp(int(floor(info.z * 3. + 0.5)), 0, 3)));
    vec4 v = texelFetch(uValue, p, 0);
    for (int c = 0; c < 4; ++c) {  // finite components only
        if (c >= n) break;
        if ((floatBitsToUint(v[c]) & 0x7f800000u) == 0x7f800000u) continue;
        lo[c] = min(lo[c], v[c]);
        hi[c] = max(hi[c], v[c]);
    }
    bool nan, inf, below, above;
    marksOf(v, n, uRange, nan, inf, below, above);
    // One mark per pixel: NaN before Inf before the range.
    if (nan) count.z += 1u;
    else if (inf) count.w += 1u;
    else if (below) more.x += 1u;
    else if (above) more.y += 1u;
}
)";

// Every later level: the blocks of the level below.
const char* const kMerge = R"(
uniform highp sampler2D uLo;
uniform highp sampler2D uHi;
uniform highp usampler2D uCount;
uniform highp usampler2D uMore;
void take(ivec2 p, inout vec4 lo, inout vec4 hi, inout uvec4 count, inout uvec4 more) {
    lo = min(lo, texelFetch(uLo, p, 0));
    hi = max(hi, texelFetch(uHi, p, 0));
    count += texelFetch(uCount, p, 0);
    uvec4 m = texelFetch(uMore, p, 0);
    more = uvec4(more.xy + m.xy, max(more.zw, m.zw));
}
)";

// The picture, as watchPicture draws it on the CPU: t = (v - lo) x uScale
// (1 / (hi - lo), made on the CPU) in float, stored as the byte nearest
// t x 255 (ties to even), or a 4-pixel checker of a marker colour and black.
// A product, not a quotient: GLSL lets a GPU divide to 2.5 ulp (NVIDIA's
// did, and 1 byte in 200 of a vertex watch differed), but rounds a product.
const char* const kColour = R"(
uniform highp sampler2D uValue;
uniform highp sampler2D uInfo;
uniform vec2 uRange;
uniform float uScale;  // 1 / (hi - lo), or 0 when hi - lo is not above 0
uniform int uHeight;
uniform vec3 uMarks[6];  // NaN, Inf, below, above, line not run, nothing drawn
out vec4 oColour;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 info = texelFetch(uInfo, p, 0);
    vec4 v = texelFetch(uValue, p, 0);
    int n = info.x > 0.5 ? clamp(int(floor(info.y * 4. + 0.5)), 0, 4) : 0;
    int mark = info.x > 0.5 ? (n == 0 ? 5 : 0) : 6;
    bool nan, inf, below, above;
    marksOf(v, n, uRange, nan, inf, below, above);
    if (mark == 0) mark = nan ? 1 : inf ? 2 : below ? 3 : above ? 4 : 0;
    if (mark != 0) {
        int row = uHeight - 1 - p.y;  // the checker counts rows from the top, as the picture's rows go
        bool lit = ((p.x / 4) + (row / 4)) % 2 == 0;
        oColour = vec4(lit ? uMarks[mark - 1] : vec3(0.), 1.);
        return;
    }
    vec4 t = uScale > 0. ? (v - uRange.x) * uScale : vec4(0.5);  // one value: mid grey
    vec4 b = roundEven(clamp(t, 0., 1.) * 255.) / 255.;
    oColour = n == 1 ? vec4(b.xxx, 1.) : n == 2 ? vec4(b.xy, 0., 1.) : n == 3 ? vec4(b.xyz, 1.) : b;
}
)";

// The parts of a program's text after the #version its context takes.
std::string versioned(const GlApi& gl, std::initializer_list<const char*> parts) {
    std::string out = gl.es ? "#version 300 es\nprecision highp float;\nprecision highp int;\n" : "#version 330\n";
    for (const char* p : parts) out += p;
    return out;
}

void makeTexture(const GlApi& gl, unsigned id, GLenum internal, GLenum format, GLenum type, int w, int h) {
    gl.BindTexture(GL_TEXTURE_2D, id);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GLint(internal), w, h, 0, format, type, nullptr);
}

void bindUnit(const GlApi& gl, int unit, unsigned texture, unsigned program, const char* name) {
    gl.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
    gl.BindTexture(GL_TEXTURE_2D, texture);
    gl.Uniform1i(gl.GetUniformLocation(program, name), unit);
}

void unbindUnits(const GlApi& gl, int count) {
    for (int unit = count - 1; unit >= 0; --unit) {
        gl.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
        gl.BindTexture(GL_TEXTURE_2D, 0);
    }
}

void drawInto(const GlApi& gl, unsigned fbo, int width, int height, int buffers) {
    static const GLenum kBuffers[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                       GL_COLOR_ATTACHMENT3};
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.DrawBuffers(buffers, kBuffers);
    gl.Viewport(0, 0, width, height);
    gl.Disable(GL_DEPTH_TEST);
    gl.Disable(GL_SCISSOR_TEST);
    gl.Disable(GL_BLEND);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace

void Renderer::dropWatchTargets() {
    if (!watchGpu_) return;
    WatchGpu& w = *watchGpu_;
    if (w.fbo) gl_->DeleteFramebuffers(1, &w.fbo);
    if (w.depth) gl_->DeleteRenderbuffers(1, &w.depth);
    gl_->DeleteTextures(2, w.textures);
    for (auto& l : w.levels) {
        gl_->DeleteFramebuffers(1, &l.fbo);
        gl_->DeleteTextures(4, l.textures);
    }
    w.levels.clear();
    w.fbo = w.depth = w.textures[0] = w.textures[1] = 0;
    w.width = w.height = 0;
    w.drawn = false;
}

bool Renderer::bindWatchTargets(int width, int height, bool depth) {
    if (!watchGpu_) watchGpu_ = std::make_unique<WatchGpu>();
    WatchGpu& w = *watchGpu_;
    if (w.width != width || w.height != height || (depth && !w.depth)) {
        dropWatchTargets();
        w.width = width, w.height = height;
        gl_->GenTextures(2, w.textures);
        gl_->GenFramebuffers(1, &w.fbo);
        gl_->BindFramebuffer(GL_FRAMEBUFFER, w.fbo);
        for (int k = 0; k < 2; ++k) {  // the value in floats; what is known of it in fractions (shader/watch_rewrite.h)
            if (k == 0) makeTexture(*gl_, w.textures[k], GL_RGBA32F, GL_RGBA, GL_FLOAT, width, height);
            else makeTexture(*gl_, w.textures[k], GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
            gl_->FramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + k), GL_TEXTURE_2D, w.textures[k], 0);
        }
        gl_->BindTexture(GL_TEXTURE_2D, 0);
        if (depth) w.depth = attachDepth(width, height);
        // The reduction's levels, each a block's side smaller, down to one
        // small enough to read back.
        for (int lw = width, lh = height; lw * lh > kBlock * kBlock || w.levels.empty();) {
            lw = (lw + kBlock - 1) / kBlock, lh = (lh + kBlock - 1) / kBlock;
            WatchGpu::Level l;
            l.width = lw, l.height = lh;
            gl_->GenTextures(4, l.textures);
            gl_->GenFramebuffers(1, &l.fbo);
            gl_->BindFramebuffer(GL_FRAMEBUFFER, l.fbo);
            for (int k = 0; k < 4; ++k) {
                if (k < 2) makeTexture(*gl_, l.textures[k], GL_RGBA32F, GL_RGBA, GL_FLOAT, lw, lh);
                else makeTexture(*gl_, l.textures[k], GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, lw, lh);
                gl_->FramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + k), GL_TEXTURE_2D, l.textures[k], 0);
            }
            const bool complete = gl_->CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
            w.levels.push_back(l);
            if (!complete) {
                dropWatchTargets();
                return false;
            }
        }
        gl_->BindTexture(GL_TEXTURE_2D, 0);
        gl_->BindFramebuffer(GL_FRAMEBUFFER, w.fbo);
    }
    w.drawn = false;
    Target target;
    target.fbo = w.fbo, target.width = width, target.height = height;
    bindForPass(target, 2, depth);
    if (gl_->CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
        dropWatchTargets();
        return false;
    }
    if (!w.built) {
        w.built = true;
        const std::string vertex = versioned(*gl_, {kVertex});
        w.leaf = buildPlainProgram(*gl_, vertex, versioned(*gl_, {kOutputs, kMarks, kLeaf, kWalk}));
        w.merge = buildPlainProgram(*gl_, vertex, versioned(*gl_, {kOutputs, kMerge, kWalk}));
        w.colour = buildPlainProgram(*gl_, vertex, versioned(*gl_, {kMarks, kColour}));
    }
    return w.leaf && w.merge && w.colour;
}

std::optional<WatchSums> Renderer::sumWatch(float lo, float hi) {
    if (!watchGpu_ || !watchGpu_->drawn || watchGpu_->levels.empty()) return std::nullopt;
    const WatchGpu& w = *watchGpu_;
    int width = w.width, height = w.height;  // the size of what the level reads
    for (size_t k = 0; k < w.levels.size(); ++k) {
        const WatchGpu::Level& l = w.levels[k];
        const unsigned prog = k == 0 ? w.leaf : w.merge;
        gl_->UseProgram(prog);
        const GLint size[2] = {width, height};
        gl_->Uniform2iv(gl_->GetUniformLocation(prog, "uSize"), 1, size);
        if (k == 0) {
            bindUnit(*gl_, 0, w.textures[0], prog, "uValue");
            bindUnit(*gl_, 1, w.textures[1], prog, "uInfo");
            const GLfloat range[2] = {lo, hi};
            gl_->Uniform2fv(gl_->GetUniformLocation(prog, "uRange"), 1, range);
        } else {
            const WatchGpu::Level& from = w.levels[k - 1];
            const char* const names[4] = {"uLo", "uHi", "uCount", "uMore"};
            for (int t = 0; t < 4; ++t) bindUnit(*gl_, t, from.textures[t], prog, names[t]);
        }
        drawInto(*gl_, l.fbo, l.width, l.height, 4);
        unbindUnits(*gl_, 4);
        width = l.width, height = l.height;
    }
    gl_->UseProgram(0);
    // The last level, a few blocks, finished here.
    const WatchGpu::Level& last = w.levels.back();
    const size_t n = size_t(last.width) * size_t(last.height) * 4;
    std::vector<float> los(n), his(n);
    std::vector<unsigned> counts(n), more(n);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, last.fbo);
    gl_->PixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int t = 0; t < 4; ++t) {
        gl_->ReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + t));
        if (t < 2) gl_->ReadPixels(0, 0, last.width, last.height, GL_RGBA, GL_FLOAT, (t ? his : los).data());
        else gl_->ReadPixels(0, 0, last.width, last.height, GL_RGBA_INTEGER, GL_UNSIGNED_INT, (t == 3 ? more : counts).data());
    }
    gl_->ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
    WatchSums s;
    s.width = w.width, s.height = w.height;
    s.lo.fill(3.402823466e38f);
    s.hi.fill(-3.402823466e38f);
    for (size_t i = 0; i < n; i += 4) {
        for (size_t c = 0; c < 4; ++c) s.lo[c] = std::min(s.lo[c], los[i + c]), s.hi[c] = std::max(s.hi[c], his[i + c]);
        s.drawn += counts[i], s.reached += counts[i + 1], s.nan += counts[i + 2], s.inf += counts[i + 3];
        s.below += more[i], s.above += more[i + 1];
        s.components = std::max(s.components, int(more[i + 2]));
        s.kind = std::max(s.kind, int(more[i + 3]));
    }
    return s;
}

void Renderer::colourWatch(float lo, float hi, float scale, const std::array<std::array<unsigned char, 3>, 6>& marks) {
    if (!watchGpu_ || !watchGpu_->drawn || !watchGpu_->colour) return;
    const WatchGpu& w = *watchGpu_;
    if (!watchPicture_ || watchPicture_->width != w.width || watchPicture_->height != w.height) {
        if (!watchPicture_) {
            watchPicture_ = std::make_unique<Target>();
            gl_->GenTextures(1, &watchPictureTexture_);
            gl_->GenFramebuffers(1, &watchPicture_->fbo);
        }
        gl_->BindTexture(GL_TEXTURE_2D, watchPictureTexture_);
        textureParameters(*gl_);
        gl_->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w.width, w.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        gl_->BindTexture(GL_TEXTURE_2D, 0);
        gl_->BindFramebuffer(GL_FRAMEBUFFER, watchPicture_->fbo);
        gl_->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, watchPictureTexture_, 0);
        watchPicture_->width = w.width, watchPicture_->height = w.height;
    }
    gl_->UseProgram(w.colour);
    bindUnit(*gl_, 0, w.textures[0], w.colour, "uValue");
    bindUnit(*gl_, 1, w.textures[1], w.colour, "uInfo");
    const GLfloat range[2] = {lo, hi};
    gl_->Uniform2fv(gl_->GetUniformLocation(w.colour, "uRange"), 1, range);
    gl_->Uniform1f(gl_->GetUniformLocation(w.colour, "uScale"), scale);
    gl_->Uniform1i(gl_->GetUniformLocation(w.colour, "uHeight"), w.height);
    GLfloat colours[18];
    for (size_t m = 0; m < 6; ++m)
        for (size_t c = 0; c < 3; ++c) colours[m * 3 + c] = float(marks[m][c]) / 255.f;
    gl_->Uniform3fv(gl_->GetUniformLocation(w.colour, "uMarks"), 6, colours);
    drawInto(*gl_, watchPicture_->fbo, w.width, w.height, 1);
    unbindUnits(*gl_, 2);
    gl_->UseProgram(0);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
}

Image Renderer::readWatchPicture() const {
    if (!watchGpu_ || !watchGpu_->drawn || !watchPicture_ || watchPicture_->width != watchGpu_->width ||
        watchPicture_->height != watchGpu_->height)
        return {};
    return readPicture(*gl_, watchPicture_->fbo, watchPicture_->width, watchPicture_->height);
}

WatchCapture Renderer::readWatchCapture(int x, int y, int w, int h) const {
    WatchCapture out;
    if (!watchGpu_ || !watchGpu_->drawn) return out;
    const WatchGpu& g = *watchGpu_;
    if (w < 0) x = 0, y = 0, w = g.width, h = g.height;
    if (x < 0 || y < 0 || w < 1 || h < 1 || x > g.width - w || y > g.height - h) return out;
    gl_->BindFramebuffer(GL_FRAMEBUFFER, g.fbo);
    gl_->PixelStorei(GL_PACK_ALIGNMENT, 4);
    out.value = Image::rgbaF32(w, h);
    gl_->ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl_->ReadPixels(x, g.height - y - h, w, h, GL_RGBA, GL_FLOAT, out.value.f32.data());
    out.value.f32 = flipRows(out.value.f32, h);
    // What is known, stored as fractions in bytes, given back as WatchCapture
    // says: x 1 or 0, y the component count, z the kind.
    std::vector<unsigned char> bytes(size_t(w) * size_t(h) * 4);
    gl_->ReadBuffer(GL_COLOR_ATTACHMENT1);
    gl_->PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_->ReadPixels(x, g.height - y - h, w, h, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    bytes = flipRows(bytes, h);
    out.info = Image::rgbaF32(w, h);
    for (size_t i = 0; i < bytes.size(); i += 4) {
        out.info.f32[i] = bytes[i] > 127 ? 1.f : 0.f;
        out.info.f32[i + 1] = std::round(bytes[i + 1] / 255.f * 4.f);
        out.info.f32[i + 2] = std::round(bytes[i + 2] / 255.f * 3.f);
        out.info.f32[i + 3] = 1.f;
    }
    gl_->ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl_->BindFramebuffer(GL_FRAMEBUFFER, 0);
    return out;
}

}  // namespace glimmer
