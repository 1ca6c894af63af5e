"""Sampled mutants (issue 40): bugs nobody here chose, drawn from the code itself.

tools/mutate.py's table holds mutants the test writers picked; this mode asks
whether the tests catch bugs a rule-based tool writes. Contract:

- The mutants: universalmutator's (Groce et al., github.com/agroce/universalmutator,
  maintained) regular-expression rules for C++ (universal.rules, cpp.rules,
  c_like.rules: the set its `mutate FILE cpp` uses), applied through its own
  `mutator.mutants_regexp`, string-literal-only changes skipped (its default),
  to every .cpp and .h of FOLDERS. Comment lines and #include lines are left
  out before anything is built (they cannot change the program). We call the
  library rather than its `mutate` command because that command builds each
  mutant with a command of its own; here the build is CMake's, incremental.
  universalmutator is not vendored: `--um DIR` names an installed or unpacked
  copy (pip install universalmutator, or its source tree). Its `comby` mode
  is not used, so a missing `comby` package is stood in for.
- The sample: the pool sorted, shuffled with random.Random(SEED), walked in
  that order until N mutants compiled and were not equivalent. Same seed and
  same source: same sample. A mutant is "equivalent" when every object file
  it rebuilt is byte-identical to the unmutated build's (trivial compiler
  equivalence; the build has no debug info, so only code counts).
- A mutant is "killed" when any test of the whole native suite fails: first
  the test programs of its own folder (STAGE1, whole, no filter; a quick way
  to a kill), then, if they pass, every other test program whole, two at a
  time, and CTest's script tests (serve.*, grading.*): the whole native
  suite, `ctest -LE browser`'s tests, stopping at the first failure; a
  failing case is run again alone and counts only if it fails again.
  Whole programs rather than CTest's process a case: the same tests in
  about half the time (docs/RELIABILITY.md). "survived" means the whole
  suite passed.
- Resumable, across checkouts: each decided mutant is a line of RECORD's
  results.jsonl and the campaign's seed and source commit are RECORD's
  source.json, both tracked, committed after each session's run (a build
  folder does not outlive a fresh checkout: the first 69 rows were lost so).
  A run skips the mutants already there. The source is the snapshot's
  (SNAP/src), fixed for the campaign; when SNAP/src is gone, it is made again
  from the recorded commit (git archive) if the tree was clean when it was
  recorded, or else the run is a recheck (below). Touch SNAP/PAUSE to pause
  between mutants.
- Crash-safe: the mutated file's original text is journalled before the
  write and put back by the next run.
- Rechecks (--sample-recheck): the snapshot moves to the working tree, and
  every survivor is tried again there, found by its text (the line it
  changed, nearest its old number), so a test written since can kill it.
  The row written last for a mutant is its verdict. The walk then goes on
  over the new source's candidates, with the same seed, skipping any
  mutant already decided under another line number (its old line found
  again nearest where it was, the same new text).
- Shown equivalent: EQUIVALENT below, a mutant's id and one line why no
  input the program can be given tells it from the original. These leave
  the count, as trivially equivalent ones do.
"""
import glob
import hashlib
import json
import os
import random
import re
import shutil
import subprocess
import sys
import time
import types

FOLDERS = ["plan", "shader", "gl", "grade", "process", "pipeline"]
RULES = ["universal.rules", "cpp.rules", "c_like.rules"]
# Each folder's own test programs: run whole before the full suite, because
# they kill most mutants in seconds.
STAGE1 = {"plan": ["test_plan"], "shader": ["test_shader"], "gl": ["test_shaderlog", "test_render"],
          "grade": ["test_grade"], "process": ["test_render", "test_glman"], "pipeline": ["test_pipeline"]}
from mutate import REPO, kill_session  # noqa: E402  (the repository both modes work in)

