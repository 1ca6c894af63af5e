#include "process/output_guard.h"

#include <sys/stat.h>

#include "plan/inputs.h"

namespace glimmer {
namespace {

bool sameFile(const struct stat& a, const std::string& path) {
    struct stat b{};
    return !path.empty() && ::stat(path.c_str(), &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

}  // namespace

std::string inputOverwrittenBy(const Plan& plan, const std::string& output) {
    struct stat out{};
    if (output.empty() || ::stat(output.c_str(), &out) != 0 || !S_ISREG(out.st_mode)) return {};  // nothing there to lose
    for (const PlanInput& in : inputsOf(plan))
        if (sameFile(out, in.path)) return in.shown;
    return {};
}

std::string overwritesAnInput(const Plan& plan, const std::string& option, const std::string& file,
                              const std::string& what) {
    const std::string input = inputOverwrittenBy(plan, file);
    return input.empty() ? std::string()
                         : "glimmer: error: " + option + " " + file + ": that is '" + input +
                               "', which the script reads; write the " + what + " under another name\n";
}

}  // namespace glimmer
