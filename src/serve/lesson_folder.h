// The lesson `glimmer serve` hands out: LESSON_DIR's files read once at
// start, bounded as the page bounds a lesson (glimmer-lesson.js: 2000 files,
// 256 MiB; here 64 MiB, the packer's limit), and the JSON the page loads
// (its "lesson is data" format: {"name", "files": {path: base64}, "scripts"}).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "serve/class_store.h"

namespace glimmer {

struct LessonFolder {
    std::string name;                          // the folder's own name
    std::map<std::string, std::string> files;  // relative path ("shaders/bloom.frag") -> bytes
    std::vector<std::string> scripts;          // the .glib files, sorted

    // True when `path` is one of the lesson's text files: the only files a
    // student's save may change (a save names no new file, so a hostile
    // page can neither make names nor fill the disk with them).
    bool editable(const std::string& path) const;
};

// Reads `dir` (hidden entries skipped, symlinks not followed out of it);
// false with `error` when it cannot, or holds more than the bounds.
bool readLessonFolder(const std::string& dir, LessonFolder& out, std::string& error);

// The page's lesson JSON: the lesson's files with `overlay`'s texts in
// place of theirs.
// `name` is the lesson's name as the page keys its kept edits by.
std::string lessonJson(const LessonFolder& lesson, const FileTexts& overlay, const std::string& name);

// The whole of one student's folder as a grader reads it: the lesson with
// `overlay`, written under `dir` (made fresh).
bool writeStudentFolder(const std::string& dir, const LessonFolder& lesson, const FileTexts& overlay,
                        std::string& error);

}  // namespace glimmer
