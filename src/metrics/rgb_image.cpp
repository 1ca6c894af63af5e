#include "metrics/rgb_image.h"

namespace glimmer {

RgbImage toRgb(const Image& img) {
    RgbImage out;
    out.width = img.width;
    out.height = img.height;
    out.rgb.resize(size_t(img.width) * size_t(img.height) * 3);
    for (size_t i = 0; i < size_t(img.width) * size_t(img.height); ++i)
        for (size_t c = 0; c < 3; ++c)
            out.rgb[i * 3 + c] = img.type == Image::Type::U8 ? img.u8[i * 4 + c] / 255.0 : double(img.f32[i * 4 + c]);
    return out;
}

}  // namespace glimmer
