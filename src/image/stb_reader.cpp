// PNG and JPEG through stb_image. stb picks its decoder from the bytes, and
// its other decoders (PNM, TGA, ...) have known bugs in Debian's 2022
// snapshot (a 16-bit PNM reads past its buffer: a 600 s fuzzing campaign
// on 16 cores found it through this function when fed unsniffed bytes), so
// this function itself refuses anything sniffImage does not call PNG or
// JPEG, whoever calls it.
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
    const ImageFormat format = sniffImage(bytes, {});
    if (format != ImageFormat::Png && format != ImageFormat::Jpeg) {
        error = "not a PNG or JPEG file (by its first bytes)";
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