# Tracked: the campaign's record outlives the build folder (see Resumable).
RECORD = os.path.join(REPO, "tools", "mutate-sample")
RESULTS = os.path.join(RECORD, "results.jsonl")
META = os.path.join(RECORD, "source.json")
# Survivors read and shown equivalent (docs/RELIABILITY.md repeats the why).
EQUIVALENT = {
    "src/plan/draw_units.cpp:20:716581da": "size_t(-1) is never below a vector's size, so t = -1 still fails the next test",
    "src/gl/renderer_internal.h:46:e3287010": "a watch Level's height is set (watch_gpu.cpp) before the Level is stored or read",
    "src/gl/texel_rate.cpp:19:bdeed1cf": "for gl_VertexID 0, 1, 2 (one triangle), (id << 1) & 3 and (id << 1) & 2 are both 0, 2, 0",
    "src/plan/plan_textures.cpp:116:7844c03b": "both callers of textureHead set isFile = false before the call",
    "src/gl/renderer_internal.h:31:8fc5e73c": "a Target's depth only decides a depth clear (on a framebuffer with no depth "
                                              "attachment, a no-op by the GL spec) and a glDeleteRenderbuffers (which "
                                              "ignores a name that is no renderbuffer): 0 and -1 draw and fail alike",
    "src/shader/watch_rewrite.cpp:234:d57e2336": "an ivec4's count 5 is written as 5 * 0.25 into an 8-bit channel of the "
                                                 "info target, which saturates at 1, the bytes of 4 (every reader clamps to 4 too)",
    "src/shader/compat_rewrite.cpp:56:ee2d5297": "definesOf only ever reads kGstapPrelude or \"\", every line of which is "
                                         "'#define NAME VALUE', which the guard lets through",
    "src/process/batch.cpp:315:15fa4577": "a time-out's `ms <= limit` made `<`: they differ only when the elapsed time, "
                                           "a steady clock's nanoseconds read at a poll, equals the limit exactly, "
                                           "which no script or setting can choose",
    "src/grade/safe_unzip.cpp:108:75c5bc73": "the unpacking buffer 64 x 1023 bytes instead of 64 x 1024: the loop reads "
                                             "min(buffer, declared + 1 - got) until the entry ends, so any size above "
                                             "0 writes the same bytes and finds the same extra byte",
    "src/gl/watch_gpu.cpp:259:0ac978a1": "the watch's targets kept, not deleted, when its framebuffer is incomplete "
                                         "(float targets not renderable): every later frame finds the same size, "
                                         "skips making them, fails the same check and draws and says the same; "
                                         "they go when the watch stops or the size changes",
    "src/plan/plan_shapes.cpp:44:27e3c854": "of the shapes made from numbers (geometry/shape_registry.cpp), only WireTorus "
                                            "sorts at or after \"WireTorus\" (WireBox ... WireTeapot all before it)",
    "src/shader/glsl_lexer.cpp:104:a54b00f9": "a word's end starts at i + 1 <= size (i < size is checked first) and "
                                              "grows by one: `end < size` and `end != size` stop it at the same place",
    "src/plan/plan.h:77:e647a978": "Wrap's Repeat and Clamp swap numbers, and no code reads one as a number: each is "
                                   "named where set, compared and turned into GL's (glWrap's switch); the one `Wrap w{}` "
                                   "is overwritten by parseTextureWrap or dropped with its error",
    "src/gl/watch_gpu.cpp:320:b7999d5f": "a `continue;` added as the last statement of the sums' loop body: it goes "
                                         "where the body's end goes, to the next i",
    "src/process/batch.cpp:123:3e399787": "the worker count's floor 1 made -1: it differs only for --jobs below 1, which "
                                          "batch's CLI refuses (Range 1..64), grading passes 1 or batch's value, and "
                                          "a batch of no jobs runs no loop with 0 workers or 1",
    "src/gl/watch_gpu.cpp:371:526b0e5f": "a watch read-back rectangle's width floor 1 made 0: its callers ask for the "
                                         "whole picture (w -1) or one pixel (1 x 1, the probe), never a width of 0",
    "src/grade/grading.h:52:5b80faa7": "Comparison's worstTile default 1 made 2: a measured comparison sets 1 first "
                                       "(grading.cpp), so the default stays only on pictures that cannot be compared "
                                       "(SSIM 0, PSNR 0), where 1 and 2 are alike above the fixed tile threshold 0.90 "
                                       "and above any measured tile they are the minimum with",
    "src/shader/glsl_scan.cpp:64:58be7657": "lineOf's `end == npos ? npos : end - at` made `end > npos ? ...`: for "
                                            "end == npos the count npos - at is still past the text's end "
                                            "(at <= size), and substr takes the rest either way",
    "src/process/session.cpp:32:c09ff817": "openSession's unknown-backend refusal skipped: every subcommand that opens "
                                           "a session reads --backend through addBackendOption, which refuses an "
                                           "unknown name before (sheet did not: fixed with this finding, "
                                           "CliUsage.UnknownBackendIsTheSameUsageErrorForEverySubcommand)",
    "src/gl/uniform_upload.cpp:202:ed69357c": "a matrix array's loop bound max(size, 1) made max(size, 0): an "
                                              "ActiveUniform's size comes only from glGetActiveUniform, 1 or more "
                                              "for an active uniform (its default, 1, when the call fails)",
    "src/process/batch.cpp:256:3b65d5e7": "the payload read even when the header check failed: our worker writes "
                                          "each 16-byte header whole (under PIPE_BUF, atomic), so a failed check is "
                                          "a dead worker's EOF, where the header reads as zeros: a 0-byte payload, "
                                          "then kind 0 fails the Result check, the crash path either way",
    "src/grade/grading.cpp:91:6e933dfc": "comparable(solution, student) for (student, solution): sizes and types are "
                                         "compared both ways alike; only 'not empty' moves to the solution, and an empty "
                                         "picture of either side is 0x0 while the other is not, or both are empty: false",
    "src/grade/grade_report.cpp:14:ad95e50a": "the review order's error rank 0 made -1: it only sorts, and every verdict "
                                              "is one of the four (grading makes no other, a read row with another is "
                                              "refused), so errors still come first and 0 for an unknown is never used",
    "src/grade/grade_report.cpp:209:0b0727d7": "a continue added as the last statement of a loop body: it goes "
                                              "where the body's end goes",
    "src/shader/watch_spec.cpp:53:d1e7868e": "d >= size made d == size: d starts at i + 1 <= size and stops at "
                                             "size at most, so the two agree",
    "src/gl/texel_rate.cpp:34:0631c6fc": "the texel-rate shader's step 1/size made -1/size: its taps mirrored, "
                                         "the same count of bilinear fetches over the same spread, into a picture "
                                         "nothing reads (only the time is kept): the same work measured",
    "src/gl/renderer_prepare.cpp:53:e8f6be17": "prepare's errorCount() == errorsBefore made <=: the count only "
                                               "grows while prepare runs (Diagnostics::clear is never called in it), "
                                               "so it is never below",
    "src/process/batch.cpp:136:569828d7": "the scheduler's skip of a slot with no worker, pid <= 0 made < 0: in "
                                          "the parent a slot's pid is -1 (none, or fork failed) or a child's; 0 is "
                                          "only the child's own view, and the child runs workerMain, which never returns",
    "src/process/watchdog.cpp:107:ffbacd55": "the child's progress pipe marked closed on a read of 1 byte, not at its "
                                             "end: records are written whole (under PIPE_BUF), so no read is 1 byte, "
                                             "and the end comes only as the child exits (it holds the write end to "
                                             "_exit, forks and execs nothing): the loop then polls until the reap, "
                                             "the same output",
    "src/process/child_guard.cpp:37:85e60e69": "a child whose parent died before prctl exits 255, not 1: its parent, "
                                               "the one glimmer that could read the code, is gone; the process that "
                                               "adopts it (init) reads no code",
    "src/gl/shader_build.cpp:191:57a5bbda": "an initialiser of more than 4 values skipped, > 4 made > -1 (never, "
                                            "size_t): takeUniformInitializers keeps a value only when its count is "
                                            "its type's, a scalar's or vecN's (1 to 4), so no initialiser has more",
    "src/gl/renderer_sliced.cpp:106:b9d611ab": "progress of a frame with nothing to draw 0.999 made 0.1: the viewer "
                                               "asks only after renderSlice returned false, which stops only at a pass "
                                               "needed and asked for, whose cost (rows >= 1 times a time per row > 0, "
                                               "measured or the fallback) makes the total > 0",
    "src/process/watchdog.cpp:93:f341eb4a": "at the time-out the write end closed again instead of the read end: "
                                            "the write end was closed before the loop and the parent opens nothing "
                                            "since, so that close fails (EBADF), and the read end left open closes "
                                            "as main returns runWithTimeout's 1, its only caller",
    "src/gl/renderer.cpp:182:573fe790": "clearIsHidden's `if (!mesh) return false` taken out: only a quad "
                                        "(coversViewport) hides a Clear, a quad's mesh is always made, and a pass "
                                        "drawn is a needed one, whose meshes uploadMeshes uploads, so it is never null",
    "src/shader/uninitialized_globals.cpp:45:b7c26131": "an unmatched '[' tested as mate == 0, not == npos: npos "
                                                        "is also >= to, so the test beside it returns false the same; "
                                                        "a '[' after the name (k >= 1) is never matched by token 0",
    "src/process/batch.cpp:28:8f498aad": "a slot's pid starting at 0, not -1: every test of a slot's pid is > 0 or "
                                         "<= 0, where 0 and -1 agree, and a fork that fails sets -1 itself",
    "src/gl/renderer.h:158:3d1ab648": "the texel-rate probe's default warm-up 200 ms made 201: it only draws that "
                                       "much longer before the timed runs (for a GPU to raise its clocks); what is "
                                       "timed and every output but a time, which 1 ms of warm-up moves less than "
                                       "run-to-run noise, are the same",
    "src/gl/shader_build.cpp:246:fb6e23dc": "makeProgram's stage loop `k < size` made `k != size`: k starts at 0 and "
                                            "grows by one, and the body changes neither k nor the stages, so both stop "
                                            "at the same place",
    "src/process/batch.cpp:59:1b52555e": "a worker's close(up[-1]) for close(up[0]): built at -O1 it reads the stack "
                                         "word below up, the high half of the last call's return address into the "
                                         "PIE binary (0x55xx-0x56xx, over 21,000, past the 20,000-descriptor limit), "
                                         "so close fails (EBADF); the worker then keeps its result pipe's read end, "
                                         "which it never reads and nothing sees: the parent closes its own end only "
                                         "after killing the worker or when it is idle and writes nothing more",
}
JOURNAL = ".sample-journal.json"


