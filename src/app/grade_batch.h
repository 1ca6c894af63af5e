// glimmer batch with --reference (app/grade_batch.cpp), and what
// batch-merge shares with it: the report written from rows.
#pragma once
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "process/batch.h"
#include "pipeline/options.h"
#include "grade/grade_report.h"
#include "grade/overrides.h"

namespace glimmer {

// Grades the submissions in `inputs` (folders, zips, scripts) of shard I/N.
int runGradeBatch(const BatchOptions& o, const std::vector<std::string>& inputs, int shard, int shards,
                  const BatchSettings& settings);

// report.html and grades.csv in `dir`, the rows' pictures read relative to
// `picturesDir`, the teacher's overrides applied; `rowHtml` caches each
// student's row (pictures encoded once), whose feedback page
// (feedback/NAME.html) is written when the row is first made, unless the
// student is in `feedbackKept` (a row resumed from an earlier run whose page
// is there and still right: feedbackStillRight).
void writeReport(const std::filesystem::path& dir, const ReportHeader& header, std::vector<GradeRow> rows,
                 std::map<std::string, std::string>& rowHtml, const std::filesystem::path& picturesDir,
                 const std::map<std::string, Override>& overrides = {},
                 const std::set<std::string>& feedbackKept = {});

// True when `dir`'s feedback page for `row` (resumed, not regraded) can stay
// as an earlier run wrote it: it exists, and neither it nor the row carries
// a teacher's override (an override added, changed or taken away since is
// written again). Writing a page encodes every setting's pictures full size:
// skipping the ones that stay keeps `--resume`/`--only` (and each hand-in
// `glimmer serve` grades) from growing with the class (issue 41).
bool feedbackStillRight(const std::filesystem::path& dir, const GradeRow& row,
                        const std::map<std::string, Override>& overrides);

// The teacher's overrides file (`file` empty: none); false, said on
// stderr, when it cannot be read or is not one (exit 2). And the warning
// for names in it that no row has (a typo would otherwise go unseen).
bool loadOverrides(const std::string& file, std::map<std::string, Override>& out);
void warnUnusedOverrides(std::vector<GradeRow> rows, const std::map<std::string, Override>& overrides);

// `text` into `path` through a temporary file and a rename.
bool writeWhole(const std::filesystem::path& path, const std::string& text);

}  // namespace glimmer
