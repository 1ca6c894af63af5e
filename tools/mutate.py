#!/usr/bin/env python3
"""Mutation testing for Glimmer (issue 26): do the tests fail when the code breaks?

A table of small, plausible bugs (MUTANTS below: a file, an exact piece of its
text, what it becomes, and the test programs and gtest filter that should
notice). Each is put into the source alone, only the test programs it names
are rebuilt and run with its filter, and the source is put back: a mutant is
"caught" when a test fails (or the program crashes or times out), "missed"
when every test still passes. The source is restored after every mutant, on
a failed build, on an error and on Ctrl-C or SIGTERM; a mutant left in place
by a kill -9 is put back by the next run (a journal in the build folder).

Not part of CI (.ci/run): it rebuilds and reruns test programs once per
mutant (the whole table: 6.6 minutes on two cores, 2026-11-27, with the test
programs already built; the score is in docs/RELIABILITY.md, "Mutation
testing (issue 26)").

Usage:
  tools/mutate.py --list                      # the table
  tools/mutate.py --check                     # is every mutant's text still in the source, once?
  tools/mutate.py --build build-mut           # every mutant, in place, with that build folder
  tools/mutate.py --snapshot build-mut/snap   # the same on a copy of the working tree (see below)
  tools/mutate.py --snapshot DIR --only grade.pass-needs-psnr,cascade.same-file
  tools/mutate.py --snapshot DIR --listed     # the behaviours issue 26 lists
  tools/mutate.py --snapshot DIR --match grade --report mutation.md
  tools/mutate.py --snapshot DIR --prepare    # copy and build only (to work on the tests)

--build DIR mutates the source tree DIR was configured from (read from its
CMakeCache.txt), in place: while a mutant is in, anyone building or
committing from that tree gets the bug. In a shared working tree use
--snapshot DIR instead: the working tree's files (tracked and untracked, not
ignored) are copied to DIR/src (only those that changed since the last copy,
so rebuilds stay incremental), DIR/build is configured from it
(RelWithDebInfo, GLIMMER_TESTS=ON) the first time, and the mutants go into
the copy.

Before the mutants, every test program of the selection is built and every
filter run on the unchanged source: all must pass, or nothing is mutated
(a test that already fails would count as catching every mutant). Exit
status: 0 when every mutant run was caught, 1 when some were missed (or did
not compile or were stale), 2 on a usage, build or baseline error.

Adding a mutant: one M(...) line. `original` must occur exactly once in the
file (--check says where it does not: another edit moved the text, so the
mutant is "stale", never counted as caught), `replacement` must be the bug
a person could really write, and `tests` maps each test program to the
gtest filter that should catch it.
"""
import argparse
import dataclasses
import datetime
import json
import os
import platform
import re
import shutil
import signal
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
JOURNAL = ".mutate-journal.json"


@dataclasses.dataclass
class Mutant:
    id: str
    file: str          # relative to the source tree
    original: str      # exact text, exactly once in the file
    replacement: str   # what it becomes (never empty: the restore looks for it)
    tests: dict        # test program -> gtest filter
    what: str          # the bug in words
    listed: bool = False  # one of the behaviours issue 26 lists


def M(id, file, original, replacement, tests, what, listed=False):
    return Mutant(id, file, original, replacement, tests, what, listed)


GRADE = {"test_grade": "Grading.*:GradeReport.*:GradeMerge.*"}
CASCADES = {"test_driver": "ErrorCascades.*:FoldDiagnostics.*"}

