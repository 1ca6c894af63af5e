#include "serve/join_qr.h"

#include <qrencode.h>

#include <fmt/format.h>
#include <memory>

namespace glimmer {
namespace {

constexpr int kQuiet = 2;

struct Code {
    int width = 0;
    std::unique_ptr<QRcode, void (*)(QRcode*)> code{nullptr, QRcode_free};
    // Dark at (x, y), counting the quiet zone (always light) around it.
    bool dark(int x, int y) const {
        x -= kQuiet;
        y -= kQuiet;
        if (x < 0 || y < 0 || x >= width || y >= width) return false;
        return code->data[y * width + x] & 1;
    }
};

Code encode(const std::string& text) {
    Code c;
    c.code.reset(QRcode_encodeString8bit(text.c_str(), 0, QR_ECLEVEL_M));
    if (c.code) c.width = c.code->width;
    return c;
}

}  // namespace

std::string qrForTerminal(const std::string& text) {
    const Code c = encode(text);
    if (!c.code) return "";
    const int side = c.width + 2 * kQuiet;
    std::string out;
    for (int y = 0; y < side; y += 2) {
        for (int x = 0; x < side; ++x) {
            const bool top = !c.dark(x, y), bottom = y + 1 < side && !c.dark(x, y + 1);
            out += top && bottom ? "\u2588" : top ? "\u2580" : bottom ? "\u2584" : " ";
        }
        out += "\n";
    }
    return out;
}

std::string qrSvg(const std::string& text) {
    const Code c = encode(text);
    if (!c.code) return "";
    const int side = c.width + 2 * kQuiet;
    std::string out = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {0} {0}\" shape-rendering=\"crispEdges\">"
        "<rect width=\"{0}\" height=\"{0}\" fill=\"#fff\"/><path fill=\"#000\" d=\"",
        side);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            if (c.dark(x, y)) out += fmt::format("M{} {}h1v1h-1z", x, y);
    out += "\"/></svg>";
    return out;
}

}  // namespace glimmer
