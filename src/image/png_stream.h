// A PNG in memory, for `render -o -` (the picture on standard output, to a
// pipe) and for tests that compare encodings.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace glimmer {

// The bytes writePng would write at `level` (0 to 9); empty for a float or
// empty image, or a level out of range. Rows are filtered and deflated in
// strips on several threads (src/image/png_write.cpp).
std::vector<std::uint8_t> encodePng(const Image& img, int level = kDefaultPngLevel);

// Writes the PNG to standard output (binary, flushed). False, with
// `error`, when the image cannot be encoded or stdout cannot take it.
bool writePngToStdout(const Image& img, std::string& error, int level = kDefaultPngLevel);

}  // namespace glimmer
