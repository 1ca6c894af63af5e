#!/usr/bin/env python3
"""glimmer serve killed with SIGKILL at any moment loses nothing it
acknowledged (issue 41, item 5). Students save in a loop (and hand in now
and then) while the server is killed at a random moment, ROUNDS times;
after each restart every student's files are their last acknowledged save
(or the one that was in flight when the kill came: committed, its answer
lost), and every acknowledged hand-in is there. At the end every hand-in is
graded, those cut off mid-grading included.

  tests/serve/serve_kill_test.py GLIMMER [ROUNDS] [SEED]"""
import os
import random
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from serve_lib import Client, Server, make_lab, make_page, read_links, wait_graded  # noqa: E402

glimmer = sys.argv[1]
rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 4
seed = int(sys.argv[3]) if len(sys.argv) > 3 else 41
rng = random.Random(seed)
work = tempfile.mkdtemp(prefix="glimmer-serve-kill-")
names = ["s%d" % i for i in range(6)]
make_lab(work, names)
page = make_page(work)
server = Server(glimmer, page, work, roster=True)
links = read_links(work)
blur = open(os.path.join(work, "lesson", "blur.frag"), encoding="utf-8").read()

acked = {n: None for n in names}        # the text of the last save the server answered
in_flight = {n: None for n in names}    # the text sent and not answered (yet)
handins_acked = {n: set() for n in names}
failures = []


def student(name, stop):
    c = Client(server.port)
    c.join_link(links[name])
    k = 0
    while not stop.is_set():
        k += 1
        text = blur + "\n// %s save %d\n" % (name, k)
        in_flight[name] = text
        try:
            status, answer = c.save({"blur.frag": text}, "save %d" % k)
            if status == 200:
                acked[name] = text
                in_flight[name] = None
            if k % 60 == 0:
                status, answer = c.json("POST", "/api/handin", {})
                if status == 200:
                    handins_acked[name].add(answer["handin"])
        except OSError:
            time.sleep(0.02)  # the server is down: try again (a browser's page does)


for r in range(rounds):
    stop = threading.Event()
    threads = [threading.Thread(target=student, args=(n, stop)) for n in names]
    for t in threads:
        t.start()
    time.sleep(rng.uniform(0.3, 2.0))
    server.kill9()
    stop.set()
    for t in threads:
        t.join()
    server.start()
    for n in names:
        c = Client(server.port)
        c.join_link(links[n])
        status, lesson = c.json("GET", "/lesson.json")
        import base64
        have = base64.b64decode(lesson["files"]["blur.frag"]).decode()
        if acked[n] is not None and have not in (acked[n], in_flight[n]):
            failures.append("round %d: %s has %r, last acknowledged %r" % (r, n, have[-20:], acked[n][-20:]))
        status, me = c.json("GET", "/api/me")
        missing = handins_acked[n] - {h["id"] for h in me["handins"]}
        if missing:
            failures.append("round %d: %s's acknowledged hand-ins %s are gone" % (r, n, sorted(missing)))
        acked[n] = have  # what it holds now is what the next round must keep
        in_flight[n] = None
    print("round %d: killed and restarted; %d students' saves and %d hand-ins checked" %
          (r, len(names), sum(len(h) for h in handins_acked.values())))

# Every hand-in graded in the end, those cut off by a kill too.
ungraded = 0
for n in names:
    c = Client(server.port)
    c.join_link(links[n])
    for h in sorted(handins_acked[n]):
        g = wait_graded(c, h, seconds=300)
        if not g or g["state"] != "graded":
            ungraded += 1
            failures.append("%s's hand-in %d: %s" % (n, h, g))
server.stop()
for f in failures:
    print("FAILED: " + f)
print("serve kill: %d rounds (seed %d), %d hand-ins, %d failures" %
      (rounds, seed, sum(len(h) for h in handins_acked.values()), len(failures)))
if not failures:
    import shutil
    shutil.rmtree(work, ignore_errors=True)
sys.exit(1 if failures else 0)