def load_universalmutator(um_dir):
    if um_dir:
        sys.path.insert(0, os.path.abspath(um_dir))
    try:
        import comby  # noqa: F401  (only its comby mode needs it)
    except ImportError:
        stand_in = types.ModuleType("comby")
        stand_in.Comby = None
        sys.modules["comby"] = stand_in
    try:
        from universalmutator import mutator
    except ImportError as e:
        sys.exit(f"mutate: universalmutator is not importable ({e}); pip install universalmutator, "
                 "or --um DIR with its source tree")
    return mutator


def skippable(line):
    s = line.strip()
    return (not s or s.startswith("//") or s.startswith("/*") or s.startswith("*") or s.startswith("#include")
            or s.startswith("#pragma"))


def pool(source, mutator):
    """Every candidate mutant: (id, folder, file, line number, new line, rule,
    the line it replaces)."""
    out = []
    quiet = open(os.devnull, "w")
    for folder in FOLDERS:
        files = sorted(glob.glob(os.path.join(source, "src", folder, "*.cpp")) +
                       glob.glob(os.path.join(source, "src", folder, "*.h")))
        for path in files:
            rel = os.path.relpath(path, source)
            with open(path, encoding="utf-8", newline="") as f:
                lines = f.readlines()
            stdout, sys.stdout = sys.stdout, quiet  # the library prints its rule list per file
            try:
                found = mutator.mutants_regexp(lines, ruleFiles=RULES, ignorePatterns=[], ignoreStringOnly=True)
            finally:
                sys.stdout = stdout
            for lineno, new, rule, _ in found:
                if skippable(lines[lineno - 1]):
                    continue
                digest = hashlib.sha1(new.encode()).hexdigest()[:8]
                out.append((f"{rel}:{lineno}:{digest}", folder, rel, lineno, new, rule[0].strip(), lines[lineno - 1]))
    out.sort()
    return out


