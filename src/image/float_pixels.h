// Shared by the float writers (image.cpp, deep_writers.cpp).
#pragma once
#include <string>
#include <vector>

#include "image/image.h"

namespace glimmer {

// The pixels of a float writer's input as float RGBA, row 0 at the top;
// false (and why, named after the writer) when the image is empty or its
// buffer does not fit it.
bool floatPixels(const Image& img, const char* writer, std::vector<float>& px, std::string& error);

}  // namespace glimmer
