// The texel-rate floor: how long the driver takes, with nothing of Glimmer
// in the way, to fetch N filtered texels per pixel from a texture of a
// format into a target of the same format. `tradeoff` divides each blur's
// taps by this rate and shows how far above the floor the method runs
// (issue 13: on the H100 a 9-tap pass sat exactly at 31.7 Gtexel/s when
// hand-written, Glimmer's did not). Hand-written GL, one full-screen
// triangle, no script, so it measures the hardware, not the interpreter.
// Held by test_render's TexelRate case to renderer.h's limits (issue 40:
// src/gl scored 10 of 14 in the first sampled mutants; docs/RELIABILITY.md).
#include "gl/renderer_internal.h"

#include "util/pcg32.h"

namespace glimmer {
using namespace renderer_detail;
namespace {

const char* const kVertex = R"(#version 330 compatibility
out vec2 vST;
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    vST = p;
    gl_Position = vec4(p * 2. - 1., 0., 1.);
}
)";

// Taps along s, centred, bilinear like every blur kernel's texture() call;
// the count is a constant (inserted below), so the loop unrolls as the
// kernels' own constant loops do.
const char* const kFragment = R"(
uniform sampler2D uImage;
in vec2 vST;
void main() {
    vec2 texel = 1. / vec2(textureSize(uImage, 0));
    vec3 sum = vec3(0.);
    for (int i = 0; i < kTaps; ++i)
        sum += texture(uImage, vST + vec2(float(i - kTaps / 2) * texel.x, 0.)).rgb;
    gl_FragColor = vec4(sum / float(kTaps), 1.);
}
)";

}  // namespace

double Renderer::texelRateMs(int width, int height, TextureDecl::Format format, int taps, int repeat,
                             std::chrono::milliseconds warmUp) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384 || taps < 1 || taps > 1024 || repeat < 1) return -1;
    const GlApi& gl = *gl_;
    const std::string fragment = fmt::format("#version 330 compatibility\nconst int kTaps = {};\n{}", taps, kFragment);
    const unsigned prog = buildPlainProgram(gl, kVertex, fragment);
    if (!prog) return -1;

    // Noise, not a cleared texture: a driver may keep a cleared one compressed.
    std::vector<float> noise(size_t(width) * size_t(height) * 4);
    Pcg32 rng(7);
    for (float& v : noise) v = rng.unit();
    unsigned tex[2] = {0, 0}, fbo = 0;
    gl.GenTextures(2, tex);
    for (int i = 0; i < 2; ++i) {
        gl.BindTexture(GL_TEXTURE_2D, tex[i]);
        textureParameters(gl, GL_TEXTURE_2D);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat(format)), width, height, 0, GL_RGBA, GL_FLOAT,
                      i == 0 ? noise.data() : nullptr);
    }
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex[1], 0);
    const GLenum buffer = GL_COLOR_ATTACHMENT0;
    gl.DrawBuffers(1, &buffer);
    gl.Viewport(0, 0, width, height);
    gl.Disable(GL_DEPTH_TEST);
    gl.Disable(GL_SCISSOR_TEST);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, tex[0]);
    gl.UseProgram(prog);
    gl.Uniform1i(gl.GetUniformLocation(prog, "uImage"), 0);

    // Warm-up: llvmpipe compiles at first draw; a GPU raises its clocks.
    const auto warmStart = std::chrono::steady_clock::now();
    do {
        gl.DrawArrays(GL_TRIANGLES, 0, 3);
        gl.Finish();
    } while (std::chrono::steady_clock::now() - warmStart < warmUp);
    std::vector<double> ms;
    for (int r = 1; r <= repeat; ++r) {
        double t = 0;
        if (gpuTimers()) {
            unsigned q = 0;
            gl.GenQueries(1, &q);
            gl.BeginQuery(GL_TIME_ELAPSED, q);
            gl.DrawArrays(GL_TRIANGLES, 0, 3);
            gl.EndQuery(GL_TIME_ELAPSED);
            GLuint64 ns = 0;
            gl.GetQueryObjectui64v(q, GL_QUERY_RESULT, &ns);
            gl.DeleteQueries(1, &q);
            t = double(ns) / 1e6;
        } else {
            gl.Finish();
            auto start = std::chrono::steady_clock::now();
            gl.DrawArrays(GL_TRIANGLES, 0, 3);
            gl.Finish();
            t = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        }
        if (r > 0) ms.push_back(t);
    }
    gl.UseProgram(0);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.DeleteFramebuffers(1, &fbo);
    gl.DeleteTextures(2, tex);
    gl.DeleteProgram(prog);
    // The fastest run: other work on a shared GPU (the lent H100 is
    // time-sliced: the same pass measured 1.0 and 5.7 ms in one run) only
    // ever adds time, so the fastest is the closest to what the hardware does.
    return *std::min_element(ms.begin(), ms.end());
}

}  // namespace glimmer
