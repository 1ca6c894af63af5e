#include "serve/lesson_folder.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>

#include "grade/grading.h"
#include "util/json.h"
#include "util/read_file.h"
#include "util/write_file.h"

namespace fs = std::filesystem;

namespace glimmer {
namespace {

constexpr std::size_t kMaxLessonFiles = 2000;
constexpr std::size_t kMaxLessonBytes = std::size_t(64) << 20;  // tools/web_lesson.py's LIMIT

bool isTextPath(const std::string& path) {
    static const char* kText[] = {".glib", ".vert", ".frag", ".geom", ".tesc", ".tese", ".comp", ".glsl", ".txt",
                                  ".vs", ".fs", ".gs", ".inc"};
    return std::any_of(std::begin(kText), std::end(kText),
                       [&](const char* e) { return path.size() > std::strlen(e) && path.ends_with(e); });
}

}  // namespace

bool LessonFolder::editable(const std::string& path) const { return files.count(path) && isTextPath(path); }

bool readLessonFolder(const std::string& dir, LessonFolder& out, std::string& error) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        error = fmt::format("{}: not a folder", dir);
        return false;
    }
    out.name = fs::path(dir).lexically_normal().filename().string();
    if (out.name.empty()) out.name = fs::path(dir).lexically_normal().parent_path().filename().string();
    std::size_t bytes = 0;
    fs::recursive_directory_iterator it(dir, fs::directory_options::none, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        const std::string leaf = it->path().filename().string();
        if (leaf.starts_with(".")) {  // hidden: .git, editors' files
            if (it->is_directory(ec)) it.disable_recursion_pending();
            continue;
        }
        if (it->is_symlink(ec) || !it->is_regular_file(ec)) continue;
        const std::string rel = fs::relative(it->path(), dir, ec).generic_string();
        if (out.files.size() >= kMaxLessonFiles) {
            error = fmt::format("{}: more than {} files: not a lesson", dir, kMaxLessonFiles);
            return false;
        }
        std::string text, why;
        if (!readRegularFile(it->path().string(), kMaxLessonBytes, text, why)) {
            error = fmt::format("{}: {}", it->path().string(), why);
            return false;
        }
        bytes += text.size();
        if (bytes > kMaxLessonBytes) {
            error = fmt::format("{}: more than {} MiB of files: not a lesson", dir, kMaxLessonBytes >> 20);
            return false;
        }
        if (rel.ends_with(".glib")) out.scripts.push_back(rel);
        out.files[rel] = std::move(text);
    }
    if (ec) {
        error = fmt::format("{}: cannot read it: {}", dir, ec.message());
        return false;
    }
    if (out.scripts.empty()) {
        error = fmt::format("{}: no .glib script in it: not a lesson", dir);
        return false;
    }
    std::sort(out.scripts.begin(), out.scripts.end());
    return true;
}

std::string lessonJson(const LessonFolder& lesson, const FileTexts& overlay, const std::string& name) {
    Json files = Json::object();
    for (const auto& [path, bytes] : lesson.files) {
        const auto mine = overlay.find(path);
        const std::string& b = mine != overlay.end() ? mine->second : bytes;
        files[path] = base64(std::vector<std::uint8_t>(b.begin(), b.end()));
    }
    Json j = {{"name", name}, {"files", files}, {"scripts", lesson.scripts}};
    return j.dump();
}

bool writeStudentFolder(const std::string& dir, const LessonFolder& lesson, const FileTexts& overlay,
                        std::string& error) {
    std::error_code ec;
    fs::remove_all(dir, ec);
    for (const auto& [path, bytes] : lesson.files) {
        const auto mine = overlay.find(path);
        const std::string& b = mine != overlay.end() ? mine->second : bytes;
        const fs::path target = fs::path(dir) / path;
        fs::create_directories(target.parent_path(), ec);
        if (ec || !writeBytesReplacing(target.string(), b.data(), b.size(), error)) {
            if (error.empty()) error = fmt::format("cannot make {}: {}", target.parent_path().string(), ec.message());
            return false;
        }
    }
    return true;
}

}  // namespace glimmer