def objects(build):
    """{object file: sha1} of every object in the build."""
    found = {}
    for root, _, files in os.walk(build):
        for f in files:
            if f.endswith(".o"):
                p = os.path.join(root, f)
                with open(p, "rb") as fh:
                    found[p] = hashlib.sha1(fh.read()).hexdigest()
    return found


def run(cmd, cwd, log, timeout):
    """The exit status (or "timeout"), the output in `log`: the table mode's runner."""
    from mutate import run_logged
    return run_logged(cmd, cwd, log, timeout)[0]


def tail(log, n=6):
    with open(log, errors="replace") as f:
        return " | ".join(l.strip() for l in f.read().splitlines()[-n:] if l.strip())[:400]


def failed_ctest(log):
    with open(log, errors="replace") as f:
        text = f.read()
    names = re.findall(r"^\s*\d+ - (\S+) \(", text, re.M)
    return ", ".join(names[:5]) or tail(log, 3)


# The programs that take longest whole, started first so the lanes end together
# (tools/shuffled-tests.sh's order, measured there).
LONGEST = ["test_cli", "test_viewer", "test_render", "test_glman", "test_pipeline", "test_serve", "test_grade"]
# CTest's native tests that are not a test program's case: scripts and the
# programs' own listing checks.
SCRIPT_TESTS = r"^(serve\.|grading\.|test_[a-z]+\.lists_tests$)"


def failed_cases(log):
    """The cases a whole gtest program said failed."""
    with open(log, errors="replace") as f:
        return sorted(set(re.findall(r"^\[  FAILED  \] ([\w/]+\.[\w/]+)", f.read(), re.M)))


