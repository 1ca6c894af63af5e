// libFuzzer: every image decoder Glimmer uses, chosen as loadImage chooses
// (by content; GLIMMER_FUZZ_DECODER picks one at build time).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/sniff.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace glimmer;
    const std::vector<std::uint8_t> bytes(data, data + size);
    Image img;
    Volume vol;
    std::string error;
#if GLIMMER_FUZZ_DECODER == 0
    decodeBmp(bytes, img, error);
#elif GLIMMER_FUZZ_DECODER == 1
    decodePngJpeg(bytes, img, error);
#elif GLIMMER_FUZZ_DECODER == 2
    decodeHdr(bytes, img, error);
#else
    decodeTex2D(bytes, img, error);
    decodeTex3D(bytes, vol, error);
#endif
    return 0;
}
