// What every front end is asked to do, as plain values: the command line
// (src/app) fills these in, the driver and the front ends read them. Exit
// codes and the small parsers every command shares live here too, so the
// viewer, the benchmarks and the tests need nothing from the executable.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "grade/grading.h"  // Thresholds: grading's defaults, said once

namespace glimmer {

// The process's exit code: 0 success, 1 script or shader errors, 2 usage errors.
enum ExitCode { kExitOk = 0, kExitScriptError = 1, kExitUsage = 2 };

struct CommonOptions {
    std::string script;
    std::string backend = "auto";
    std::vector<std::string> includeDirs;
    std::vector<std::string> sets;  // name=value
    std::string size;               // WxH
    bool standIns = false;          // --stand-ins: missing images and models are replaced (assets/stand_ins.h)
    bool sandbox = false;           // files only inside the script's folder and -I folders
    std::uint64_t maxMemoryMiB = 0; // 0: the default budget (plan/limits.h)
    double timeoutSeconds = 0;      // --timeout: the GL work runs in a child stopped after this (0: no limit)
};

// glimmer check: --web translates every shader for WebGL 2 instead of compiling on a context.
struct CheckOptions : CommonOptions {
    bool web = false;
    std::string watch;        // --watch FILE:LINE:EXPR: can this be watched? (pipeline/watch.h)
    bool listInputs = false;  // --list-inputs: after a clean check, every file the script reads on stdout
};

struct RenderOptions : CommonOptions {
    std::string output = "out.png";
    std::vector<std::string> dumps;  // UNIT=file.png
    double time = 0;
    int frames = 1;   // --frames: a sequence, Timer advancing 1/fps a frame from `time`
    double fps = 24;  // --fps
    bool timings = false;
    int pngLevel = 3;     // --png-level: zlib's level for the PNGs, 0 to 9 (image.h's kDefaultPngLevel)
    bool health = false;  // print the numeric health of every target
    bool strict = false;  // and exit 1 if any holds NaN, Inf, negatives or values above 65504
    std::string watch;       // --watch FILE:LINE:EXPR: that value over its pass instead of the picture
    std::string watchRange;  // --watch-range LO,HI (default: the values' own)
};

struct SheetOptions : CommonOptions {
    std::vector<std::string> vary;  // NAME=V1,V2,... (columns, then rows)
    std::string output = "sheet.png";
};

// glimmer batch: scripts from the command line and --list, one PNG each in outputDir.
struct BatchOptions : CommonOptions {
    std::vector<std::string> scripts;
    std::string list;       // a file with one script per line
    std::string outputDir;  // -o
    std::string report;     // JSON lines
    std::string shard;      // I/N
    int jobs = 2;
    bool strict = false;
    // Grading (folders and zips, one per student; app/grade_batch.cpp):
    std::string reference;          // --reference: the teacher's solution
    std::vector<std::string> vary;  // NAME=V1,V2,...: the settings compared (default: the solution's sliders)
    bool noSandbox = false;         // --no-sandbox: grading sandboxes by default
    bool resume = false;            // --resume: keep what -o already holds, grade only the rest
    std::vector<std::string> only;  // --only NAME: regrade these students into what -o already holds
    std::string overrides;          // --overrides FILE: the teacher's scores and comments (grade/overrides.h)
    Thresholds thresholds;          // --pass-ssim, --pass-psnr, --look-ssim, --look-psnr
};

// glimmer batch-merge: the shards of a grading job array joined into one report.
struct BatchMergeOptions {
    std::vector<std::string> shards;  // the shards' -o folders
    std::string outputDir;
    std::string overrides;            // --overrides FILE, as for batch
};

struct TradeoffOptions {
    std::string image;  // empty: the grid pattern, generated at `size`
    std::string size;
    std::string format = "RGBA16F";
    int repeat = 5;
    std::vector<std::string> methods;
    std::string backend = "auto";
    std::string output = "tradeoff";
    double matchSigma = 0;  // > 0: one method per family, scaled to this sigma (bloom/blur_methods.h)
};

// "512x512" -> 512, 512. False on anything else, or a side outside 1..16384.
bool parseSize(const std::string& text, int& w, int& h);

}  // namespace glimmer