def native_suite(build, jobs, log, done=()):
    """"" when every native test passes, else what failed. Every test program
    whole (their cases in one process each, as tools/shuffled-tests.sh runs
    them; `done`: those that already passed whole for this mutant), `jobs` at
    a time, the longest first; then CTest's script tests (serve.*, grading.*).
    A failure must repeat to count: a program's failed cases are run again
    alone, a program that timed out or failed with no case named is run again
    whole. The viewer's tests click a real window, and on a machine loaded
    by other work one failed once unmutated and passed alone. Stops at the
    first failure that repeats. A program runs with --gtest_fail_fast: a
    kill is known at its first failing case, not after the program's other
    cases (test_cli whole takes minutes); when that failure does not repeat,
    the cases it skipped run, the ones that did not repeat left out."""
    tests = os.path.join(build, "tests")
    found = sorted(f for f in os.listdir(tests) if f.startswith("test_") and os.access(os.path.join(tests, f), os.X_OK)
                   and os.path.isfile(os.path.join(tests, f)) and f not in done)
    todo = [p for p in LONGEST if p in found] + [p for p in found if p not in LONGEST]
    running, flaky = {}, []

    def confirm(program, rc, plog):
        """A failure's names if it repeats, else ""."""
        left_out = []
        while rc != 0:
            cases = failed_cases(plog) if rc != "timeout" else []
            again = [os.path.join(tests, program)] + ([f"--gtest_filter={':'.join(cases)}"] if cases else [])
            if run(again, tests, f"{plog}.again.log", 1200) != 0:
                what = ", ".join(cases[:5]) if cases else ("timed out" if rc == "timeout" else f"exit {rc}")
                return f"{program}: {what}"
            flaky.append(f"{program} ({', '.join(cases[:3]) or 'whole'})")
            if not cases:
                return ""  # the whole program ran again and passed
            # Fail-fast stopped the program at these cases: the rest has not run.
            left_out += cases
            plog = f"{plog}.rest.log"
            rc = run([os.path.join(tests, program), "--gtest_fail_fast", f"--gtest_filter=-{':'.join(left_out)}"],
                     tests, plog, 1800)
        return ""

    try:
        while todo or running:
            while todo and len(running) < jobs:
                program = todo.pop(0)
                plog = f"{log}.{program}.whole.log"
                out = open(plog, "w")
                running[program] = (subprocess.Popen([os.path.join(tests, program), "--gtest_fail_fast"], cwd=tests, stdout=out,
                                                     stderr=subprocess.STDOUT, start_new_session=True),
                                    out, plog, time.time())
            time.sleep(0.5)
            for program, (proc, out, plog, began) in list(running.items()):
                rc = proc.poll()
                if rc is None and time.time() - began > 1800:
                    kill_session(proc.pid)
                    proc.wait()
                    rc = "timeout"
                if rc is None:
                    continue
                out.close()
                del running[program]
                if rc != 0:
                    failed = confirm(program, rc, plog)
                    if failed:
                        return failed
    finally:
        for proc, out, _, _ in running.values():
            kill_session(proc.pid)
            proc.wait()
            out.close()
    rc = run(["ctest", "--test-dir", build, "-R", SCRIPT_TESTS, "-j", str(jobs), "--timeout", "600"], build,
             f"{log}.ctest.log", 3600)
    if rc != 0:
        names = failed_ctest(f"{log}.ctest.log")
        if run(["ctest", "--test-dir", build, "--rerun-failed", "--timeout", "600"], build, f"{log}.rerun.log", 3600) != 0:
            return "ctest: " + names
        flaky.append(names)
    if flaky:
        print(f"mutate: {'; '.join(flaky)} failed and then passed alone (not counted as a kill)", flush=True)
    return ""


def compile_commands(build):
    """{source file: (directory, command)} from CMake's compile_commands.json."""
    with open(os.path.join(build, "compile_commands.json"), encoding="utf-8") as f:
        return {os.path.realpath(e["file"]): (e["directory"], e["command"]) for e in json.load(f)}


def quick_compile(path, build, commands, log):
    """The one translation unit first: a mutant that does not compile is told
    in seconds, without make walking the tree. For a header, a file that
    includes it, checked for syntax only. True when it compiles."""
    path = os.path.realpath(path)
    if path.endswith(".cpp"):
        entry = commands.get(path)
        if not entry:
            return True
        return run(["sh", "-c", entry[1]], entry[0], log, 600) == 0
    header = os.path.relpath(path, os.path.join(os.path.dirname(os.path.dirname(path))))
    sibling = path[:-2] + ".cpp"
    users = [sibling] if sibling in commands else [f for f in commands if f.endswith(".cpp") and
                                                    f'#include "{header}"' in open(f, errors="replace").read()]
    if not users:
        return True
    directory, command = commands[users[0]]
    return run(["sh", "-c", re.sub(r" -o \S+", " -o /dev/null", command) + " -fsyntax-only"], directory, log, 600) == 0


