// glimmer batch-merge: the shards of a grading job array (each a
// `glimmer batch --reference ... --shard I/N -o DIR`) joined into one
// report, after checking that every student of the class was graded exactly
// once. No GL: it reads the shards' records and pictures.
#include <filesystem>
#include <iostream>
#include <map>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/subcommands.h"
#include "app/grade_batch.h"
#include "pipeline/console.h"
#include "grade/grade_merge.h"
#include "util/read_file.h"

namespace glimmer {
namespace fs = std::filesystem;

void addBatchMergeCommand(CLI::App& app, BatchMergeOptions& o) {
    CLI::App* sub = app.add_subcommand("batch-merge", "join the -o folders of graded shards (batch --reference "
                                                      "--shard I/N) into one report, each student exactly once");
    sub->add_option("shards", o.shards, "the shards' -o folders")->required();
    sub->add_option("-o,--output", o.outputDir, "the folder for the joined report.html, grades.csv and grades.jsonl")
        ->required();
    sub->add_option("--overrides", o.overrides, "a CSV student,score,comment, as for batch --reference");
}

int runBatchMerge(const BatchMergeOptions& o) {
    std::map<std::string, Override> overrides;
    if (!loadOverrides(o.overrides, overrides)) return kExitUsage;
    ReportHeader header;
    std::vector<std::string> students;
    std::vector<std::vector<GradeRow>> shards;
    std::error_code ec;
    fs::create_directories(o.outputDir, ec);
    if (!fs::is_directory(o.outputDir)) {
        std::cerr << fmt::format("glimmer: error: -o {}: cannot make this folder\n", o.outputDir);
        return kExitUsage;
    }
    for (const auto& dir : o.shards) {
        std::string text, why;
        const std::string headerFile = (fs::path(dir) / "grading.txt").string();
        ReportHeader h;
        std::vector<std::string> list;
        if (!readRegularFile(headerFile, 1 << 24, text, why) || !parseRunHeader(text, h, list, why)) {
            std::cerr << fmt::format("{}: error: not a graded shard: {}\n", headerFile, why);
            return kExitUsage;
        }
        if (shards.empty()) {
            header = h;
            students = list;
        } else if (list != students || h.settings != header.settings || h.solution != header.solution ||
                   h.solutionContent != header.solutionContent) {
            std::cerr << fmt::format("{}: error: graded another class, solution or settings than {}\n", headerFile,
                                     (fs::path(o.shards[0]) / "grading.txt").string());
            return kExitUsage;
        }
        const std::string records = (fs::path(dir) / "grades.jsonl").string();
        std::vector<GradeRow> rows;
        if (!readRegularFile(records, std::uint64_t(1) << 30, text, why)) {
            std::cerr << fmt::format("{}: error: cannot read it: it {}\n", records, why);
            return kExitUsage;
        }
        if (!parseRecords(text, records, rows, why)) {
            std::cerr << why << "\n";
            return kExitUsage;
        }
        // Pictures stay where the shard drew them; the joined records point there.
        for (auto& r : rows) {
            if (!r.picture.empty()) r.picture = fs::relative(fs::absolute(fs::path(dir) / r.picture), fs::absolute(o.outputDir), ec).string();
            if (!r.solution.empty()) r.solution = fs::relative(fs::absolute(fs::path(dir) / r.solution), fs::absolute(o.outputDir), ec).string();
        }
        shards.push_back(rows);
    }
    std::vector<GradeRow> merged;
    std::vector<std::string> problems;
    if (!mergeShardRows(shards, students, merged, problems)) {
        for (const auto& p : problems) std::cerr << "glimmer: error: batch-merge: " << p << "\n";
        return kExitScriptError;
    }
    std::string kept;
    for (const auto& r : merged) kept += gradeRecord(r) + "\n";
    writeWhole(fs::path(o.outputDir) / "grades.jsonl", kept);
    writeWhole(fs::path(o.outputDir) / "grading.txt", runHeaderText(header, students));
    header.expected = int(students.size());
    std::map<std::string, std::string> rowHtml;
    writeReport(o.outputDir, header, merged, rowHtml, o.outputDir, overrides);
    warnUnusedOverrides(merged, overrides);
    reportWrote(fmt::format("{} ({} submissions from {} shards, each exactly once)",
                            (fs::path(o.outputDir) / "report.html").string(), merged.size(), shards.size()));
    return kExitOk;
}

}  // namespace glimmer
