// The writers of deep pictures, 16-bit PNG (libpng) and OpenEXR (tinyexr),
// in a file of their own: the browser build (src/web) has neither library
// and links src/web/web_image_writers.cpp in their place.
#include <png.h>
#include <tinyexr.h>

#include <algorithm>
#include <cmath>

#include "image/float_pixels.h"
#include "image/image.h"
#include "util/write_file.h"

namespace glimmer {

bool writePng16(const std::string& path, const Image& img, std::string& error) {
    // libpng's simplified API: 16 bits a channel, the values as they are
    // (clamped to 0..1), tagged linear (gAMA 1.0).
    std::vector<float> px;
    if (!floatPixels(img, "writePng16", px, error)) return false;
    std::vector<png_uint_16> out(px.size());
    for (size_t i = 0; i < px.size(); ++i)
        out[i] = png_uint_16(std::lround(std::clamp(double(px[i]), 0.0, 1.0) * 65535.0));
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = png_uint_32(img.width);
    image.height = png_uint_32(img.height);
    image.format = PNG_FORMAT_LINEAR_RGB_ALPHA;
    return writeReplacing(path, [&](const std::string& target, std::string& why) {
        if (png_image_write_to_file(&image, target.c_str(), 0, out.data(), 0, nullptr)) return true;
        why = "cannot write " + path + ": " + image.message;
        return false;
    }, error);
}

bool writeExr(const std::string& path, const Image& img, std::string& error) {
    std::vector<float> px;
    if (!floatPixels(img, "writeExr", px, error)) return false;
    return writeReplacing(path, [&](const std::string& target, std::string& why) {
        const char* err = nullptr;
        if (SaveEXR(px.data(), img.width, img.height, 4, 0, target.c_str(), &err) >= 0) return true;
        why = "cannot write " + path + (err ? std::string(": ") + err : std::string());
        if (err) FreeEXRErrorMessage(err);
        return false;
    }, error);
}

}  // namespace glimmer