def git_head():
    r = subprocess.run(["git", "-C", REPO, "rev-parse", "HEAD"], capture_output=True, text=True)
    return r.stdout.strip()


def tree_clean():
    """True when the working tree is its HEAD commit (the record aside), so
    the snapshot can be made again from the commit alone."""
    r = subprocess.run(["git", "-C", REPO, "status", "--porcelain"], capture_output=True, text=True)
    rel = os.path.relpath(RECORD, REPO)
    return r.returncode == 0 and all(l[3:].startswith(rel) for l in r.stdout.splitlines())


def source_from_commit(snap, commit):
    """SNAP/src made again from a recorded commit; None when git cannot."""
    src = os.path.join(snap, "src")
    shutil.rmtree(src, ignore_errors=True)
    os.makedirs(src)
    archive = subprocess.run(["git", "-C", REPO, "archive", commit], capture_output=True)
    if archive.returncode != 0 or subprocess.run(["tar", "-x", "-C", src], input=archive.stdout).returncode != 0:
        return None
    print(f"mutate: {src} made again from {commit[:10]}, the campaign's recorded source", flush=True)
    return src


def configure(snap, source):
    build = os.path.join(snap, "build")
    if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
        # -O1 and no debug info: quicker builds and links, and object files
        # that differ only when the code does (the equivalence test above).
        subprocess.run(["cmake", "-S", source, "-B", build, "-DCMAKE_BUILD_TYPE=RelWithDebInfo",
                        "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -DNDEBUG", "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -DNDEBUG",
                        "-DGLIMMER_TESTS=ON"], check=True, stdout=subprocess.DEVNULL)
    return build


def recover(snap):
    j = os.path.join(snap, JOURNAL)
    if os.path.exists(j):
        with open(j, encoding="utf-8") as f:
            entry = json.load(f)
        with open(entry["path"], "w", encoding="utf-8", newline="") as f:
            f.write(entry["file"])
        os.remove(j)
        print(f"mutate: put back {entry['path']}, left mutated by an earlier run", flush=True)


def decided():
    out = {}
    if os.path.exists(RESULTS):
        with open(RESULTS, encoding="utf-8") as f:
            for line in f:
                if line.strip():
                    r = json.loads(line)
                    out[r["id"]] = r
    return out


def report(results, seed, want, out=None):
    rows = list(results.values())
    counted = [r for r in rows if counts(r)]
    shown = [r for r in rows if r["id"] in EQUIVALENT]
    lines = [f"Sampled mutants (seed {seed}, {len(counted)} of the {want} wanted counted; "
             f"{sum(r['result'] == 'no compile' for r in rows)} did not compile, "
             f"{sum(r['result'] == 'equivalent' for r in rows)} equivalent by object code, "
             f"{len(shown)} shown equivalent):", "",
             "| folder | counted | killed | survived | score |", "|---|---|---|---|---|"]
    for folder in FOLDERS:
        c = [r for r in counted if r["folder"] == folder]
        k = sum(r["result"] == "killed" for r in c)
        lines.append(f"| src/{folder} | {len(c)} | {k} | {len(c) - k} | "
                     f"{(100 * k / len(c)):.0f}% |" if c else f"| src/{folder} | 0 | | | |")
    k = sum(r["result"] == "killed" for r in counted)
    if counted:
        lines.append(f"| all | {len(counted)} | {k} | {len(counted) - k} | {(100 * k / len(counted)):.0f}% |")
    rechecked = [r for r in counted if r.get("recheck") and r["result"] == "killed"]
    if rechecked:
        lines += ["", "Survivors killed since, by a test written for them (rechecked):", ""]
        for r in sorted(rechecked, key=lambda r: r["id"]):
            lines.append(f"- `{r['file']}:{r['line']}` at {r['recheck'][:10]}: {r['detail']}")
    survivors = [r for r in counted if r["result"] == "survived"]
    if survivors:
        lines += ["", "Survivors:", ""]
        for r in sorted(survivors, key=lambda r: r["id"]):
            lines.append(f"- `{r['file']}:{r['line']}`: `{r['was'].strip()}` -> `{r['new'].strip()}`")
    if shown:
        lines += ["", "Shown equivalent:", ""]
        for r in sorted(shown, key=lambda r: r["id"]):
            lines.append(f"- `{r['file']}:{r['line']}`: {EQUIVALENT[r['id']]}")
    text = "\n".join(lines) + "\n"
    print(text)
    if out:
        with open(out, "w", encoding="utf-8") as f:
            f.write(text)


def counts(row):
    """A mutant that counts toward the sample: it compiled, and it is not
    equivalent, trivially or shown."""
    return row["result"] in ("killed", "survived") and row["id"] not in EQUIVALENT


