#!/usr/bin/env python3
"""Mutation testing for Glimmer (issue 26): do the tests fail when the code breaks?

A table of small, plausible bugs (MUTANTS in tools/mutants.py: a file, an exact piece of its
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
  tools/mutate.py --sample 200 --seed 40 --um ~/universalmutator   # sampled mutants (issue 40)
  tools/mutate.py --sample 200 --sample-recheck --um ~/universalmutator  # survivors against new tests

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


from mutants import MUTANTS  # the table of bugs, one row each (tools/mutants.py)


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


def kill_session(pid):
    """Ends the session `pid` leads, every process group in it: a test
    program's viewer under xvfb-run is a group of its own, and killing the
    program's group alone left it and its Xvfb running, orphaned."""
    try:
        os.killpg(pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    subprocess.run(["pkill", "-KILL", "-s", str(pid)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def run_logged(cmd, cwd, log, timeout=None):
    """Runs `cmd` in a session of its own (so a timeout or Ctrl-C ends its
    children too); returns (exit status or 'timeout', output)."""
    with open(log, "w") as out:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            rc = p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            kill_session(p.pid)
            p.wait()
            rc = "timeout"
        except BaseException:
            kill_session(p.pid)
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
    sample = ap.add_argument_group("sampled mutants (issue 40; tools/mutate_sample.py says how)")
    sample.add_argument("--sample", type=int, metavar="N",
                        help="draw mutants with universalmutator until N compiled, non-equivalent ones ran "
                             "(with --snapshot DIR, default build-mut/sample); resumable")
    sample.add_argument("--seed", type=int, default=40, help="the sample's seed (default 40)")
    sample.add_argument("--um", help="universalmutator's source tree, when it is not installed")
    sample.add_argument("--sample-reset", action="store_true", help="forget the campaign's results and start over")
    sample.add_argument("--sample-report-only", action="store_true", help="print the campaign's score and stop")
    sample.add_argument("--sample-recheck", action="store_true",
                        help="move the campaign's source to the working tree and try every survivor again, "
                             "then go on drawing")
    sample.add_argument("--sample-recheck-only", action="store_true",
                        help="with --sample-recheck: stop after the survivors")
    args = ap.parse_args()
    if args.sample is not None:
        import mutate_sample
        return mutate_sample.main(args)

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
