#!/usr/bin/env python3
"""A lab's load on `glimmer serve`, measured (issue 41, item 6): STUDENTS
simulated students (real HTTP clients, one thread each) join by their links,
save every 2 s as the page does while its student types, poll /api/me every
2 s as the page does, and hand in three times; the teacher's page polls the
class every 2 s. Prints failed requests, save latency (p50/p95/max), how long
until every hand-in was graded, and the server's memory (peak RSS, threads).

  tools/serve-load.py GLIMMER [--students 200] [--seconds 60] [--jobs 2]

Not a test (its figures depend on the machine): docs/PERFORMANCE.md keeps
them. The lab is the blur exercise of tests/data/grading."""
import argparse
import os
import random
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tests", "serve"))
from serve_lib import Client, Server, make_lab, make_page, read_links  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("glimmer")
ap.add_argument("--students", type=int, default=200)
ap.add_argument("--seconds", type=float, default=60)
ap.add_argument("--jobs", type=int, default=2)
ap.add_argument("--seed", type=int, default=41)
args = ap.parse_args()

work = tempfile.mkdtemp(prefix="glimmer-serve-load-")
names = ["student%03d" % i for i in range(args.students)]
make_lab(work, names)
page = make_page(work)
server = Server(args.glimmer, page, work, roster=True, extra=["--jobs", str(args.jobs)])
links = read_links(work)
blur = open(os.path.join(work, "lesson", "blur.frag"), encoding="utf-8").read()

lock = threading.Lock()
save_ms, failures, handins = [], [], {}
peak = {"rss_kb": 0, "threads": 0}
stop = threading.Event()


def note_failure(what):
    with lock:
        failures.append(what)


def student(name, rng):
    c = Client(server.port)
    status, _, _ = c.join_link(links[name])
    if status != 303:
        note_failure("%s: join %d" % (name, status))
        return
    hand_at = sorted(rng.uniform(0.1, 0.9) * args.seconds for _ in range(3))
    start = time.time()
    time.sleep(rng.uniform(0, 2))  # the class does not type in step
    k = 0
    mine = []
    while not stop.is_set():
        k += 1
        t0 = time.time()
        try:
            status, answer = c.save({"blur.frag": blur + "\n// %s edit %d\n" % (name, k)}, "blur.glib: drawn")
            ms = (time.time() - t0) * 1000
            if status != 200:
                note_failure("%s: save %d: %s" % (name, status, answer))
            else:
                with lock:
                    save_ms.append(ms)
            status, _ = c.json("GET", "/api/me")
            if status != 200:
                note_failure("%s: /api/me %d" % (name, status))
            if hand_at and time.time() - start >= hand_at[0]:
                hand_at.pop(0)
                status, answer = c.json("POST", "/api/handin", {})
                if status != 200:
                    note_failure("%s: hand-in %d" % (name, status))
                else:
                    mine.append(answer["handin"])
        except OSError as e:
            note_failure("%s: %s" % (name, e))
        time.sleep(max(0.0, 2.0 - (time.time() - t0)))
    with lock:
        handins[name] = (c, mine)


def teacher():
    c = Client(server.port)
    c.request("GET", server.teacher_path)
    while not stop.is_set():
        status, _ = c.json("GET", "/api/class")
        if status != 200:
            note_failure("teacher: /api/class %d" % status)
        time.sleep(2)


def watch_memory():
    while not stop.is_set() or not peak.get("done"):
        try:
            with open("/proc/%d/status" % server.proc.pid) as f:
                for line in f:
                    if line.startswith("VmRSS:"):
                        peak["rss_kb"] = max(peak["rss_kb"], int(line.split()[1]))
                    if line.startswith("Threads:"):
                        peak["threads"] = max(peak["threads"], int(line.split()[1]))
        except OSError:
            return
        time.sleep(0.5)


rng = random.Random(args.seed)
threads = [threading.Thread(target=student, args=(n, random.Random(rng.random()))) for n in names]
threads.append(threading.Thread(target=teacher))
memory = threading.Thread(target=watch_memory, daemon=True)
memory.start()
t_start = time.time()
for t in threads:
    t.start()
time.sleep(args.seconds)
stop.set()
for t in threads:
    t.join()
t_load = time.time() - t_start

# Every hand-in graded: how long after the load ended.
total = sum(len(m) for _, m in handins.values())
deadline = time.time() + 1800
graded = failed_grading = 0
while time.time() < deadline:
    graded = failed_grading = 0
    for name, (c, mine) in handins.items():
        status, me = c.json("GET", "/api/me")
        states = {h["id"]: h["state"] for h in me["handins"]} if status == 200 else {}
        graded += sum(states.get(h) == "graded" for h in mine)
        failed_grading += sum(states.get(h) == "failed" for h in mine)
    if graded + failed_grading >= total:
        break
    time.sleep(2)
t_graded = time.time() - t_start
peak["done"] = True
server.stop()

save_ms.sort()
pick = lambda q: save_ms[min(len(save_ms) - 1, int(q * len(save_ms)))] if save_ms else float("nan")
print("serve load: %d students for %.0f s (saves and polls every 2 s, 3 hand-ins each), the teacher's grid open"
      % (args.students, t_load))
print("  requests failed: %d%s" % (len(failures), "" if not failures else " (first: %s)" % failures[0]))
print("  saves: %d, latency p50 %.1f ms, p95 %.1f ms, max %.1f ms" % (len(save_ms), pick(0.5), pick(0.95),
                                                                    save_ms[-1] if save_ms else float("nan")))
print("  hand-ins: %d, graded %d, failed %d; all done %.0f s after the start (grading --jobs %d)"
      % (total, graded, failed_grading, t_graded, args.jobs))
print("  server: peak RSS %.1f MiB, peak threads %d" % (peak["rss_kb"] / 1024, peak["threads"]))
ok = not failures and graded == total and pick(0.95) <= 200
print("  goals (no failed request, p95 <= 200 ms, every hand-in graded): %s" % ("met" if ok else "NOT met"))
if ok:
    import shutil
    shutil.rmtree(work, ignore_errors=True)
sys.exit(0 if ok else 1)