def pause(snap):
    while os.path.exists(os.path.join(snap, "PAUSE")):
        time.sleep(5)


def find_line(path, was, near):
    """The number of the line whose text is `was`, nearest `near`; None when
    no line is."""
    with open(path, encoding="utf-8", newline="") as f:
        lines = f.readlines()
    hits = [i + 1 for i, line in enumerate(lines) if line == was]
    return min(hits, key=lambda n: abs(n - near)) if hits else None


class Trial:
    """One mutant tried: written, built, tested, and the file and the
    objects put back, whatever happened."""

    def __init__(self, snap, source, build, logs, base, baseline_dir, commands, args):
        self.snap, self.source, self.build, self.logs = snap, source, build, logs
        self.base, self.baseline_dir, self.commands, self.args = base, baseline_dir, commands, args

    def run(self, folder, rel, lineno, new):
        """(result, detail, seconds)."""
        build, args = self.build, self.args
        path = os.path.join(self.source, rel)
        with open(path, encoding="utf-8", newline="") as f:
            lines = f.readlines()  # numbered as pool() and find_line() number them
        original = "".join(lines)
        lines[lineno - 1] = new
        with open(os.path.join(self.snap, JOURNAL), "w", encoding="utf-8") as f:
            json.dump({"path": path, "file": original}, f)
        t0 = time.time()
        changed, lost = [], []
        try:
            with open(path, "w", encoding="utf-8", newline="") as f:
                f.write("".join(lines))
            digest = hashlib.sha1(new.encode()).hexdigest()[:8]
            log = os.path.join(self.logs, f"{rel}_{lineno}_{digest}".replace("/", "_"))
            if not quick_compile(path, build, self.commands, log + ".build.log"):
                rc = 1
            else:
                rc = run(["cmake", "--build", build, "-j", str(args.jobs)], build, log + ".build.log", 1800)
            now = objects(build)
            changed = [p for p, h in now.items() if self.base.get(p) != h]
            lost = [p for p in self.base if p not in now]  # a failed compile removes its object
            if rc != 0:
                result, detail = "no compile", tail(log + ".build.log", 3)
            elif not changed:
                result, detail = "equivalent", "the same object code"
            else:
                result, detail = "survived", "every native test passed"
                for program in STAGE1[folder]:
                    exe = os.path.join(build, "tests", program)
                    rc = run([exe], os.path.join(build, "tests"), f"{log}.{program}.log", args.timeout)
                    if rc != 0:
                        result, detail = "killed", f"{program} ({'timed out' if rc == 'timeout' else 'exit %s' % rc})"
                        break
                if result == "survived":
                    failed = native_suite(build, args.jobs, log, done=STAGE1[folder])
                    if failed:
                        result, detail = "killed", failed
        finally:
            with open(path, "w", encoding="utf-8", newline="") as f:
                f.write(original)
            # The unmutated objects back, newer than the source, so the next
            # build relinks without compiling them again.
            for p in changed + lost:
                shutil.copy2(os.path.join(self.baseline_dir, os.path.relpath(p, build)), p)
                os.utime(p)
            os.remove(os.path.join(self.snap, JOURNAL))
        return result, detail, round(time.time() - t0)