MUTANTS = [
    # ---- issue 26's list ----
    M("grade.pass-needs-psnr", "src/grade/grading.cpp",
      "if (minSsim >= t.passSsim && minPsnr >= t.passPsnr) v.kind",
      "if (minSsim >= t.passSsim) v.kind",
      GRADE, "the pass verdict uses only SSIM (the PSNR half dropped)", listed=True),
    M("grade.blank-is-wrong", "src/grade/grading.cpp",
      "else if (minSsim >= t.lookSsim && !blank) v.kind = \"look\";",
      "else if (minSsim >= t.lookSsim) v.kind = \"look\";",
      GRADE, "a blank picture no longer counts as wrong", listed=True),
    M("resume.same-reference", "src/app/grade_batch.cpp",
      "if (before.solution != header.solution || before.settings != header.settings ||",
      "if (before.settings != header.settings ||",
      {"test_cli": "CliGrade.Resume*"}, "--resume with another --reference resumes and mixes two gradings",
      listed=True),
    M("csv.plus-is-a-formula", "src/grade/grade_report.cpp",
      "(text[0] == '=' || text[0] == '+' || text[0] == '-' || text[0] == '@')",
      "(text[0] == '=' || text[0] == '-' || text[0] == '@')",
      GRADE, "the CSV guard stops quoting cells that start with '+'", listed=True),
    M("html.escape-quote", "src/grade/grade_report.cpp",
      "case '\"': out += \"&quot;\"; break;",
      "case '\"': out += \"\\\"\"; break;",
      GRADE, "the HTML escaper stops escaping '\"' (a student's name inside an attribute)", listed=True),
    M("cascade.same-file", "src/driver/error_cascades.cpp",
      "if (first >= 0 && d.fromDriver && d.file == all[size_t(first)].file &&\n            (runLines",
      "if (first >= 0 && d.fromDriver &&\n            (runLines",
      CASCADES, "folding cascading errors ignores the file (a.frag:5 hidden under a.vert:5)", listed=True),
    M("nvidia.core-at-150", "src/gl/shader_build.cpp",
      "return version >= 150 && v.profile.empty() ? v.line : 0;",
      "return version > 150 && v.profile.empty() ? v.line : 0;",
      {"test_cli": "CliNvidiaLeniency.*Version*"}, "the core-profile leniency stops applying at '#version 150' itself",
      listed=True),

    M("png.strips-of-fixed-rows", "src/image/png_write.cpp",
      "const int stripRows = int(std::clamp<std::size_t>(kStripBytes / rowBytes, 1, std::size_t(img.height)));",
      "const int stripRows = int(std::clamp<std::size_t>(std::size_t(img.height) / std::max(1u, "
      "std::thread::hardware_concurrency()), 1, std::size_t(img.height)));",
      {"test_image": "PngWrite.*"}, "the PNG's strips are the picture split among the cores (the bytes then depend "
      "on the machine)", listed=True),

    # ---- src/grade ----
    M("grade.sliders-skip-repeats", "src/grade/grading.cpp",
      "if (!seen.insert(v).second) continue;", "seen.insert(v);",
      GRADE, "a slider whose end is its default is tried twice"),
    M("grade.vary-limit", "src/grade/grading.cpp",
      "if (out.size() > 64) {", "if (out.size() > 65) {",
      GRADE, "--vary allows 65 settings"),
    M("grade.blank-only-if-solution-is-not", "src/grade/grading.cpp",
      "c.blank = oneColour(student) && !oneColour(solution);", "c.blank = oneColour(student);",
      GRADE, "a one-colour picture is 'blank' even when the solution is one colour too"),
    M("grade.one-colour-reads-blue", "src/grade/grading.cpp",
      "for (size_t c = 0; c < 3; ++c)\n            if (p.u8[t * 4 + c] != p.u8[c]) return false;",
      "for (size_t c = 0; c < 2; ++c)\n            if (p.u8[t * 4 + c] != p.u8[c]) return false;",
      GRADE, "a picture that varies only in blue counts as one colour"),
    M("grade.worst-is-lowest-ssim", "src/grade/grading.cpp",
      "if (perSetting[k].ssim < perSetting[worst].ssim) worst = k;",
      "if (perSetting[k].ssim > perSetting[worst].ssim) worst = k;",
      GRADE, "the worst setting is the best one"),
    M("grade.score-clamped", "src/grade/grading.cpp",
      "v.score = int(std::lround(100 * std::clamp(minSsim, 0.0, 1.0)));",
      "v.score = int(std::lround(100 * minSsim));",
      GRADE, "a negative SSIM gives a negative score"),
    M("grade.missing-uniform-is-look", "src/grade/grading.cpp",
      "v.kind = missing.empty() ? \"pass\" : \"look\";", "v.kind = \"pass\";",
      GRADE, "a submission lacking the solution's uniform passes"),
    M("grade.difference-x4", "src/grade/grading.cpp",
      "std::min(255, diff * 4)", "std::min(255, diff * 2)",
      GRADE, "the difference picture is scaled by 2, not 4"),
    M("grade.base64-padding", "src/grade/grading.cpp",
      "out += i + 2 < bytes.size() ? k[n & 63] : '=';", "out += i + 1 < bytes.size() ? k[n & 63] : '=';",
      GRADE, "base64 loses its last '=' of padding"),
    M("grade.records-only-cut-last-line", "src/grade/grade_merge.cpp",
      "if (cutOff && i + 1 == lines.size()) break;", "if (i + 1 == lines.size()) break;",
      GRADE, "a whole (not cut off) bad last record is dropped without an error"),
    M("grade.records-later-wins", "src/grade/grade_merge.cpp",
      "if (it != at.end()) rows[it->second] = r;", "if (it != at.end()) continue;",
      GRADE, "a student graded again after a resume keeps the old record"),
    M("grade.merge-twice", "src/grade/grade_merge.cpp",
      "else if (times[s] > 1)", "else if (times[s] > 2)",
      GRADE, "a student graded by two shards is not reported"),
    M("grade.header-sandbox", "src/grade/grade_merge.cpp",
      "h.sandbox = value == \"on\";", "h.sandbox = value != \"\";",
      GRADE, "'sandbox: off' reads back as on"),
    M("grade.record-whole-score", "src/grade/grade_row.cpp",
      "if (!(score >= 0 && score <= 100) || score != std::floor(score))",
      "if (!(score >= 0 && score <= 100))",
      GRADE, "a record with a fractional score is read (and truncated)"),
    M("grade.record-verdict-checked", "src/grade/grade_row.cpp",
      "if (r.verdict != \"pass\" && r.verdict != \"look\" && r.verdict != \"wrong\" && r.verdict != \"error\")",
      "if (r.verdict != \"pass\" && r.verdict != \"look\" && r.verdict != \"wrong\" && r.verdict != \"error\" && false)",
      GRADE, "a record with an unknown verdict is read"),
    M("grade.review-order", "src/grade/grade_report.cpp",
      "if (a.score != b.score) return a.score < b.score;", "if (a.score != b.score) return a.score > b.score;",
      GRADE, "within a verdict the best score comes first"),
    M("csv.quote-newline", "src/grade/grade_report.cpp",
      "if (text.find_first_of(\",\\\"\\n\\r\") == std::string::npos) return text;",
      "if (text.find_first_of(\",\\\"\") == std::string::npos) return text;",
      GRADE, "a CSV cell with a line break is not quoted (a folder name with a newline splits the row)"),
    M("html.still-running", "src/grade/grade_report.cpp",
      "h.expected > int(rows.size()) ?", "h.expected >= int(rows.size()) ?",
      GRADE, "a finished report says '(the rest still running)'"),
    M("unzip.symlink", "src/grade/safe_unzip.cpp",
      "return opsys == ZIP_OPSYS_UNIX && ((attributes >> 16) & S_IFMT) == S_IFLNK;",
      "return opsys == ZIP_OPSYS_UNIX && ((attributes >> 16) & S_IFMT) == S_IFDIR;",
      {"test_grade": "SafeUnzip.*"}, "a symbolic link in a zip is unpacked"),
    M("unzip.dotdot", "src/grade/safe_unzip.cpp",
      "if (name.compare(start, end - start, \"..\") == 0 && end - start == 2) return \"leaves its folder (..)\";",
      "if (name.compare(start, end - start, \"..\") == 0 && end - start == 2 && start == 0) return \"leaves its folder (..)\";",
      {"test_grade": "SafeUnzip.*"}, "only a leading '..' is refused (a/../../x escapes)"),
    M("submissions.depth", "src/grade/submissions.cpp",
      "if (it->is_directory(ec) && it.depth() >= kScriptSearchDepth - 1) it.disable_recursion_pending();",
      "if (it->is_directory(ec) && it.depth() >= kScriptSearchDepth - 2) it.disable_recursion_pending();",
      {"test_grade": "Submissions.*"}, "scripts eight folders deep are no longer found"),
    M("zip.backslash-folders", "src/grade/safe_unzip.cpp",
      "if (c == '\\\\') c = '/';",
      "if (c == '\\\\') c = '\\\\';",
      {"test_grade": "SafeUnzip.*:UnsafeEntry*"}, "a zip's backslashes are no longer folders (issue 29)"),
    M("plan.case-hint", "src/plan/plan_textures.cpp",
      "if (std::string other = sameNameButCase(tried, name); !other.empty())",
      "if (std::string other = sameNameButCase({}, name); !other.empty())",
      {"test_cli": "CliMessyWork.*"}, "a name in another case is no longer named in the error (issue 29)"),
    M("assets.shader-bom", "src/assets/load_assets.cpp",
      "text->replace(0, 3, \"   \");",
      "text->replace(0, 0, \"\");",
      {"test_cli": "CliMessyWork.*"}, "a byte-order mark before #version reaches the compiler (issue 29)"),
    M("names.keep-utf8", "src/driver/batch.cpp",
      "if (size_t n = utf8Letter(base, k)) {",
      "if (size_t n = 0 * utf8Letter(base, k)) {",
      {"test_cli": "CliGrade.Names*"}, "a student's letters beyond ASCII become '_' again (issue 29)"),
    M("names.twice-said", "src/app/grade_batch.cpp",
      "if (subs[i].name == subs[i - 1].name && (i < 2 || subs[i - 2].name != subs[i].name)) {",
      "if (false) {",
      {"test_cli": "CliGrade.Names*"}, "a student who handed in twice is graded twice without a word (issue 29)"),
    M("csv.tab-first", "src/grade/grade_report.cpp",
      "if (text[0] == '\\t' || text[0] == '\\r') return true;",
      "if (text[0] == '\\r') return true;",
      GRADE, "a cell starting with a tab before a formula is no longer guarded (issue 29)"),
    M("report.error-label", "src/grade/grade_report.cpp",
      "const std::string label = r.verdict == \"error\" && !r.notes.empty() ? \"error: \" + r.notes : r.verdict;",
      "const std::string label = r.verdict;",
      GRADE, "every error row says only 'error' again (issue 29)"),
    M("batch.timeout-ms", "src/driver/batch.cpp",
      "s.timeoutSeconds, s.timeoutSeconds), ms);",
      "s.timeoutSeconds, s.timeoutSeconds), 0);",
      {"test_cli": "CliGrade.EachKind*"}, "a timed-out submission's time is 0.00 s again (issue 29)"),

    # ---- src/driver ----
    M("cascade.first-is-a-driver-error", "src/driver/error_cascades.cpp",
      "first = d.fromDriver ? int(i) : -1;", "first = int(i);",
      CASCADES, "the driver's errors fold under one of Glimmer's own errors of the same file"),
    M("cascade.warning-from-driver", "src/driver/error_cascades.cpp",
      "if (first >= 0 && d.fromDriver && d.file == all[size_t(first)].file) cause[i] = first;",
      "if (first >= 0 && d.file == all[size_t(first)].file) cause[i] = first;",
      CASCADES, "Glimmer's own warnings and notes about the shader are hidden under the driver's error"),
    M("cascade.same-line", "src/driver/error_cascades.cpp",
      "(runLines.count(d.loc.line) || d.message", "(d.message",
      CASCADES, "errors on the first error's line no longer follow from it"),
    M("cascade.same-message", "src/driver/error_cascades.cpp",
      "|| d.message == all[size_t(first)].message ||", "||",
      CASCADES, "the same undeclared name on a later line is a new mistake"),
    M("cascade.failed-type", "src/driver/error_cascades.cpp",
      "if (m.find(mark) != std::string::npos) return true;", "if (m.find(mark) == 0) return true;",
      CASCADES, "an error naming the failed type `error` on another line is a new mistake"),
    M("fold.per-file", "src/driver/fold_diagnostics.cpp",
      "if (d.severity == Severity::Warning) ++count[d.file + \"\\n\" + diagnosticKind(d.message)];",
      "if (d.severity == Severity::Warning) ++count[diagnosticKind(d.message)];",
      CASCADES, "warnings of one kind in two files are folded together"),
    M("fold.numbers", "src/driver/fold_diagnostics.cpp",
      "if (std::isdigit(static_cast<unsigned char>(c))) {\n            while",
      "if (false && std::isdigit(static_cast<unsigned char>(c))) {\n            while",
      CASCADES, "warnings differing only in a number are not one kind"),
    M("fold.two-is-a-group", "src/driver/fold_diagnostics.cpp",
      "if (n >= 2) {", "if (n >= 3) {",
      CASCADES, "two warnings of one kind are not folded"),
    M("fold.not-shown-counted", "src/driver/fold_diagnostics.cpp",
      "++notShown;\n            continue;", "continue;\n            ++notShown;",
      CASCADES, "diagnostics past the limit vanish without '... N more'"),
    M("fold.followers-plural", "src/driver/fold_diagnostics.cpp",
      "one ? \"s\" : \"\", one ? \"it\" : \"them\"", "one ? \"\" : \"s\", one ? \"it\" : \"them\"",
      CASCADES, "'5 more errors follows'"),
    M("health.alpha-not-clipped", "src/driver/numeric_health.cpp",
      "for (size_t i = 0; i < f.size(); ++i) f[i] = i % 4 == 3 ? 0.f : img.u8[i] / 255.f;",
      "for (size_t i = 0; i < f.size(); ++i) f[i] = img.u8[i] / 255.f;",
      {"test_render": "Hdr.*"}, "--health counts the alpha of every 8-bit pixel as clipped"),
    M("web.geometry-at-the-program", "src/driver/web_check.cpp",
      "if (!refused && !webRefusal(webStage(stage.kind)).empty()) refused = &stage;",
      "if (!refused && !webRefusal(webStage(stage.kind)).empty() && false) refused = &stage;",
      {"test_cli": "CliWebCheck.*"}, "check --web translates a geometry shader instead of refusing its Program once"),
    M("web.gstap-prelude-only-for-gstap", "src/driver/web_check.cpp",
      "in.prelude = decl.gstap ? kGstapPrelude : \"\";", "in.prelude = kGstapPrelude;",
      {"test_cli": "CliWebCheck.*"}, "check --web compiles every Program after GSTAP's aliases"),
    M("web.translates", "src/driver/web_check.cpp",
      "translateForWeb(in, diags);\n", "(void)in;\n",
      {"test_cli": "CliWebCheck.*"}, "check --web translates nothing"),
    M("session.check-compiles", "src/driver/session.cpp",
      "bool ok = uploadScript(*s.renderer, s.loaded, everything, diags) && filesOk;",
      "bool ok = filesOk;",
      {"test_cli": "CliWebCheck.*"}, "glimmer check makes a context but compiles nothing on it"),
    M("checks.draws-nothing", "src/driver/script_checks.cpp",
      "if (step.kind == Step::Kind::Draw) return true;", "if (step.kind == Step::Kind::Clear) return true;",
      {"test_cli": "CliUnix.*"}, "a script that only clears is not warned about"),

    # ---- src/plan ----
    M("deps.screen-downstream", "src/plan/dependencies.cpp",
      "if (p.targets.empty()) touched |= screenDirty || change.screen;",
      "if (p.targets.empty()) touched |= change.screen;",
      {"test_plan": "Dependencies.*:CarryOver.*"}, "a screen pass after another changed screen pass is not redrawn"),
    M("deps.shared-target", "src/plan/dependencies.cpp",
      "for (int t : p.targets) touched |= dirtyTextures.count(t) > 0;",
      "for (int t : p.targets) touched |= false && t;",
      {"test_plan": "Dependencies.*:CarryOver.*"}, "passes drawing into one target no longer run together"),
    M("deps.reads", "src/plan/dependencies.cpp",
      "for (int t : p.reads) touched |= dirtyTextures.count(t) > 0;",
      "for (int t : p.reads) touched |= false && t;",
      {"test_plan": "Dependencies.*:CarryOver.*"}, "a pass reading a changed texture is not redrawn"),
    M("deps.repeat-walk", "src/plan/dependencies.cpp",
      "run[i] = grew = true;", "run[i] = true;",
      {"test_plan": "Dependencies.*:CarryOver.*"}, "the walk does not repeat to reach back to earlier passes"),
    M("values.carry-clamped", "src/plan/uniform_values.cpp",
      "if (u.form == UniformSetting::Form::Range) v[0] = std::clamp(v[0], u.min, u.max);",
      "if (u.form == UniformSetting::Form::Range) v[0] = v[0];",
      {"test_plan": "Dependencies.*:CarryOver.*"}, "a reload keeps a slider value outside its new range"),
    M("values.carry-same-form", "src/plan/uniform_values.cpp",
      "if (was.name != u.name || was.form != u.form) continue;", "if (was.name != u.name) continue;",
      {"test_plan": "Dependencies.*:CarryOver.*"}, "a reload carries a value into a uniform of another form"),
    M("values.differing-both-ways", "src/plan/uniform_values.cpp",
      "for (const auto& [key, v] : other.values_)\n        if (get(key.program, key.name) != v) out.insert(key.program);",
      "for (const auto& [key, v] : other.values_)\n        if (false) out.insert(key.program);",
      {"test_plan": "Dependencies.*:CarryOver.*"}, "a uniform only the other values hold is not a difference"),
    M("set.range-bounds", "src/plan/uniform_values.cpp",
      "if (value < u.min || value > u.max) {", "if (value < u.min || value >= u.max) {",
      {"test_plan": "SetTest.*"}, "--set at a range's top end is refused"),
    M("set.colour-keeps-alpha", "src/plan/uniform_values.cpp",
      "rgba.push_back(u.values.size() > 3 ? u.values[3] : 1.0);", "rgba.push_back(1.0);",
      {"test_plan": "SetTest.*:SetColour.*"}, "--set of R,G,B drops the colour's own alpha"),
    M("set.bool-words", "src/plan/uniform_values.cpp",
      "value = lowered == \"true\" ? 1 : 0;", "value = part == \"true\" ? 1 : 0;",
      {"test_plan": "SetTest.*"}, "--set uFlag=TRUE sets false"),
    M("usage.unneeded-pass", "src/plan/usage.cpp",
      "if (!pass.needed && !everything) continue;", "if (!pass.needed && everything) continue;",
      {"test_plan": "Usage.*:PlanTest.*"}, "the textures, meshes and programs of passes nobody reads are made"),
    M("hidden.depth-pass", "src/plan/hidden_clears.cpp",
      "if (pass.needsDepth || pass.targets.size() > 1) continue;", "if (pass.targets.size() > 1) continue;",
      {"test_plan": "HiddenClears.*"}, "a Clear of a pass with depth is marked hidden (its depth buffer is then never cleared)"),
    M("hidden.convex-both-sides", "src/plan/hidden_clears.cpp",
      "return !(anyPositive && anyNegative);", "return !(anyPositive || anyNegative);",
      {"test_plan": "HiddenClears.*"}, "no corner of the viewport is ever inside a quad"),

    # ---- src/shader ----
    M("precision.from-130", "src/shader/precision_strip.cpp",
      "if (versionOf(source) >= 130) return r;", "if (versionOf(source) > 130) return r;",
      {"test_shader": "PrecisionStrip.*"}, "precision qualifiers are stripped from GLSL 1.30, which has them"),
    M("precision.lowp", "src/shader/precision_strip.cpp",
      "if (word == \"highp\" || word == \"mediump\" || word == \"lowp\") blank(i, j);",
      "if (word == \"highp\" || word == \"mediump\") blank(i, j);",
      {"test_shader": "PrecisionStrip.*"}, "'lowp' is left in a GLSL 1.10 shader"),
    M("gs4.version-150-kept", "src/shader/gs4_translate.cpp",
      "if (r.usesExt && version && versionNumber(version->text) < 150) {",
      "if (r.usesExt && version && versionNumber(version->text) <= 150) {",
      {"test_shader": "Gs4Translate.*"}, "a '#version 150' EXT geometry shader is rewritten to 150 compatibility"),
    M("gs4.vertices-in-size-only-global", "src/shader/gs4_translate.cpp",
      "if (depth == 0 && k > 0 && punct(k - 1, '[') && punct(k + 1, ']')) {",
      "if (k > 0 && punct(k - 1, '[') && punct(k + 1, ']')) {",
      {"test_shader": "Gs4Translate.*"}, "gl_VerticesIn as an index inside a function becomes []"),
    M("gs4.varying-out", "src/shader/gs4_translate.cpp",
      "if (ident(k + 1, \"in\") || ident(k + 1, \"out\")) {", "if (ident(k + 1, \"in\")) {",
      {"test_shader": "Gs4Translate.*"}, "'varying out' becomes 'out out'"),
    M("compat.texcoord-count", "src/shader/compat_rewrite.cpp",
      "if (k >= 0 && k < kTexCoordCount && close < s.size() && s[close] == ']') {",
      "if (k >= 0 && k <= kTexCoordCount && close < s.size() && s[close] == ']') {",
      {"test_shader": "WebTranslate*:CompatRewrite*"}, "gl_TexCoord[8] (past gl_MaxTextureCoords) becomes a varying"),
    M("compat.fragdata-and-fragcolor", "src/shader/compat_rewrite.cpp",
      "if (fragData && !fragColor) {", "if (fragData) {",
      {"test_shader": "WebTranslate*:CompatRewrite*"}, "gl_FragColor and gl_FragData together are declared twice at location 0"),
    M("compat.attribute-in-vertex-only", "src/shader/compat_rewrite.cpp",
      "if (word == \"attribute\" && vertex) {", "if (word == \"attribute\") {",
      {"test_shader": "WebTranslate*:CompatRewrite*"}, "'attribute' in a fragment shader becomes 'in' instead of an error"),
    M("compat.version-at-least-330", "src/shader/compat_rewrite.cpp",
      "std::max(330, r.version)", "std::max(300, r.version)",
      {"test_shader": "WebTranslate*:CompatRewrite*"}, "a #version 120 shader is compiled as #version 300 core"),

    M("coverage.one-write", "src/shader/coverage_hints.cpp",
      "return uses == 1 && plain;", "return plain;",
      {"test_shader": "CoverageHints.*"}, "a vertex shader writing gl_Position twice is vouched for by its last write"),

    # ---- src/gl ----
    M("upload.luminance", "src/gl/uniform_upload.cpp",
      "return {0.2126 * values[0] + 0.7152 * values[1] + 0.0722 * values[2]};",
      "return {(values[0] + values[1] + values[2]) / 3};",
      {"test_glman": "GlmanCheck.*"}, "a colour given to a float is the plain mean, not the luminance"),
    M("upload.bool-every-component", "src/gl/uniform_upload.cpp",
      "return std::vector<double>(n, b);", "return std::vector<double>(1, b);",
      {"test_glman": "GlmanCheck.*"}, "a checkbox given to a vector sets only its first component"),
    M("upload.round-ints", "src/gl/uniform_upload.cpp",
      "GLint(clampToInt(std::round(values[k])))", "GLint(clampToInt(values[k]))",
      {"test_glman": "*Golden.*:GlmanCheck.*:GlmanProperties.*"}, "an int uniform set to 2.7 is 2, not 3"),
    M("upload.matrix-identity", "src/gl/uniform_upload.cpp",
      "m[e * size_t(t.components) + size_t(k * dim + k)] = values[0];",
      "m[e * size_t(t.components) + size_t(k)] = values[0];",
      {"test_glman": "GlmanCheck.*:*Golden.*"}, "one number given to a matrix fills its first column, not its diagonal"),
    M("upload.missing-or-extra", "src/gl/uniform_upload.cpp",
      "how = s.values.size() < want ? \"the missing components are 0\" : \"the extra values are dropped\";",
      "how = s.values.size() > want ? \"the missing components are 0\" : \"the extra values are dropped\";",
      {"test_glman": "GlmanCheck.*"}, "too few values are called extra, too many missing"),
    M("unset.timer-is-fed", "src/gl/unset_uniforms.cpp",
      "return name == \"Timer\" || name == \"Noise2\"", "return name == \"Noise2\"",
      {"test_cli": "CliUnsetUniforms.*"}, "a shader reading Timer is told that the script never sets it"),
    M("bind.other-targets", "src/plan/draw_units.cpp",
      "out.insert(out.end(), others->second.begin(), others->second.end());",
      "out.insert(out.end(), others->second.begin(), others->second.begin());",
      {"test_glman": "UnitTargets.*:GlmanCheck.*"}, "a unit keeps only the texture bound last, not those of its other targets"),
    M("bind.texture-kind", "src/plan/draw_units.cpp",
      "textures[size_t(t)].kind == kind) return t;", "textures[size_t(t)].kind != kind) return t;",
      {"test_glman": "UnitTargets.*:GlmanCheck.*"}, "a sampler's unit is matched with a texture of another kind"),
    M("bind.empty-targets", "src/gl/renderer.cpp",
      "for (size_t k = 0; k < std::size(kTargets); ++k) gl_->BindTexture(kTargets[k], onTarget[k]);",
      "for (size_t k = 0; k < std::size(kTargets); ++k) if (onTarget[k]) gl_->BindTexture(kTargets[k], onTarget[k]);",
      {"test_glman": "UnitTargets.*:GlmanCheck.*"}, "a target the draw has no texture for keeps an older draw's texture"),
    M("bind.noise-yields", "src/gl/renderer.cpp",
      "for (int tex : d.texturesOn(unit)) scripts = scripts || textures_[tex].target == target;",
      "for (int tex : d.texturesOn(unit)) scripts = scripts && textures_[tex].target == target;",
      {"test_glman": "GlmanCheck.*"}, "the built-in noise replaces the script's own texture on unit 2"),
    M("upload.array-name", "src/gl/uniform_upload.cpp",
      "u.name.resize(u.name.size() - 3);", "u.name.resize(u.name.size());",
      {"test_glman": "GlmanCheck.*:*Golden.*"}, "an array uniform ('uW[0]') is never matched to the script's 'uW'"),
]


