// glimmer batch --reference: a class graded against the teacher's solution.
// The submissions are found and unpacked (grade/), drawn by the batch
// workers at every setting (process/batch.h), compared here as each result
// arrives, and written at once: a record line (what --resume and
// batch-merge read back), then the page and the CSV, rewritten at most
// every two seconds and at the end (app/grade_report_files.cpp).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "lang/diagnostics.h"
#include "app/grade_batch.h"
#include "process/batch.h"
#include "pipeline/console.h"
#include "pipeline/load_script.h"
#include "grade/grade_merge.h"
#include "grade/grade_report.h"
#include "grade/grading.h"
#include "grade/safe_unzip.h"
#include "grade/submissions.h"
#include "plan/inputs.h"
#include "plan/limits.h"
#include "util/read_file.h"

namespace glimmer {
namespace fs = std::filesystem;

namespace {

std::string thresholdsText(const Thresholds& t) {
    return fmt::format("pass: SSIM ≥ {:g} and PSNR ≥ {:g} dB at every setting; look: SSIM ≥ {:g} at the worst "
                       "and PSNR ≥ {:g} dB at every setting; score: 100 × the worst SSIM",
                       t.passSsim, t.passPsnr, t.lookSsim, t.lookPsnr);
}

std::vector<Slider> slidersOf(const Plan& plan) {
    std::vector<Slider> out;
    std::set<std::string> seen;
    for (const auto& program : plan.programs)
        for (const auto& u : program.uniforms)
            if (u.form == UniformSetting::Form::Range && !u.values.empty() && seen.insert(u.name).second)
                out.push_back({u.name, u.min, u.values[0], u.max});
    return out;
}

std::string failureNote(const std::string& diagnostics) {
    if (diagnostics.find("stopped after") != std::string::npos) return "timed out";
    if (diagnostics.find("crashed") != std::string::npos) return "the renderer crashed";
    if (diagnostics.find("sandbox") != std::string::npos) return "reads files outside its folder";
    return "does not render";
}

// The submission's sliders against the solution's ("NAME MIN DEFAULT MAX"
// each, process/batch.h): a range or a default the student changed is said
// in the row, whatever the pictures (issue 29: `<0 1 2>` against `<0 1 4>`
// went unmentioned). Sliders the submission lacks are judge()'s.
std::string sliderDifferences(const std::vector<std::string>& student, const std::vector<std::string>& solution) {
    std::map<std::string, std::string> theirs;
    for (const auto& line : student) theirs[line.substr(0, line.find(' '))] = line;
    std::string out;
    for (const auto& line : solution) {
        const std::string name = line.substr(0, line.find(' '));
        auto it = theirs.find(name);
        if (it == theirs.end() || it->second == line) continue;
        auto numbers = [](const std::string& l) {  // MIN DEFAULT MAX, as the worker wrote them
            std::istringstream in(l.substr(l.find(' ') + 1));
            std::string a, b, c;
            in >> a >> b >> c;
            return std::array<std::string, 3>{a, b, c};
        };
        auto s = numbers(it->second), r = numbers(line);
        if (s[0] != r[0] || s[2] != r[2])
            out += fmt::format("{}{}: range <{} {}> (the solution's <{} {}>)", out.empty() ? "" : "; ", name, s[0], s[2],
                               r[0], r[2]);
        if (s[1] != r[1])
            out += fmt::format("{}{}: default {} (the solution's {})", out.empty() ? "" : "; ", name, s[1], r[1]);
    }
    return out;
}

// The time each submission may take when the teacher gives no --timeout:
// per setting the larger of kFloorSeconds and kTimesSolution times the
// solution's own time at that setting, measured in this run on this machine
// (so a loaded machine slows both alike), and as much again for preparing
// (issue 29: a correct blur took 11.8 s on a loaded machine).
constexpr double kFloorSeconds = 10, kTimesSolution = 20;
double gradingTimeLimit(const BatchResult& solution, std::string& how, std::vector<double>& deadlines) {
    const double prepare = std::max(kFloorSeconds, kTimesSolution * solution.prepareMs / 1000);
    double total = prepare;
    std::string each;
    deadlines.clear();
    for (double ms : solution.settingMs) {
        const double limit = std::max(kFloorSeconds, kTimesSolution * ms / 1000);
        total += limit;
        deadlines.push_back(std::ceil(total));  // setting k done by then, counted from the job's start
        each += fmt::format("{}{:.0f}", each.empty() ? "" : ", ", limit);
    }
    // Whole seconds, up: the limit said here is the one a stop names (the
    // generated class's endless loop, on a loaded machine, was "stopped
    // after 80.2667 s (--timeout 80.2667)" where this line said 80 s).
    total = std::ceil(total);
    how = fmt::format("each submission may take {:.0f} s: per setting the larger of {:g} s and {:g} x the "
                      "solution's own time there ({} s), and the same for preparing ({:.0f} s), each setting "
                      "stopped once it runs past its share and the earlier ones' (not one limit for the whole); "
                      "--timeout sets another", total, kFloorSeconds, kTimesSolution, each, prepare);
    return total;
}

// FNV-1a over the solution's script and every file it reads, each with its
// name: what --resume compares (a file that cannot be read counts as its name).
std::string solutionContent(const std::string& script, const Plan& plan) {
    std::uint64_t h = 1469598103934665603ull;
    auto add = [&](const std::string& bytes) {
        for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
        h = (h ^ 0xff) * 1099511628211ull;  // a separator, so "ab"+"c" is not "a"+"bc"
    };
    std::vector<std::string> files = {script};
    for (const PlanInput& in : inputsOf(plan)) files.push_back(in.path);
    for (const std::string& f : files) {
        std::string text, why;
        add(fs::path(f).filename().string());
        if (readRegularFile(f, std::size_t(1) << 30, text, why)) add(text);
    }
    return fmt::format("{:016x}", h);
}

// Unique file stems for the students' pictures ("alice", "alice-2", ...).
// A stem is at most kMaxStemBytes (cut where a UTF-8 character starts): a
// picture is STEM-k.png and a page STEM.html, and most file systems take
// 255 bytes a name (issue 37: a correct submission in a folder of 250
// characters was "error, cannot write ... File name too long").
constexpr size_t kMaxStemBytes = 120;
std::vector<std::string> pictureStems(const std::vector<Submission>& subs) {
    std::vector<std::string> names;
    for (const auto& s : subs) {
        std::string name = s.name;
        // A folder named with spaces only was "script" (issue 37): said as what it is.
        if (!name.empty() && name.find_first_not_of(' ') == std::string::npos)
            name = fmt::format("({} space{})", name.size(), name.size() == 1 ? "" : "s");
        if (name.size() > kMaxStemBytes) {
            size_t cut = kMaxStemBytes;
            while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;
            name.resize(cut);
        }
        names.push_back(name + ".glib");
    }
    auto out = batchOutputNames(names, true);
    for (auto& n : out) n.resize(n.size() - 4);
    return out;
}

// A student who handed in twice (a folder and a zip of it): both are
// graded, and said, never silently as NAME-2 (issue 29): here, and in each
// of their rows, where the teacher reads (the generated class of
// tools/grading-class.py: lena and lena-2 were two plain passes). Returns
// submission path -> the note its row takes.
std::map<std::string, std::string> handedInMoreThanOnce(const std::vector<Submission>& subs) {
    std::map<std::string, std::string> handedInTwice;
    for (size_t i = 0, j = 0; i < subs.size(); i = j) {
        std::string files, paths;
        for (j = i; j < subs.size() && subs[j].name == subs[i].name; ++j) {
            fs::path p = fs::path(subs[j].path).lexically_normal();
            if (p.filename().empty()) p = p.parent_path();  // "class/lena/"
            files += (files.empty() ? "" : ", ") + p.filename().string();
            paths += (paths.empty() ? "" : ", ") + subs[j].path;
        }
        if (j - i < 2) continue;
        for (size_t k = i; k < j; ++k)
            handedInTwice[subs[k].path] = fmt::format("handed in more than once ({}); each is a row of its own", files);
        std::cerr << fmt::format("glimmer: warning: {} handed in more than once ({}); each is graded, as a row of its "
                                 "own\n", sanitizeForTerminal(subs[i].name, false), sanitizeForTerminal(paths, false));
    }
    return handedInTwice;
}

// Whether the grading in `out` (its grading.txt, if any) was made with the
// same solution, settings, thresholds and sandbox as `header`; says why not.
bool sameGradingAsBefore(const fs::path& out, const ReportHeader& header, const std::string& outputDir) {
    if (!fs::exists(out / "grading.txt")) return true;
    std::string text, why;
    ReportHeader before;
    std::vector<std::string> beforeStudents;
    if (!readRegularFile((out / "grading.txt").string(), 1 << 24, text, why) ||
        !parseRunHeader(text, before, beforeStudents, why)) {
        std::cerr << fmt::format("glimmer: error: --resume: {}: {}\n", (out / "grading.txt").string(), why);
        return false;
    }
    if (before.solution != header.solution || before.settings != header.settings ||
        before.thresholds != header.thresholds || before.sandbox != header.sandbox ||
        before.solutionContent != header.solutionContent) {
        std::cerr << fmt::format("glimmer: error: --resume: {} was graded with another solution{}, settings, "
                                 "thresholds or sandbox; grade it again without --resume, or into another -o\n",
                                 outputDir,
                                 before.solution == header.solution && before.solutionContent != header.solutionContent
                                     ? " (the same name, other content)"
                                     : "");
        return false;
    }
    return true;
}

// A submission's row from what its worker drew: an error that says where it
// stopped, or the verdict of its pictures against the solution's at each
// setting (the worst setting's pictures, the student's and the solution's
// in `solutionOutputs`, linked). Student, submission and script are the
// caller's to fill.
GradeRow rowOf(const BatchResult& result, const std::vector<Setting>& settings, const std::vector<Image>& solutionPictures,
               const std::vector<std::string>& solutionOutputs, const std::vector<std::string>& solutionSliders,
               const Thresholds& thresholds, const fs::path& out) {
    GradeRow r;
    r.diagnostics = result.diagnostics;
    r.seconds = result.ms / 1000.0;
    if (result.written.size() != settings.size()) {
        r.verdict = "error";
        r.notes = failureNote(result.diagnostics);
        if (r.notes == "timed out" || r.notes == "the renderer crashed") {
            // Where it stopped, as the worker last said (process/batch_worker.h).
            const int k = result.stoppedAt;
            r.notes += k == BatchResult::kStoppedPreparing ? std::string(" while loading and compiling")
                       : k >= 0 && size_t(k) < settings.size()
                           ? fmt::format(" at setting {} ({} of {})", settingLabel(settings[size_t(k)]), k + 1,
                                         settings.size())
                           : std::string();
        }
        return r;
    }
    std::vector<Comparison> comparisons;
    for (size_t k = 0; k < settings.size(); ++k) {
        Image student;
        std::string why;
        loadImage(result.written[k], student, why);
        comparisons.push_back(comparePictures(student, solutionPictures[k]));
    }
    size_t worst = 0;
    Verdict v = judge(comparisons, result.missing, thresholds, worst);
    r.verdict = v.kind;
    r.score = v.score;
    r.notes = v.notes;
    r.ssim = comparisons[worst].ssim;
    r.psnr = comparisons[worst].psnr;
    r.worstSetting = settingLabel(settings[worst]);
    for (size_t k = 0; k < settings.size(); ++k)
        r.bySetting += fmt::format("{}{} {:.3f}", k ? " · " : "", settingLabel(settings[k]), comparisons[k].ssim);
    if (std::string changed = sliderDifferences(result.sliders, solutionSliders); !changed.empty())
        r.notes += (r.notes.empty() ? "" : "; ") + changed;
    std::error_code ec;
    r.picture = fs::relative(result.written[worst], out, ec).string();
    r.solution = fs::relative(solutionOutputs[worst], out, ec).string();
    return r;
}

}  // namespace

bool loadOverrides(const std::string& file, std::map<std::string, Override>& out) {
    out.clear();
    if (file.empty()) return true;
    std::string text, why;
    if (!readRegularFile(file, 16 << 20, text, why)) {
        std::cerr << fmt::format("glimmer: error: --overrides {}: cannot read it: it {}\n", sanitizeForTerminal(file, false), why);
        return false;
    }
    if (!parseOverrides(text, file, out, why)) {
        std::cerr << sanitizeForTerminal(why, false) << "\n";
        return false;
    }
    return true;
}

void warnUnusedOverrides(std::vector<GradeRow> rows, const std::map<std::string, Override>& overrides) {
    // The first few by name, the rest counted (issue 37: 99,999 unknown
    // names printed 9.3 MB of warnings).
    constexpr size_t kNamed = 5;
    const std::vector<std::string> unknown = applyOverrides(rows, overrides);
    for (size_t k = 0; k < unknown.size() && k < kNamed; ++k)
        std::cerr << fmt::format("glimmer: warning: --overrides names '{}', whom no row has (as the report names "
                                 "students)\n", sanitizeForTerminal(unknown[k], false));
    if (unknown.size() > kNamed)
        std::cerr << fmt::format("glimmer: warning: --overrides names {} more whom no row has\n", unknown.size() - kNamed);
}

int runGradeBatch(const BatchOptions& o, const std::vector<std::string>& inputs, int shard, int shards,
                  const BatchSettings& base) {
    std::map<std::string, Override> overrides;
    if (!loadOverrides(o.overrides, overrides)) return kExitUsage;
    // --only regrades into a graded folder: as --resume, with those students' records dropped.
    const bool resume = o.resume || !o.only.empty();
    const std::set<std::string> only(o.only.begin(), o.only.end());
    if (!o.only.empty() && !fs::exists(fs::path(o.outputDir) / "grades.jsonl")) {
        std::cerr << fmt::format("glimmer: error: --only: {} holds no grading to regrade into (grades.jsonl); grade "
                                 "the class first\n", o.outputDir);
        return kExitUsage;
    }
    std::vector<std::string> errors;
    std::vector<std::string> skippedHidden;
    std::vector<Submission> subs = listSubmissions(inputs, errors, &skippedHidden);
    for (const auto& e : errors) std::cerr << e << "\n";
    for (const auto& w : skippedHidden) std::cerr << sanitizeForTerminal(w, false) << "\n";
    {  // -o inside the class folder is not a student
        std::error_code ec;
        std::erase_if(subs, [&](const Submission& sub) { return fs::equivalent(sub.path, o.outputDir, ec); });
    }
    const std::map<std::string, std::string> handedInTwice = handedInMoreThanOnce(subs);
    if (subs.empty()) {
        std::cerr << "glimmer: error: batch: no submissions to grade\n";
        return kExitUsage;
    }
    // The solution, planned without GL: its sliders are the settings compared.
    Diagnostics diags;
    LoadedScript solution;
    PlanOptions planOptions;
    planOptions.includeDirs = o.includeDirs;
    if (!loadScript(o.reference, planOptions, diags, solution) || diags.errorCount() > 0) {
        printDiagnostics(diags, solution.sources, std::cerr);
        std::cerr << fmt::format("glimmer: error: --reference {}: the solution has errors\n", o.reference);
        return kExitUsage;
    }
    std::vector<Setting> settings;
    if (!o.vary.empty()) {
        std::string why;
        if (!settingsFromVary(o.vary, settings, why)) {
            std::cerr << "glimmer: error: " << why << "\n";
            return kExitUsage;
        }
    } else {
        settings = settingsFromSliders(slidersOf(solution.plan));
    }
    const Thresholds& thresholds = o.thresholds;
    const fs::path out(o.outputDir), pictures = out / "pictures", unpacked = out / "unpacked";
    std::error_code ec;
    fs::create_directories(pictures, ec);

    // Every student of the whole class, named uniquely, in the same order on every shard.
    std::vector<std::string> stems = pictureStems(subs);
    ReportHeader header;
    header.solution = o.reference;
    for (const auto& s : settings) header.settings.push_back(settingLabel(s));
    header.thresholds = thresholdsText(thresholds);
    header.sandbox = !o.noSandbox;
    header.solutionContent = solutionContent(o.reference, solution.plan);
    std::vector<std::string> mine;
    for (size_t i = 0; i < subs.size(); ++i)
        if (inShard(i, shard, shards)) mine.push_back(stems[i]);
    for (const auto& name : only)
        if (std::find(stems.begin(), stems.end(), name) == stems.end()) {
            std::cerr << fmt::format("glimmer: error: --only {}: no such student in this class (as the report names "
                                     "them)\n", sanitizeForTerminal(name, false));
            return kExitUsage;
        }
    header.expected = int(mine.size());
    // Resuming is only sound when the earlier run graded the same way.
    if (resume && !sameGradingAsBefore(out, header, o.outputDir)) return kExitUsage;
    writeWhole(out / "grading.txt", runHeaderText(header, stems));

    // What an earlier run of this folder already graded.
    std::vector<GradeRow> rows;
    std::set<std::string> feedbackKept;  // of those, the students whose feedback page stays
    const fs::path records = out / "grades.jsonl";
    if (resume && fs::exists(records)) {
        std::string text, why;
        if (!readRegularFile(records.string(), std::uint64_t(1) << 30, text, why)) {
            std::cerr << fmt::format("glimmer: error: --resume: {}: cannot read it: it {}\n", records.string(), why);
            return kExitUsage;
        }
        if (!parseRecords(text, records.string(), rows, why)) {
            std::cerr << why << "\n";
            return kExitUsage;
        }
        std::set<std::string> wanted(mine.begin(), mine.end());
        std::erase_if(rows, [&](const GradeRow& r) { return !wanted.count(r.student) || only.count(r.student); });
        for (const GradeRow& r : rows)
            if (feedbackStillRight(out, r, overrides)) feedbackKept.insert(r.student);
    }
    std::set<std::string> graded;
    for (const auto& r : rows) graded.insert(r.student);
    {  // the records file holds exactly what is kept, whole lines only
        std::string kept;
        for (const auto& r : rows) kept += gradeRecord(r) + "\n";
        writeWhole(records, kept);
    }
    std::ofstream recordOut(records, std::ios::app);

    // The solution first, at every setting.
    BatchSettings solutionSettings = base;
    solutionSettings.sandbox = false;  // the teacher's own files
    solutionSettings.jobs = 1;
    BatchJob solutionJob{o.reference, "", settings, {}, {}};
    for (size_t k = 0; k < settings.size(); ++k)
        solutionJob.outputs.push_back((pictures / fmt::format("solution-{}.png", k)).string());
    auto solved = runBatch({solutionJob}, solutionSettings, {});
    if (solved[0].exitCode != 0) {
        std::cerr << solved[0].diagnostics;
        std::cerr << fmt::format("glimmer: error: --reference {}: the solution does not render\n", o.reference);
        return kExitUsage;
    }
    if (!solved[0].missing.empty()) {  // a --vary name the solution does not have: every student would "lack" it
        std::cerr << fmt::format("glimmer: error: --vary {}: the solution {} has no uniform of that name\n",
                                 solved[0].missing[0], o.reference);
        return kExitUsage;
    }
    BatchSettings studentSettings = base;
    if (studentSettings.timeoutSeconds <= 0) {  // on by default when grading
        std::string how;
        studentSettings.timeoutSeconds = gradingTimeLimit(solved[0], how, studentSettings.settingDeadlines);
        studentSettings.timeoutSaid = "the time limit of grading; --timeout sets another";
        std::cerr << "glimmer: grading: " << how << "\n";
    }
    std::vector<Image> solutionPictures(settings.size());
    for (size_t k = 0; k < settings.size(); ++k) {
        std::string why;
        loadImage(solutionJob.outputs[k], solutionPictures[k], why);
    }

    std::map<std::string, std::string> rowHtml;
    auto lastWrite = std::chrono::steady_clock::now();
    std::map<std::string, std::string> scriptChosen;  // student -> which of several scripts was graded, and why
    auto keep = [&](GradeRow r) {
        // Nothing to compare: still show what was asked for (the solution at its defaults).
        if (r.solution.empty()) r.solution = fs::relative(solutionJob.outputs[0], out, ec).string();
        if (auto twice = handedInTwice.find(r.submission); twice != handedInTwice.end())
            r.notes += (r.notes.empty() ? "" : "; ") + twice->second;
        if (auto chose = scriptChosen.find(r.student); chose != scriptChosen.end())
            r.notes += (r.notes.empty() ? "" : "; ") + chose->second;
        rows.push_back(r);
        recordOut << gradeRecord(r) << "\n";
        recordOut.flush();
        if (std::chrono::steady_clock::now() - lastWrite > std::chrono::seconds(2)) {
            writeReport(out, header, rows, rowHtml, out, overrides, feedbackKept);
            lastWrite = std::chrono::steady_clock::now();
        }
    };

    // Unpack, find the script; what cannot be graded is a row at once.
    std::vector<BatchJob> jobs;
    std::vector<size_t> jobStudent;  // index into subs
    for (size_t i = 0; i < subs.size(); ++i) {
        if (!inShard(i, shard, shards) || graded.count(stems[i]) || (!only.empty() && !only.count(stems[i]))) continue;
        GradeRow r;
        r.student = stems[i];
        r.submission = subs[i].path;
        std::string folder = subs[i].path, why;
        if (subs[i].zip) {
            folder = (unpacked / stems[i]).string();
            fs::remove_all(folder, ec);
            if (!safeUnzip(subs[i].path, folder, UnzipLimits{}, why)) {
                r.verdict = "error";
                r.notes = "the zip was refused";
                r.diagnostics = why + "\n";
                keep(r);
                continue;
            }
        }
        std::string chose;
        std::string script = findScript(folder, why, fs::path(o.reference).filename().string(), &chose);
        if (!chose.empty()) scriptChosen[stems[i]] = chose;
        if (script.empty()) {
            r.verdict = "error";
            r.notes = why.find("no .glib") != std::string::npos ? "no script" : "more than one script";
            r.diagnostics = why + "\n";
            keep(r);
            continue;
        }
        // The submission's folder is readable too: the sandbox is the submission, not only the script's folder.
        BatchJob job{script, "", settings, {}, {folder}};
        for (size_t k = 0; k < settings.size(); ++k) {
            job.outputs.push_back((pictures / fmt::format("{}-{}.png", stems[i], k)).string());
            fs::remove(job.outputs.back(), ec);  // what is there after a stop is this run's: where it stopped
        }
        jobs.push_back(job);
        jobStudent.push_back(i);
    }

    // A picture of one colour is a verdict only when a fresh worker, alone on
    // the machine, draws it again (process/batch.h: on a shared GPU another
    // process can reset this one's work, which then reads back as zeros).
    studentSettings.recheck = [&](size_t, const BatchResult& result) {
        if (result.written.size() != settings.size()) return false;
        for (size_t k = 0; k < settings.size(); ++k) {
            Image student;
            std::string why;
            if (loadImage(result.written[k], student, why) && blankAgainst(student, solutionPictures[k]))
                return true;
        }
        return false;
    };
    Progress progress;
    runBatch(jobs, studentSettings, [&](size_t done, size_t total) { progress.update(fmt::format("batch: {}/{} graded", done, total)); },
             [&](size_t j, const BatchResult& result) {
                 const size_t i = jobStudent[j];
                 GradeRow r = rowOf(result, settings, solutionPictures, solutionJob.outputs, solved[0].sliders, thresholds,
                                    out);
                 r.student = stems[i];
                 r.submission = subs[i].path;
                 r.script = jobs[j].script;
                 keep(r);
             });
    progress.finish();
    writeReport(out, header, rows, rowHtml, out, overrides, feedbackKept);
    warnUnusedOverrides(rows, overrides);
    std::map<std::string, int> counts;
    for (const auto& r : rows) ++counts[r.verdict];
    reportWrote(fmt::format("{} ({} submissions: {} pass, {} look, {} wrong, {} error), {}",
                            (out / "report.html").string(), rows.size(), counts["pass"], counts["look"],
                            counts["wrong"], counts["error"], (out / "grades.csv").string()));
    return counts["error"] ? kExitScriptError : kExitOk;
}

}  // namespace glimmer
