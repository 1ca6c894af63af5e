#include "process/output_guard.h"

#include <sys/stat.h>

#include <filesystem>
#include <vector>

#include "image/animation.h"
#include "lang/diagnostics.h"
#include "plan/inputs.h"

namespace glimmer {
namespace {

bool sameFile(const struct stat& a, const std::string& path) {
    struct stat b{};
    return !path.empty() && ::stat(path.c_str(), &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

}  // namespace

std::string inputOverwrittenBy(const Plan& plan, const std::string& output) {
    if (output.empty()) return {};
    // As the system resolves the name, and as a writer that tidies the path
    // first would ("x0/../bright.frag" with no folder x0; issue 37).
    for (const std::string& name : {output, std::filesystem::path(output).lexically_normal().string()}) {
        struct stat out{};
        if (::stat(name.c_str(), &out) != 0 || !S_ISREG(out.st_mode)) continue;  // nothing there to lose
        for (const PlanInput& in : inputsOf(plan))
            if (sameFile(out, in.path)) return in.shown;
    }
    return {};
}

std::string notAFileToWrite(const std::string& file) {
    struct stat st{};
    if (::stat(file.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        return S_ISDIR(st.st_mode) ? "a folder" : S_ISFIFO(st.st_mode) ? "a FIFO (writing would wait for a reader)"
                                                                       : "a device or other special file";
    // A name under /dev or /proc is never a picture, even one not there yet.
    const std::string norm = std::filesystem::path(file).lexically_normal().string();
    for (const char* root : {"/dev/", "/proc/", "/sys/"})
        if (norm.rfind(root, 0) == 0) return std::string("under ") + root + ", not a file";
    return {};
}

std::string outputRefusal(const Plan& plan, const std::string& option, const std::string& file, const std::string& what,
                          int frames) {
    const std::string shown = sanitizeForTerminal(file, false);  // a name may hold ESC (issue 37)
    if (const std::string special = notAFileToWrite(file); !special.empty())
        return option + " " + shown + ": that is " + special + "; write the " + what + " to a file";
    // A frame pattern: every name it makes, and the name as written.
    std::vector<std::string> names = {file};
    if (isFramePattern(file))
        for (int i = 0; i < frames; ++i) {
            std::string name, why;
            if (frameFileName(file, i, name, why)) names.push_back(name);
        }
    for (const std::string& name : names) {
        const std::string input = inputOverwrittenBy(plan, name);
        if (!input.empty())
            return option + " " + shown + ": that is '" + sanitizeForTerminal(input, false) +
                   "', which the script reads; write the " + what + " under another name";
    }
    return {};
}

std::string overwritesAnInput(const Plan& plan, const std::string& option, const std::string& file,
                              const std::string& what, int frames) {
    const std::string why = outputRefusal(plan, option, file, what, frames);
    return why.empty() ? why : "glimmer: error: " + why + "\n";
}

}  // namespace glimmer
