// PNG and JPEG through stb_image. Only called for bytes that sniffImage
// named PNG or JPEG, so stb's other decoders (PNM, TGA, ... with their
// known bugs in Debian's 2022 snapshot) are never reached.
#include <stb/stb_image.h>

#include <cstring>
#include <memory>

#include "image/sniff.h"

namespace glimmer {
namespace {

struct StbFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

}  // namespace

bool decodePngJpeg(const std::vector<std::uint8_t>& bytes, Image& out, std::string& error) {
    if (bytes.size() > std::size_t(0x7fffffff)) {  // stb takes an int length
        error = "image file too large";
        return false;
    }
    const int len = int(bytes.size());
    int w = 0, h = 0, n = 0;
    if (!stbi_info_from_memory(bytes.data(), len, &w, &h, &n)) {
        error = std::string("cannot decode image: ") + stbi_failure_reason();
        return false;
    }
    if (!checkImageSize(w, h, error)) return false;
    int dw = 0, dh = 0;
    std::unique_ptr<stbi_uc, StbFree> px(stbi_load_from_memory(bytes.data(), len, &dw, &dh, &n, 4));
    if (!px) {
        error = std::string("cannot decode image: ") + stbi_failure_reason();
        return false;
    }
    if (dw != w || dh != h) {  // never trust a size twice read
        error = "image size changed while decoding";
        return false;
    }
    out = Image::rgba8(w, h);
    std::memcpy(out.u8.data(), px.get(), out.u8.size());
    return true;
}

}  // namespace glimmer