class Interrupted(Exception):
    pass


def on_signal(signum, frame):
    raise Interrupted(f"signal {signum}")


def read(path):
    with open(path, "r", encoding="utf-8", newline="") as f:
        return f.read()


def write(path, text):
    with open(path, "w", encoding="utf-8", newline="") as f:
        f.write(text)


def journal_path(build):
    return os.path.join(build, JOURNAL)


def put_back(path, original_text, replacement, original_file):
    """Undoes one mutant in `path`, keeping any other edit made meanwhile.
    True when the file holds no mutant any more."""
    if not os.path.exists(path):
        return False
    now = read(path)
    if now == original_file:
        return True
    mutated_file = original_file.replace(original_text, replacement, 1)
    if now == mutated_file:
        write(path, original_file)
        return True
    if now.count(replacement) == 1 and now.replace(replacement, original_text, 1).count(original_text) == 1:
        write(path, now.replace(replacement, original_text, 1))  # someone edited elsewhere in the file meanwhile
        return True
    backup = path + ".mutate-orig"
    write(backup, original_file)
    print(f"mutate: ERROR: cannot tell the mutant apart from other edits in {path}; the file as it was "
          f"before the mutant is in {backup}", file=sys.stderr)
    return False


def recover(build):
    """A run killed outright leaves its journal: put that mutant back first."""
    j = journal_path(build)
    if not os.path.exists(j):
        return True
    with open(j, encoding="utf-8") as f:
        entry = json.load(f)
    ok = put_back(entry["path"], entry["original"], entry["replacement"], entry["file"])
    print(f"mutate: put back mutant {entry['id']} left in {entry['path']} by an earlier run"
          + ("" if ok else " (FAILED, see above)"), file=sys.stderr)
    if ok:
        os.remove(j)
    return ok


