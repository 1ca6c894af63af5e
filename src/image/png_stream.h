// A PNG in memory, for `render -o -` (the picture on standard output, to a
// pipe) and for tests that compare encodings.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace glimmer {

// The bytes writePng would write; empty for a float or empty image.
std::vector<std::uint8_t> encodePng(const Image& img);

// Writes the PNG to standard output (binary, flushed). False, with
// `error`, when the image cannot be encoded or stdout cannot take it.
bool writePngToStdout(const Image& img, std::string& error);

}  // namespace glimmer
