// What a target's format does to a bloom's numbers, as figures: an HDR ramp
// (0 to 2 across the picture) blurred once into each format. 8-bit targets
// band (few distinct levels) and clip at 1; float targets keep both.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include <fmt/format.h>

#include "pipeline/prepare_script.h"
#include "backends/context.h"
#include "gl/renderer.h"
#include "plan/uniform_values.h"

namespace glimmer {

int formatFigures(const std::string& backendName) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / fmt::format("glimmer-formats-{}", ::getpid());
    fs::create_directories(dir);
    std::ofstream(dir / "st.vert") << "#version 330 compatibility\nout vec2 vST;\nvoid main() {\n"
                                      "    vST = gl_MultiTexCoord0.st;\n"
                                      "    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n}\n";
    // A smooth ramp 0..2 along s, the same on every row.
    std::ofstream(dir / "ramp.frag") << "#version 330 compatibility\nin vec2 vST;\n"
                                        "void main() { gl_FragColor = vec4(vec3(2.0 * vST.s), 1.0); }\n";
    std::ofstream(dir / "copy.frag") << "#version 330 compatibility\nuniform sampler2D Src;\nin vec2 vST;\n"
                                        "void main() { gl_FragColor = texture(Src, vST); }\n";
    BackendChoice choice;
    std::string why;
    if (!parseBackend(backendName, choice)) return 2;
    auto ctx = createContext(choice, why);
    if (!ctx) {
        fmt::print(stderr, "{}\n", why);
        return 1;
    }
    fmt::print("\n== target formats: a 0..2 ramp, 1024 texels wide, drawn into each format ==\n");
    fmt::print("{:<16}{:>16}{:>18}{:>16}{:>16}\n", "format", "levels in 0..1", "clipped at 1 (%)", "max error<=1",
               "max value");
    for (const char* format : {"RGBA8", "R11F_G11F_B10F", "RGBA16F", "RGBA32F"}) {
        std::ofstream(dir / "f.glib") << fmt::format(
            "Ortho -1 1 -1 1\nLookAt 0 0 1  0 0 0  0 1 0\nTexture2D 5 1024 4 RGBA32F\nTexture2D 6 1024 4 {}\n"
            "Vertex st.vert\nRenderToTexture 5\nFragment ramp.frag\nProgram Ramp\nQuadXY 0 1\n"
            "RenderToTexture 6\nFragment copy.frag\nProgram Copy Src 5\nQuadXY 0 1\nRenderToTexture\n",
            format);
        Diagnostics d;
        LoadedScript ls;
        ScriptRequest request;
        request.script = (dir / "f.glib").string();
        request.plan.keepTargets = {6};
        auto r = prepareScript(request, [&](const char* n) { return ctx->getProcAddress(n); }, d, ls);
        if (!r) {
            printDiagnostics(d, ls.sources, std::cerr);
            return 1;
        }
        r->render(UniformValues(ls.plan), 0);
        Image out = r->readTextureFloat(ls.plan.finalUnits.at(6));
        std::set<float> levels;
        int clipped = 0, aboveOne = 0;
        double maxErr = 0, maxValue = 0;
        for (int x = 0; x < out.width; ++x) {
            double exact = 2.0 * (x + 0.5) / out.width;
            float v = out.f32[size_t(x) * 4];  // row 0, red
            maxValue = std::max(maxValue, double(v));
            if (exact <= 1.0) {
                levels.insert(v);
                maxErr = std::max(maxErr, std::abs(v - exact));
            } else {
                ++aboveOne;
                clipped += v == 1.0f;
            }
        }
        fmt::print("{:<16}{:>16}{:>18.1f}{:>16.2e}{:>16.4f}\n", format, levels.size(), 100.0 * clipped / aboveOne,
                   maxErr, maxValue);
    }
    // What a blur can cost at best in each format: the texel-rate floor that
    // `tradeoff` divides by (gl/texel_rate.cpp), per format, same context.
    fmt::print("\n== texel rate: a hand-written pass of 9 bilinear taps a pixel, 1920x1080, from each format ==\n");
    fmt::print("{:<16}{:>12}{:>14}\n", "format", "ms", "Gtexel/s");
    auto probe = Renderer::create([&](const char* n) { return ctx->getProcAddress(n); }, why);
    for (const char* format : {"RGBA8", "R11F_G11F_B10F", "RGBA16F", "RGBA32F"}) {
        TextureDecl::Format f;
        if (!probe || !parseTextureFormat(format, f)) break;
        const double ms = probe->texelRateMs(1920, 1080, f, 9, 5);
        fmt::print("{:<16}{:>12.3f}{:>14.2f}\n", format, ms, ms > 0 ? 9.0 * 1920 * 1080 / (ms * 1e6) : 0.0);
    }
    fs::remove_all(dir);
    return 0;
}

}  // namespace glimmer
