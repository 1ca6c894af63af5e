// Grading one submission's pictures against the solution's: which slider
// settings to try, how alike two pictures are, and the verdict. Pure
// functions on pictures already rendered; no GL.
// Issue 40's sampled mutants found two things no test held (src/grade at 2
// of 4 then): the thumbnails the report shows, now compared byte for byte
// against their picture's quadrants, and Thresholds' defaults, which the
// program read from a second copy in BatchOptions (now it holds these).
#pragma once
#include <string>
#include <vector>

#include "image/image.h"

namespace glimmer {

// One slider of the solution: `uX <min value max>` in a Program line.
struct Slider {
    std::string name;
    double min = 0, value = 0, max = 0;
};

// One setting: "name=value" assignments (`--set` syntax); empty: the script's own values.
using Setting = std::vector<std::string>;

// The solution's defaults first, then each slider at its min and at its max
// with the others at their defaults (a picture painted for one setting then
// fails the others), at most `maxSettings` in all, repeated values skipped.
std::vector<Setting> settingsFromSliders(const std::vector<Slider>& sliders, size_t maxSettings = 16);

// --vary NAME=a,b,c (one or more): defaults first, then each value of each
// name with the rest at their defaults. False, with `error`, on a malformed one.
bool settingsFromVary(const std::vector<std::string>& vary, std::vector<Setting>& out, std::string& error);

// "uX=0.5, uY=1", or "defaults" for the empty setting.
std::string settingLabel(const Setting& s);

// What a mean over the whole picture misses: a threshold on max(r,g,b)
// instead of luma (70 pixels off by up to 71 levels) or edges that wrap
// instead of clamping (1,357 pixels off by up to 89) passed at SSIM 0.99+
// (issue 29). So the comparison also counts the pixels off by more than
// kLocalLevels in any channel, and keeps the SSIM of the worst tile of
// kTileSide x kTileSide: an error a person sees at once, whatever its share
// of the picture.
constexpr int kLocalLevels = 24;  // about a tenth of the range: never two right answers' rounding
constexpr int kTileSide = 32;

struct Comparison {
    double psnr = 0;   // dB over RGB, peak 1; +inf when identical
    double ssim = 0;   // mean SSIM of the luma (metrics/ssim.h), 8x8 windows
    bool blank = false;  // the student's picture is a single colour and the solution's is not
    double offShare = 0;   // the share of pixels off by more than kLocalLevels in some channel
    double worstTile = 1;  // the lowest mean SSIM of a kTileSide tile (both: no local error, unless measured)
};

// Both RGBA8. A size mismatch or a float picture compares as PSNR 0, SSIM 0.
Comparison comparePictures(const Image& student, const Image& solution);

// Comparison::blank alone, without the measures (grading's recheck asks it
// of every finished submission before comparing it for its row).
bool blankAgainst(const Image& student, const Image& solution);

// |student - solution| per channel, times 4 (small errors show), opaque.
Image differencePicture(const Image& student, const Image& solution);

// A box-filtered copy whose longer side is at most `maxSide`.
Image thumbnail(const Image& picture, int maxSide);

struct Thresholds {
    double passSsim = 0.95, passPsnr = 30;  // both, at every setting: pass
    double lookSsim = 0.70;                 // at the worst setting: close enough for a person to look
    // A pass also needs, at every setting, at most this share of pixels off
    // by more than kLocalLevels (0.01%: 26 pixels of 512x512, where a step()
    // written > instead of >= may flip a few) and no tile below this SSIM;
    // otherwise it is "look", said with where.
    double passOffShare = 0.0001, passTileSsim = 0.90;
    // A look also needs PSNR >= this at every setting: 18 dB is an RMS error
    // of 32 levels, every pixel an eighth of the range off on average. SSIM
    // of the luma forgives a change of brightness over flat regions: a
    // submission painted for the default setting (its sliders read by no
    // shader) kept SSIM 0.754 at uThreshold=0.1, where its picture was
    // 13.6 dB from the solution's, and was a "look" (the generated class of
    // tools/grading-class.py). The looks measured there and in the tests,
    // mistakes in a place, stay between 20 and 45 dB.
    double lookPsnr = 18;
};

// "pass", "look" (needs a person), "wrong", "error" (nothing to compare:
// no script, does not compile, timed out, crashed).
struct Verdict {
    std::string kind;
    int score = 0;      // 100 x the worst setting's SSIM, clamped to 0..100; 0 for "error"
    std::string notes;  // why, in words
};

// `worst`: the setting with the lowest SSIM. `missing`: uniforms the
// solution has and the submission lacks (a pass becomes "look").
Verdict judge(const std::vector<Comparison>& perSetting, const std::vector<std::string>& missing,
              const Thresholds& t, size_t& worst);

// Standard base64 (RFC 4648, with padding), for data URLs.
std::string base64(const std::vector<std::uint8_t>& bytes);

}  // namespace glimmer
