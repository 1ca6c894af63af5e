#include "image/animation.h"
#include "util/write_file.h"

#include <webp/demux.h>
#include <webp/encode.h>
#include <webp/mux.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>

namespace glimmer {
namespace {

// Finds the one number conversion: its start, its end (one past 'd') and
// its zero-padded width. False when there is none or more than one, or a '%'
// that is not %% or %[0]Nd.
bool findConversion(const std::string& p, size_t& start, size_t& end, int& width, std::string& error) {
    int found = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        if (p[i] != '%') continue;
        if (i + 1 < p.size() && p[i + 1] == '%') {
            ++i;
            continue;
        }
        size_t j = i + 1;
        int w = 0;
        while (j < p.size() && std::isdigit(static_cast<unsigned char>(p[j])) && j - i <= 3) w = w * 10 + (p[j++] - '0');
        if (j >= p.size() || p[j] != 'd') {
            error = "'" + p + "': a frame name takes one %d, or %04d for a zero-padded number";
            return false;
        }
        start = i;
        end = j + 1;
        width = w;
        ++found;
        i = j;
    }
    if (found != 1) {
        error = "'" + p + "': a frame name takes exactly one %d (such as frame_%04d.png)";
        return false;
    }
    return true;
}

std::string unescapePercents(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        out += s[i];
        if (s[i] == '%' && i + 1 < s.size() && s[i + 1] == '%') ++i;
    }
    return out;
}

}  // namespace

bool isFramePattern(const std::string& path) {
    for (size_t i = 0; i < path.size(); ++i) {
        if (path[i] != '%') continue;
        if (i + 1 < path.size() && path[i + 1] == '%') {
            ++i;
            continue;
        }
        return true;
    }
    return false;
}

bool frameFileName(const std::string& pattern, int frame, std::string& out, std::string& error) {
    size_t start = 0, end = 0;
    int width = 0;
    if (!findConversion(pattern, start, end, width, error)) return false;
    std::string number = std::to_string(frame);
    if (int(number.size()) < width) number.insert(0, size_t(width) - number.size(), '0');
    out = unescapePercents(pattern.substr(0, start)) + number + unescapePercents(pattern.substr(end));
    return true;
}

bool writeAnimatedWebp(const std::string& path, const std::vector<Image>& frames, double fps, std::string& error) {
    if (frames.empty() || !(fps > 0)) {
        error = "an animation needs at least one frame and a positive frame rate";
        return false;
    }
    const int w = frames[0].width, h = frames[0].height;
    WebPAnimEncoderOptions options;
    if (!WebPAnimEncoderOptionsInit(&options)) {
        error = "libwebp: version mismatch";
        return false;
    }
    options.anim_params.loop_count = 0;  // forever, as slides want
    options.allow_mixed = 0;
    std::unique_ptr<WebPAnimEncoder, void (*)(WebPAnimEncoder*)> enc(WebPAnimEncoderNew(w, h, &options),
                                                                     WebPAnimEncoderDelete);
    if (!enc) {
        error = "libwebp: cannot start an animation of " + std::to_string(w) + "x" + std::to_string(h);
        return false;
    }
    WebPConfig config;
    WebPConfigInit(&config);
    config.lossless = 1;  // the frames decode to exactly the pixels rendered
    config.quality = 75;
    config.method = 4;
    auto timestamp = [&](size_t i) { return int(std::lround(double(i) * 1000.0 / fps)); };
    for (size_t i = 0; i < frames.size(); ++i) {
        const Image& f = frames[i];
        if (f.type != Image::Type::U8 || f.width != w || f.height != h) {
            error = "animation frames must be 8-bit and of one size";
            return false;
        }
        WebPPicture pic;
        WebPPictureInit(&pic);
        pic.use_argb = 1;
        pic.width = w;
        pic.height = h;
        if (!WebPPictureImportRGBA(&pic, f.u8.data(), w * 4)) {
            WebPPictureFree(&pic);
            error = "libwebp: out of memory";
            return false;
        }
        bool ok = WebPAnimEncoderAdd(enc.get(), &pic, timestamp(i), &config);
        WebPPictureFree(&pic);
        if (!ok) {
            error = std::string("libwebp: ") + WebPAnimEncoderGetError(enc.get());
            return false;
        }
    }
    WebPAnimEncoderAdd(enc.get(), nullptr, timestamp(frames.size()), nullptr);
    WebPData data;
    WebPDataInit(&data);
    if (!WebPAnimEncoderAssemble(enc.get(), &data)) {
        error = std::string("libwebp: ") + WebPAnimEncoderGetError(enc.get());
        return false;
    }
    bool written = writeBytesReplacing(path, data.bytes, data.size, error);
    WebPDataClear(&data);
    return written;
}

bool readAnimatedWebp(const std::string& path, DecodedAnimation& out, std::string& error) {
    std::vector<std::uint8_t> bytes;
    if (!readFileBytes(path, bytes, error)) return false;
    WebPData data{bytes.data(), bytes.size()};
    WebPAnimDecoderOptions options;
    if (!WebPAnimDecoderOptionsInit(&options)) {
        error = "libwebp: version mismatch";
        return false;
    }
    options.color_mode = MODE_RGBA;
    options.use_threads = 0;
    std::unique_ptr<WebPAnimDecoder, void (*)(WebPAnimDecoder*)> dec(WebPAnimDecoderNew(&data, &options),
                                                                     WebPAnimDecoderDelete);
    if (!dec) {
        error = path + ": not a WebP file";
        return false;
    }
    WebPAnimInfo info;
    if (!WebPAnimDecoderGetInfo(dec.get(), &info)) {
        error = path + ": cannot read the animation's header";
        return false;
    }
    out = {};
    out.width = int(info.canvas_width);
    out.height = int(info.canvas_height);
    out.loopCount = int(info.loop_count);
    while (WebPAnimDecoderHasMoreFrames(dec.get())) {
        uint8_t* buf = nullptr;
        int timestamp = 0;
        if (!WebPAnimDecoderGetNext(dec.get(), &buf, &timestamp)) {
            error = path + ": a frame cannot be decoded";
            return false;
        }
        Image img = Image::rgba8(out.width, out.height);
        std::copy_n(buf, img.u8.size(), img.u8.data());
        out.frames.push_back(std::move(img));
        out.timestampsMs.push_back(timestamp);
    }
    return true;
}

}  // namespace glimmer
