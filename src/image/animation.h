// Frame sequences: `render --frames N --fps F` writes either one PNG per
// frame (a printf-style number in the name, frame_%04d.png) or one animated
// WebP through Debian's libwebp (WebPAnimEncoder), lossless, looping, that
// a teacher can drop into slides.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace glimmer {

// "frame_%04d.png", 7 -> "frame_0007.png". The pattern must hold exactly one
// %d, optionally with a zero-padded width (%04d); "%%" is a percent sign.
// False (and `error`) for anything else.
bool frameFileName(const std::string& pattern, int frame, std::string& out, std::string& error);

// Whether `path` names a frame pattern (holds a '%' conversion other than %%).
bool isFramePattern(const std::string& path);

// An animated WebP, lossless, looping forever; frame i shown from
// i * 1000 / fps ms. RGBA8 frames of one size.
bool writeAnimatedWebp(const std::string& path, const std::vector<Image>& frames, double fps, std::string& error);

struct DecodedAnimation {
    std::vector<Image> frames;
    std::vector<int> timestampsMs;  // when each frame ends, as libwebp reports it
    int loopCount = -1;             // 0: forever
    int width = 0, height = 0;
};

// Reads an animated (or still) WebP back with libwebp's WebPAnimDecoder.
bool readAnimatedWebp(const std::string& path, DecodedAnimation& out, std::string& error);

}  // namespace glimmer