def main(args):
    snap = os.path.abspath(args.snapshot or os.path.join("build-mut", "sample"))
    from mutate import sync_snapshot  # the copy of the working tree, as the table's mode makes it
    results = decided()
    if args.sample_report_only:
        report(results, args.seed, args.sample, args.report)
        return 0
    head = git_head()
    os.makedirs(snap, exist_ok=True)
    os.makedirs(RECORD, exist_ok=True)
    recover(snap)

    def save(meta):
        with open(META, "w") as f:
            json.dump(meta, f, indent=1)
            f.write("\n")

    if os.path.exists(META) and results and not args.sample_reset:
        with open(META) as f:
            meta = json.load(f)
        if meta.get("seed") != args.seed:
            sys.exit(f"mutate: this campaign's seed is {meta.get('seed')}; --sample-reset to start over")
        source = os.path.join(snap, "src")  # the campaign's copy, as the last run or recheck left it
        if not args.sample_recheck and not os.path.exists(os.path.join(source, "CMakeLists.txt")):
            source = source_from_commit(snap, meta["commit"]) if meta.get("clean") else None
            if source is None:
                print("mutate: the campaign's source is gone and cannot be made again from its commit: "
                      "rechecking against the working tree", flush=True)
                args.sample_recheck = True
        if args.sample_recheck:
            source = sync_snapshot(snap)  # the campaign moves to the working tree
            meta.setdefault("rechecked", []).append({"commit": head, "at": time.strftime("%Y-%m-%d %H:%M")})
            meta["commit"], meta["clean"] = head, tree_clean()
            save(meta)
    else:
        if args.sample_reset and os.path.exists(RESULTS):
            os.remove(RESULTS)
            results = {}
        source = sync_snapshot(snap)
        save({"seed": args.seed, "commit": head, "clean": tree_clean(), "started": time.strftime("%Y-%m-%d %H:%M")})
    build = configure(snap, source)
    logs = os.path.join(snap, "logs")
    os.makedirs(logs, exist_ok=True)
    mutator = load_universalmutator(args.um)
    candidates = pool(source, mutator)
    order = candidates[:]
    random.Random(args.seed).shuffle(order)
    print(f"mutate: {len(candidates)} candidate mutants in {', '.join('src/' + f for f in FOLDERS)}; "
          f"seed {args.seed}; {len(results)} decided already", flush=True)

    print("mutate: building the unmutated snapshot", flush=True)
    if run(["cmake", "--build", build, "-j", str(args.jobs)], build, os.path.join(logs, "baseline-build.log"), None) != 0:
        sys.exit(f"mutate: the unmutated snapshot does not build: {logs}/baseline-build.log")
    baseline_dir = os.path.join(snap, "baseline-objects")
    base = objects(build)
    # The unmutated suite must pass, or every mutant would read "killed":
    # at the start, and after a recheck moved the source.
    if not args.no_baseline and (not results or args.sample_recheck):
        failed = native_suite(build, args.jobs, os.path.join(logs, "baseline"))
        if failed:
            sys.exit(f"mutate: the native suite fails unmutated ({failed}); nothing mutated")
    shutil.rmtree(baseline_dir, ignore_errors=True)
    for p in base:
        d = os.path.join(baseline_dir, os.path.relpath(p, build))
        os.makedirs(os.path.dirname(d), exist_ok=True)
        shutil.copy2(p, d)

    commands = compile_commands(build)
    trial = Trial(snap, source, build, logs, base, baseline_dir, commands, args)
    def record(row):
        # Opened for each row, not held: a git command that rewrites the
        # file while the walk runs (a stash, a checkout) would leave a held
        # handle writing into the replaced, unlinked copy, and the rows lost.
        with open(RESULTS, "a", encoding="utf-8") as out:
            out.write(json.dumps(row) + "\n")
        results[row["id"]] = row

    if args.sample_recheck:
        survivors = [r for r in results.values() if r["result"] == "survived" and r["id"] not in EQUIVALENT
                     and r.get("recheck") != head]
        print(f"mutate: rechecking {len(survivors)} survivors against {head[:10]}", flush=True)
        for r in sorted(survivors, key=lambda r: r["id"]):
            pause(snap)
            lineno = find_line(os.path.join(source, r["file"]), r["was"], r["line"])
            if lineno is None:
                row = dict(r, result="gone", detail="its line is no longer in the source", recheck=head, seconds=0)
            else:
                result, detail, seconds = trial.run(r["folder"], r["file"], lineno, r["new"])
                row = dict(r, result=result, detail=detail, recheck=head, seconds=seconds, line_now=lineno)
            record(row)
            print(f"[recheck] {r['id']} {row['result']}: {row['detail']} ({row['seconds']} s)", flush=True)

    # A mutant decided at an older source, where its line now is: the same
    # mutant under another number is not drawn again (two equal lines of a
    # file are two places, and stay two mutants).
    decided_at = set()
    for r in results.values():
        now = find_line(os.path.join(source, r["file"]), r["was"], r.get("line_now", r["line"]))
        if now is not None:
            decided_at.add((r["file"], now, r["new"]))
    counted = sum(counts(r) for r in results.values())
    for cand in order:
        if counted >= args.sample or args.sample_recheck_only:
            break
        mid, folder, rel, lineno, new, rule, was = cand
        if mid in results or (rel, lineno, new) in decided_at:
            continue
        pause(snap)
        result, detail, seconds = trial.run(folder, rel, lineno, new)
        record({"id": mid, "folder": folder, "file": rel, "line": lineno, "was": was, "new": new, "rule": rule,
                "result": result, "detail": detail, "seconds": seconds, "commit": head})
        if counts(results[mid]):
            counted += 1
        print(f"[{counted}/{args.sample}] {mid} {result}: {detail} ({seconds} s)", flush=True)
    run(["cmake", "--build", build, "-j", str(args.jobs)], build, os.path.join(logs, "restore-build.log"), None)
    report(results, args.seed, args.sample, args.report)
    return 0