def run_logged(cmd, cwd, log, timeout=None):
    """Runs `cmd` in a session of its own (so a timeout or Ctrl-C ends its
    children too); returns (exit status or 'timeout', output)."""
    with open(log, "w") as out:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            rc = p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
            rc = "timeout"
        except BaseException:
            try:
                os.killpg(p.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            p.wait()
            raise
    with open(log, errors="replace") as f:
        return rc, f.read()


def build(builddir, targets, jobs, log):
    rc, out = run_logged(["cmake", "--build", builddir, "-j", str(jobs), "--target", *sorted(targets)], builddir, log)
    return rc == 0, out


def run_tests(builddir, program, gfilter, timeout, log):
    """'pass', or a description of how the tests failed."""
    exe = os.path.join(builddir, "tests", program)
    rc, out = run_logged([exe, f"--gtest_filter={gfilter}"], os.path.join(builddir, "tests"), log, timeout)
    if rc == "timeout":
        return f"{program} timed out after {timeout} s"
    if "Running 0 tests" in out:
        return f"{program}: the filter {gfilter} runs no test"
    if rc == 0:
        return "pass"
    failed = sorted(set(re.findall(r"^\[  FAILED  \] ([A-Za-z_][\w/.]*)", out, re.M)))
    if failed:
        return ", ".join(failed)
    return f"{program} exited {rc}" if rc > 0 else f"{program} killed by signal {-rc}"


def sync_snapshot(snapdir):
    """The working tree's files, tracked and untracked but not ignored, into
    snapdir/src; a changed file gets the current time (so it is rebuilt)."""
    src = os.path.join(snapdir, "src")
    names = subprocess.run(["git", "-C", REPO, "ls-files", "-co", "--exclude-standard", "-z"], check=True,
                           capture_output=True).stdout.decode().split("\0")
    wanted = set()
    copied = 0
    for name in names:
        if not name or not os.path.isfile(os.path.join(REPO, name)):
            continue
        wanted.add(name)
        a, b = os.path.join(REPO, name), os.path.join(src, name)
        if os.path.isfile(b) and os.path.getsize(a) == os.path.getsize(b):
            with open(a, "rb") as fa, open(b, "rb") as fb:
                if fa.read() == fb.read():
                    continue
        os.makedirs(os.path.dirname(b), exist_ok=True)
        shutil.copyfile(a, b)
        shutil.copymode(a, b)
        copied += 1
    removed = 0
    for root, dirs, files in os.walk(src):
        for f in files:
            rel = os.path.relpath(os.path.join(root, f), src)
            if rel not in wanted:
                os.remove(os.path.join(root, f))
                removed += 1
    print(f"mutate: snapshot {src}: {copied} files copied, {removed} removed, {len(wanted)} in all")
    return src


def source_of(builddir):
    cache = os.path.join(builddir, "CMakeCache.txt")
    if not os.path.exists(cache):
        return None
    for line in open(cache, encoding="utf-8", errors="replace"):
        if line.startswith("CMAKE_HOME_DIRECTORY:"):
            return line.split("=", 1)[1].strip()
    return None


def check_texts(source, mutants):
    """{id: problem} for mutants whose text is not in the source exactly once."""
    problems = {}
    for m in mutants:
        path = os.path.join(source, m.file)
        if not os.path.exists(path):
            problems[m.id] = f"{m.file} does not exist"
            continue
        n = read(path).count(m.original)
        if n != 1:
            problems[m.id] = f"its text occurs {n} times in {m.file}"
        elif not m.replacement or m.replacement == m.original:
            problems[m.id] = "its replacement is empty or the same text"
    return problems


def markdown(results, started, seconds):
    caught = [r for r in results if r["result"] == "caught"]
    missed = [r for r in results if r["result"] == "missed"]
    lines = [f"Mutation run of {started:%Y-%m-%d %H:%M}, {platform.node()} ({os.cpu_count()} cores), "
             f"{seconds / 60:.0f} min: {len(caught)} of {len(caught) + len(missed)} caught.", "",
             "| mutant | file | the bug | result | caught by |", "|---|---|---|---|---|"]
    for r in results:
        m = r["mutant"]
        lines.append(f"| {m.id}{' (listed)' if m.listed else ''} | `{m.file}` | {m.what} | {r['result']} | "
                     f"{r['detail']} |")
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    where = ap.add_mutually_exclusive_group()
    where.add_argument("--build", help="a configured build folder; its source tree is mutated in place")
    where.add_argument("--snapshot", help="a folder for a copy of the working tree (SNAP/src) and its build (SNAP/build)")
    ap.add_argument("--only", help="mutant ids, comma-separated")
    ap.add_argument("--match", help="only mutants whose id or file contains this")
    ap.add_argument("--listed", action="store_true", help="only the behaviours issue 26 lists")
    ap.add_argument("--list", action="store_true", help="print the table and stop")
    ap.add_argument("--check", action="store_true", help="check that every mutant's text is in the source once, and stop")
    ap.add_argument("-j", "--jobs", type=int, default=2, help="build jobs (default 2)")
    ap.add_argument("--timeout", type=int, default=600, help="seconds a test program may run (default 600)")
    ap.add_argument("--report", help="write the results as a Markdown table to this file")
    ap.add_argument("--prepare", action="store_true",
                    help="copy the snapshot (with --snapshot), build the selection's test programs, and stop")
    ap.add_argument("--no-baseline", action="store_true", help="skip the run on the unchanged source (not advised)")
    args = ap.parse_args()

    mutants = MUTANTS
    ids = [m.id for m in MUTANTS]
    dupes = {i for i in ids if ids.count(i) > 1}
    if dupes:
        sys.exit(f"mutate: duplicate mutant ids: {', '.join(sorted(dupes))}")
    if args.only:
        want = args.only.split(",")
        unknown = [w for w in want if w not in ids]
        if unknown:
            sys.exit(f"mutate: no mutant named {', '.join(unknown)} (--list shows them)")
        mutants = [m for m in mutants if m.id in want]
    if args.match:
        mutants = [m for m in mutants if args.match in m.id or args.match in m.file]
    if args.listed:
        mutants = [m for m in mutants if m.listed]
    if args.list:
        for m in mutants:
            tests = "; ".join(f"{p} {f}" for p, f in m.tests.items())
            print(f"{m.id:38} {m.file:34} {m.what}\n{'':38} {tests}")
        print(f"{len(mutants)} mutants")
        return 0

    if args.snapshot:
        snap = os.path.abspath(args.snapshot)
        source = sync_snapshot(snap)
        builddir = os.path.join(snap, "build")
        if not os.path.exists(os.path.join(builddir, "CMakeCache.txt")):
            subprocess.run(["cmake", "-S", source, "-B", builddir, "-DCMAKE_BUILD_TYPE=RelWithDebInfo",
                            "-DGLIMMER_TESTS=ON"], check=True, stdout=subprocess.DEVNULL)
    else:
        builddir = os.path.abspath(args.build or os.path.join(REPO, "build-mut"))
        source = source_of(builddir) if not args.check else (source_of(builddir) or REPO)
        if not source:
            sys.exit(f"mutate: {builddir} is not a configured build folder (cmake -S . -B {builddir} "
                     "-DCMAKE_BUILD_TYPE=RelWithDebInfo -DGLIMMER_TESTS=ON)")

    for s in (signal.SIGTERM, signal.SIGHUP):
        signal.signal(s, on_signal)
    if not args.check and not recover(builddir):
        return 2

    problems = check_texts(source, mutants)
    if args.check:
        for m in mutants:
            print(f"{m.id:38} {problems.get(m.id, 'ok')}")
        print(f"{len(mutants) - len(problems)} of {len(mutants)} mutants apply to {source}")
        return 1 if problems else 0

    logdir = os.path.join(builddir, "mutate-logs")
    os.makedirs(logdir, exist_ok=True)
    if args.prepare:
        targets = sorted({p for m in mutants for p in m.tests})
        ok, _ = build(builddir, targets, args.jobs, os.path.join(logdir, "prepare-build.log"))
        print(f"mutate: built {' '.join(targets)} in {builddir}" if ok else
              f"mutate: the build failed; see {logdir}/prepare-build.log")
        return 0 if ok else 2
    started = datetime.datetime.now()
    t0 = time.time()
    runnable = [m for m in mutants if m.id not in problems]
    targets = sorted({p for m in runnable for p in m.tests})
    print(f"mutate: {len(mutants)} mutants, {len(problems)} stale; source {source}; build {builddir}; logs {logdir}")

    try:
        if runnable and not args.no_baseline:
            print(f"mutate: baseline: building {' '.join(targets)}", flush=True)
            ok, _ = build(builddir, targets, args.jobs, os.path.join(logdir, "baseline-build.log"))
            if not ok:
                print(f"mutate: the unchanged source does not build; see {logdir}/baseline-build.log", file=sys.stderr)
                return 2
            bad = []
            for program, gfilter in sorted({(p, f) for m in runnable for p, f in m.tests.items()}):
                got = run_tests(builddir, program, gfilter, args.timeout, os.path.join(logdir, "baseline-test.log"))
                if got != "pass":
                    bad.append(f"{program} --gtest_filter={gfilter}: {got}")
            if bad:
                print("mutate: the tests fail on the unchanged source; nothing mutated:\n  " + "\n  ".join(bad),
                      file=sys.stderr)
                return 2
            print(f"mutate: baseline passes ({time.time() - t0:.0f} s)", flush=True)

        results = []
        for m in mutants:
            if m.id in problems:
                results.append({"mutant": m, "result": "stale", "detail": problems[m.id]})
                print(f"[{len(results):2}/{len(mutants)}] {m.id:38} stale: {problems[m.id]}", flush=True)
                continue
            path = os.path.join(source, m.file)
            original_file = read(path)
            entry = {"id": m.id, "path": path, "original": m.original, "replacement": m.replacement,
                     "file": original_file}
            t = time.time()
            with open(journal_path(builddir), "w", encoding="utf-8") as f:
                json.dump(entry, f)
            try:
                write(path, original_file.replace(m.original, m.replacement, 1))
                log = os.path.join(logdir, m.id)
                ok, out = build(builddir, m.tests.keys(), args.jobs, log + ".build.log")
                if not ok:
                    result, detail = "does not compile", f"see {log}.build.log"
                else:
                    fails = []
                    for program, gfilter in m.tests.items():
                        got = run_tests(builddir, program, gfilter, args.timeout, f"{log}.{program}.log")
                        if got != "pass":
                            fails.append(got)
                    result = "caught" if fails else "missed"
                    detail = "; ".join(fails) if fails else "every test passed"
            finally:
                # No signal may stop the restore half-way.
                blocked = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM, signal.SIGHUP})
                try:
                    if put_back(path, m.original, m.replacement, original_file):
                        os.remove(journal_path(builddir))
                finally:
                    signal.pthread_sigmask(signal.SIG_SETMASK, blocked)
            results.append({"mutant": m, "result": result, "detail": detail})
            print(f"[{len(results):2}/{len(mutants)}] {m.id:38} {result:8} {detail} ({time.time() - t:.0f} s)",
                  flush=True)
    except (KeyboardInterrupt, Interrupted) as e:
        print(f"\nmutate: stopped ({e or 'Ctrl-C'}); the source is restored", file=sys.stderr)
        return 2
    finally:
        if runnable:  # the binaries back to the unchanged source
            build(builddir, targets, args.jobs, os.path.join(logdir, "restore-build.log"))

    caught = sum(r["result"] == "caught" for r in results)
    missed = [r for r in results if r["result"] == "missed"]
    other = [r for r in results if r["result"] not in ("caught", "missed")]
    print(f"\nmutate: {caught} of {caught + len(missed)} mutants caught"
          + (f"; {len(other)} stale or not compiling" if other else "")
          + f" ({(time.time() - t0) / 60:.1f} min, {platform.node()}, {os.cpu_count()} cores, {started:%Y-%m-%d})")
    for r in missed:
        print(f"  missed: {r['mutant'].id}: {r['mutant'].what}")
    for r in other:
        print(f"  {r['result']}: {r['mutant'].id}: {r['detail']}")
    listed = [r for r in results if r["mutant"].listed]
    if listed:
        print(f"  issue 26's behaviours: {sum(r['result'] == 'caught' for r in listed)} of {len(listed)} caught")
    if args.report:
        with open(args.report, "w", encoding="utf-8") as f:
            f.write(markdown(results, started, time.time() - t0))
    return 0 if caught == len(results) else 1


if __name__ == "__main__":
    sys.exit(main())
