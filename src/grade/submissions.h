// A class as it arrives: a folder of folders (or zips), one per student.
// Which entries are submissions, and which script in each is the one to
// grade. Reads folders only; no GL, nothing unpacked here.
#pragma once
#include <string>
#include <vector>

namespace glimmer {

struct Submission {
    std::string name;    // the student: the folder's name, or the zip's without ".zip"
    std::string path;    // the folder, the zip, or a lone .glib
    bool zip = false;
};

// The submissions in `inputs`, in name order: a .zip is one; a folder with a
// .glib directly inside is one; any other folder is a class, and each folder
// and zip directly inside it is one; a .glib file is one on its own. Hidden
// entries and __MACOSX are skipped. `errors` gets a line for each input that
// is none of these.
// `warnings` (when given) gets a line for each hidden folder or zip of a
// class that is skipped: a student's ".late" is said, not lost (issue 37).
std::vector<Submission> listSubmissions(const std::vector<std::string>& inputs, std::vector<std::string>& errors,
                                        std::vector<std::string>* warnings = nullptr);

// The one .glib in a submission folder, searched up to three folders deep
// (hidden folders and __MACOSX skipped; at most 10000 entries looked at).
// "" with `error` set ("class/bob: error: no .glib script in this
// submission", "... 2 .glib scripts (a.glib, sub/b.glib); keep one") otherwise.
// A path ending in .glib is its own script. With several, the one whose file
// name is `preferred` (grading: the solution's script's name), when exactly
// one is, and `note` says so ("2 .glib scripts (bloom.glib,
// old/bloom_old.glib): graded bloom.glib, named like the solution's"; issue
// 37: a student who kept the old version beside the new one).
std::string findScript(const std::string& folder, std::string& error, const std::string& preferred = "",
                       std::string* note = nullptr);

}  // namespace glimmer
