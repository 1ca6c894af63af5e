#include "grade/submissions.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

namespace glimmer {
namespace fs = std::filesystem;
namespace {

bool hasExtension(const fs::path& p, const std::string& ext) {
    std::string e = p.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return e == ext;
}

bool skipped(const fs::path& p) {
    const std::string n = p.filename().string();
    return n.empty() || n[0] == '.' || n == "__MACOSX";
}

bool holdsScript(const fs::path& dir) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (!skipped(e.path()) && e.is_regular_file(ec) && hasExtension(e.path(), ".glib")) return true;
    return false;
}

}  // namespace

std::vector<Submission> listSubmissions(const std::vector<std::string>& inputs, std::vector<std::string>& errors,
                                        std::vector<std::string>* warnings) {
    std::vector<Submission> out;
    for (const auto& input : inputs) {
        fs::path p(input);
        std::error_code ec;
        if (fs::is_regular_file(p, ec) && hasExtension(p, ".zip")) {
            out.push_back({p.stem().string(), input, true});
        } else if (fs::is_regular_file(p, ec) && hasExtension(p, ".glib")) {
            out.push_back({p.parent_path().filename().string().empty() ? p.stem().string()
                                                                       : p.parent_path().filename().string(),
                           input, false});
        } else if (fs::is_directory(p, ec)) {
            if (holdsScript(p)) {
                fs::path n = fs::absolute(p).lexically_normal();
                if (n.filename().empty()) n = n.parent_path();
                out.push_back({n.filename().string(), input, false});
                continue;
            }
            std::vector<Submission> inside;
            for (const auto& e : fs::directory_iterator(p, ec)) {
                if (skipped(e.path())) {
                    const bool looksHandedIn = e.is_directory(ec) || (e.is_regular_file(ec) && hasExtension(e.path(), ".zip"));
                    if (warnings && looksHandedIn && e.path().filename() != "__MACOSX")
                        warnings->push_back(fmt::format("glimmer: warning: {}: skipped, its name starts with '.' (hidden); "
                                                        "rename it to grade it", e.path().string()));
                    continue;
                }
                if (e.is_directory(ec)) inside.push_back({e.path().filename().string(), e.path().string(), false});
                else if (e.is_regular_file(ec) && hasExtension(e.path(), ".zip"))
                    inside.push_back({e.path().stem().string(), e.path().string(), true});
            }
            if (inside.empty()) errors.push_back(fmt::format("{}: error: no submission folders, zips or .glib scripts in this folder", input));
            out.insert(out.end(), inside.begin(), inside.end());
        } else {
            errors.push_back(fmt::format("{}: error: not a folder, a .zip or a .glib script", input));
        }
    }
    std::stable_sort(out.begin(), out.end(), [](const Submission& a, const Submission& b) {
        return a.name != b.name ? a.name < b.name : a.path < b.path;
    });
    return out;
}

constexpr int kScriptSearchDepth = 8;

std::string findScript(const std::string& folder, std::string& error, const std::string& preferred, std::string* note) {
    error.clear();
    fs::path root(folder);
    std::error_code ec;
    if (fs::is_regular_file(root, ec) && hasExtension(root, ".glib")) return folder;
    if (!fs::is_directory(root, ec)) {
        error = fmt::format("{}: error: not a folder", folder);
        return "";
    }
    std::vector<std::string> found, others;
    int looked = 0;
    auto it = fs::recursive_directory_iterator(root, fs::directory_options::skip_permission_denied, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (++looked > 10000) {
            error = fmt::format("{}: error: more than 10000 files; not searched further", folder);
            return "";
        }
        const fs::path& p = it->path();
        if (skipped(p)) {
            if (it->is_directory(ec)) it.disable_recursion_pending();
            continue;
        }
        // Eight levels (0 to 7): a zip of a zip's folder of a course folder
        // still has its script found (issue 29: three levels down was "no
        // .glib script"); the file count above bounds the walk.
        if (it->is_directory(ec) && it.depth() >= kScriptSearchDepth - 1) it.disable_recursion_pending();
        if (it->is_regular_file(ec) && !it->is_symlink(ec)) {
            if (hasExtension(p, ".glib")) found.push_back(p.lexically_relative(root).string());
            else if (others.size() < 6) others.push_back(p.lexically_relative(root).string());
        }
    }
    std::sort(found.begin(), found.end());
    if (found.size() == 1) return (root / found[0]).string();
    if (found.empty()) {
        // What was there instead: a script saved as .txt, a folder of shaders only.
        std::sort(others.begin(), others.end());
        std::string names;
        for (size_t k = 0; k < others.size() && k < 5; ++k) names += (names.empty() ? "" : ", ") + others[k];
        error = others.empty() ? fmt::format("{}: error: no .glib script in this submission (it holds no file)", folder)
                               : fmt::format("{}: error: no .glib script in this submission; it holds {}{}", folder, names,
                                             others.size() > 5 ? ", ..." : "");
    } else {
        std::string names;
        for (const auto& f : found) names += (names.empty() ? "" : ", ") + f;
        std::vector<std::string> named;
        for (const auto& f : found)
            if (!preferred.empty() && fs::path(f).filename() == preferred) named.push_back(f);
        if (named.size() == 1) {
            if (note) *note = fmt::format("{} .glib scripts ({}): graded {}, named like the solution's", found.size(), names,
                                          named[0]);
            return (root / named[0]).string();
        }
        error = fmt::format("{}: error: {} .glib scripts ({}); keep one", folder, found.size(), names);
    }
    return "";
}

}  // namespace glimmer
