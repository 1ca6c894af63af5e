// glimmer batch: a class of scripts in one call, for graders. The work is
// process/batch.h (a pool of workers that each keep a GL context); this file
// reads the list, shards it, and writes the report.
#include <charconv>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fstream>
#include <iostream>

#include <fcntl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/subcommands.h"
#include "app/grade_batch.h"
#include "process/batch.h"
#include "pipeline/console.h"
#include "pipeline/options.h"
#include "plan/limits.h"
#include "util/read_file.h"

namespace glimmer {
namespace {

bool parseShard(const std::string& text, int& shard, int& shards) {
    auto slash = text.find('/');
    if (slash == std::string::npos) return false;
    auto num = [](std::string_view s, int& v) {
        auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        return ec == std::errc() && end == s.data() + s.size();
    };
    return num(std::string_view(text).substr(0, slash), shard) && num(std::string_view(text).substr(slash + 1), shards) &&
           shards >= 1 && shard >= 1 && shard <= shards;
}

}  // namespace

void addBatchCommand(CLI::App& app, BatchOptions& o) {
    CLI::App* sub = app.add_subcommand("batch", "render many scripts to PNGs with workers that keep their GL context, or grade "
                                                "a class against a solution (--reference)");
    sub->add_option("scripts", o.scripts, "the .glib scripts; with --reference, also submission folders, zips, "
                                          "or a class folder holding one folder or zip per student");
    sub->add_option("--list", o.list, "a file naming one script per line (blank lines and # comments skipped)");
    sub->add_option("-o,--output", o.outputDir, "the folder for the PNGs (one per script, named after its path); grading: "
                                                    "for report.html, grades.csv, grades.jsonl and the pictures")
        ->required();
    sub->add_option("--report", o.report, "write one JSON line per script (path, exit, output, diagnostics, ms, health)");
    sub->add_option("--jobs", o.jobs, "worker processes")->capture_default_str()->check(CLI::Range(1, 64));
    sub->add_option("--shard", o.shard, "I/N: render only positions I, I+N, ... of the list (for a job array)");
    sub->add_option("--size", o.size, "output size WxH (default: each script's WindowSize, else 600x600)");
    addBackendOption(sub, o.backend)->capture_default_str();
    sub->add_option("-I,--include", o.includeDirs, "another folder to find shaders and images in");
    sub->add_flag("--strict", o.strict, "a target holding NaN, Inf, negatives or values above 65504 fails the script");
    addSafetyOptions(sub, o);
    sub->add_option("--reference", o.reference, "SOLUTION.glib: grade each submission against it, at several slider "
                                                "settings; writes report.html, grades.csv and grades.jsonl in -o");
    sub->add_option("--vary", o.vary, "NAME=V1,V2,...: the settings compared (default: each slider of the solution "
                                      "at its min and max)");
    sub->add_flag("--no-sandbox", o.noSandbox, "grading: let submissions read files outside their folders "
                                               "(grading sandboxes by default)");
    sub->add_flag("--resume", o.resume, "grading: keep what -o already holds and grade only what is missing");
    sub->add_option("--only", o.only, "grading: regrade only this student (as the report names them; repeatable) "
                                      "into what -o already holds");
    sub->add_option("--overrides", o.overrides, "grading: a CSV student,score,comment whose scores and comments the "
                                                "report, the CSV and the feedback pages take over the computed ones");
    sub->add_option("--pass-ssim", o.thresholds.passSsim, "grading: SSIM a pass needs at every setting")
        ->capture_default_str()->check(CLI::Range(0.0, 1.0));
    sub->add_option("--pass-psnr", o.thresholds.passPsnr, "grading: PSNR (dB) a pass needs at every setting")
        ->capture_default_str()->check(CLI::Range(0.0, 200.0));
    sub->add_option("--look-ssim", o.thresholds.lookSsim, "grading: SSIM at the worst setting below which a submission is "
                                               "wrong rather than worth a look")
        ->capture_default_str()->check(CLI::Range(0.0, 1.0));
    sub->add_option("--look-psnr", o.thresholds.lookPsnr, "grading: PSNR (dB) at every setting below which a submission is "
                                               "wrong rather than worth a look")
        ->capture_default_str()->check(CLI::Range(0.0, 200.0));
}

namespace {

// Two batches writing into one -o folder at once would overwrite each
// other's pictures and both report success (issue 30): the second is
// refused. A POSIX record lock belongs to this process alone (forked
// workers do not inherit it) and goes with it however it ends, so a killed
// batch never leaves the folder locked (only, harmlessly, the lock file).
// A batch that ends normally removes the file.
class OutputFolderLock {
public:
    ~OutputFolderLock() {
        if (fd_ < 0) return;
        ::unlink(path_.c_str());
        ::close(fd_);
    }
    bool lock(const std::string& dir, std::string& why) {
        path_ = (std::filesystem::path(dir) / ".glimmer-batch.lock").string();
        fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
        if (fd_ < 0) {
            why = fmt::format("cannot open {}: {}", path_, std::strerror(errno));
            return false;
        }
        struct flock whole{};
        whole.l_type = F_WRLCK;
        whole.l_whence = SEEK_SET;  // l_start 0, l_len 0: the whole file
        if (::fcntl(fd_, F_SETLK, &whole) != 0) {
            ::close(fd_);
            fd_ = -1;
            why = "another glimmer batch is writing into this folder; wait for it to finish, or give each batch its "
                  "own -o";
            return false;
        }
        return true;
    }

private:
    int fd_ = -1;
    std::string path_;
};

}  // namespace

int runBatch(const BatchOptions& o) {
    std::vector<std::string> scripts = o.scripts;
    if (!o.list.empty()) {
        std::string text, why;
        if (!readRegularFile(o.list, kMaxScriptBytes, text, why)) {
            std::cerr << fmt::format("glimmer: error: --list {}: cannot read it: it {}\n", o.list, why);
            return kExitUsage;
        }
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) {
            while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
            if (!line.empty() && line[0] != '#') scripts.push_back(line);
        }
    }
    const bool grading = !o.reference.empty();
    if (grading && (!o.report.empty() || o.strict)) {
        std::cerr << "glimmer: error: batch --reference writes its own grades.jsonl and report.html in -o; --report "
                     "and --strict are for plain batch\n";
        return kExitUsage;
    }
    if (!grading) {
        std::error_code ec;
        for (const auto& sc : scripts)
            if (std::filesystem::is_directory(sc, ec) || (sc.size() > 4 && sc.compare(sc.size() - 4, 4, ".zip") == 0)) {
                std::cerr << fmt::format("glimmer: error: batch: {} is a folder or zip: submissions are graded; "
                                         "give --reference SOLUTION.glib\n", sc);
                return kExitUsage;
            }
        if (!o.vary.empty() || o.noSandbox || o.resume) {
            std::cerr << "glimmer: error: batch: --vary, --no-sandbox and --resume are for grading; give --reference "
                         "SOLUTION.glib\n";
            return kExitUsage;
        }
    }
    if (scripts.empty()) {
        std::cerr << "glimmer: error: batch: no scripts (name them, or give --list FILE)\n";
        return kExitUsage;
    }
    int shard = 1, shards = 1;
    if (!o.shard.empty() && !parseShard(o.shard, shard, shards)) {
        std::cerr << fmt::format("glimmer: error: --shard '{}' is not I/N with 1 <= I <= N\n", o.shard);
        return kExitUsage;
    }
    BatchSettings settings;
    if (!o.size.empty() && !parseSize(o.size, settings.width, settings.height)) {
        std::cerr << fmt::format("glimmer: error: --size '{}' is not WIDTHxHEIGHT (1 to 16384 each)\n", o.size);
        return kExitUsage;
    }
    std::error_code ec;
    std::filesystem::create_directories(o.outputDir, ec);
    if (!std::filesystem::is_directory(o.outputDir)) {
        std::cerr << fmt::format("glimmer: error: -o {}: cannot make this folder\n", o.outputDir);
        return kExitUsage;
    }
    OutputFolderLock folderLock;
    if (std::string why; !folderLock.lock(o.outputDir, why)) {
        std::cerr << fmt::format("glimmer: error: -o {}: {}\n", o.outputDir, why);
        return kExitUsage;
    }
    settings.backend = o.backend;
    settings.includeDirs = o.includeDirs;
    settings.maxMemoryMiB = o.maxMemoryMiB;
    settings.timeoutSeconds = o.timeoutSeconds;
    settings.strict = o.strict;
    settings.jobs = o.jobs;
    if (grading) {
        // Untrusted work: sandboxed unless the teacher says otherwise, and then said once.
        settings.sandbox = !o.noSandbox;
        if (o.noSandbox)
            std::cerr << "glimmer: warning: --no-sandbox: submissions may read any file this user can read\n";
        return runGradeBatch(o, scripts, shard, shards, settings);
    }
    std::vector<std::string> names = batchOutputNames(scripts);  // from the whole list: the same on every shard
    std::vector<BatchJob> jobs;
    for (size_t i = 0; i < scripts.size(); ++i)
        if (inShard(i, shard, shards))
            jobs.push_back({scripts[i], (std::filesystem::path(o.outputDir) / names[i]).string(), {}, {}, {}});
    settings.sandbox = o.sandbox;
    Progress progress;
    auto results = runBatch(jobs, settings, [&](size_t done, size_t total) {
        progress.update(fmt::format("batch: {}/{} scripts", done, total));
    });
    progress.finish();
    int failed = 0;
    std::ofstream report;
    if (!o.report.empty()) {
        report.open(o.report);
        if (!report) {
            std::cerr << fmt::format("glimmer: error: --report {}: cannot write it\n", o.report);
            return kExitUsage;
        }
    }
    for (const auto& r : results) {
        failed += r.exitCode != 0;
        if (report.is_open()) report << r.json << "\n";
    }
    reportWrote(fmt::format("{} of {} scripts to {}{}{}", jobs.size() - size_t(failed), jobs.size(), o.outputDir,
                            failed ? fmt::format(" ({} failed)", failed) : "",
                            o.report.empty() ? "" : ", report " + o.report));
    return failed ? kExitScriptError : kExitOk;
}

}  // namespace glimmer
