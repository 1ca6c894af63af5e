// The subcommands of the glimmer program. Each returns the process's exit
// code: 0 success, 1 script or shader errors, 2 usage errors.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "backends/context.h"

namespace CLI {
class App;
}

namespace glimmer {

enum ExitCode { kExitOk = 0, kExitScriptError = 1, kExitUsage = 2 };

struct CommonOptions {
    std::string script;
    std::string backend = "auto";
    std::vector<std::string> includeDirs;
    std::vector<std::string> sets;  // name=value
    std::string size;               // WxH
    bool sandbox = false;           // files only inside the script's folder and -I folders
    std::uint64_t maxMemoryMiB = 0; // 0: the default budget (plan/limits.h)
};

struct RenderOptions : CommonOptions {
    std::string output = "out.png";
    std::vector<std::string> dumps;  // UNIT=file.png
    double time = 0;
    bool timings = false;
    bool health = false;  // print the numeric health of every target
    bool strict = false;  // and exit 1 if any holds NaN, Inf, negatives or values above 65504
};

struct SheetOptions : CommonOptions {
    std::vector<std::string> vary;  // NAME=V1,V2,... (columns, then rows)
    std::string output = "sheet.png";
};

struct TradeoffOptions {
    std::string image;  // empty: the grid pattern, generated at `size`
    std::string size;
    std::string format = "RGBA16F";
    int repeat = 5;
    std::vector<std::string> methods;
    std::string backend = "auto";
    std::string output = "tradeoff";
};

void addRenderCommand(CLI::App& app, RenderOptions& options);
void addTradeoffCommand(CLI::App& app, TradeoffOptions& options);
int runTradeoff(const TradeoffOptions& options);
void addSheetCommand(CLI::App& app, SheetOptions& options);
int runSheet(const SheetOptions& options);
void addCheckCommand(CLI::App& app, CommonOptions& options);
struct ViewOptions;
void addViewCommand(CLI::App& app, ViewOptions& options);
int runRender(const RenderOptions& options);
int runCheck(const CommonOptions& options);

// --sandbox and --max-memory (app/safety_options.cpp).
void addSafetyOptions(CLI::App* sub, CommonOptions& options);

// "512x512" -> 512, 512. False on anything else.
bool parseSize(const std::string& text, int& w, int& h);

}  // namespace glimmer
