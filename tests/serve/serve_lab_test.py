#!/usr/bin/env python3
"""glimmer serve, a lab from the outside (issue 41): a roster of three joins
by their links, saves, hands in; each hand-in's verdict and score equal what
`glimmer batch --reference` gives the same files from the command line; and
what no one may do is refused: another's work or feedback, files outside the
lesson, bodies too large, a form from another site, too many requests, the
teacher's calls without the teacher's token.

  tests/serve/serve_lab_test.py GLIMMER [PAGE_DIR]   (default: a stand-in page)
Prints one line per check and "serve lab: N passed, M failed"."""
import base64
import csv
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from serve_lib import Client, Server, make_lab, make_page, read_links, wait_graded  # noqa: E402

glimmer = sys.argv[1]
passed = failed = 0


def check(ok, what, got=""):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAILED: %s%s" % (what, ("\n  got: %s" % (got,)) if got != "" else ""))


work = tempfile.mkdtemp(prefix="glimmer-serve-lab-")
names = ['"Lovelace, Ada"', "Bob", "Émile Zola"]
lesson, solution = make_lab(work, names)
page = sys.argv[2] if len(sys.argv) > 2 else make_page(work)
blur = open(os.path.join(lesson, "blur.frag"), encoding="utf-8").read()
# What the three hand in: the solution's blur with a comment (pass), no blur
# at all (wrong), a syntax error (error).
texts = {
    "Lovelace, Ada": blur + "\n// mine\n",
    "Bob": blur.replace("gl_FragColor = vec4( sum / weightSum, 1. );", "gl_FragColor = texture( ImageUnit, vST );"),
    "Émile Zola": blur.replace("float weightSum = 0.;", "float weightSum = 0. +;"),
}

# Refusals at start, in compiler style where a file is at fault.
r = subprocess.run([glimmer, "serve", lesson, "--solution", os.path.join(lesson, "blur.glib"), "--page", page,
                    "--port", "0", "--state", os.path.join(work, "x")], capture_output=True, text=True, timeout=60)
check(r.returncode == 2 and "is inside the lesson folder" in r.stderr, "a solution inside the lesson is refused",
      r.stderr)
with open(os.path.join(work, "twice.csv"), "w") as f:
    f.write("name\nAda\nBob\nAda\n")
r = subprocess.run([glimmer, "serve", lesson, "--solution", solution, "--page", page, "--port", "0", "--state",
                    os.path.join(work, "x"), "--roster", os.path.join(work, "twice.csv")],
                   capture_output=True, text=True, timeout=60)
check(r.returncode == 2 and r.stderr == os.path.join(work, "twice.csv") +
      ":4:1: error: 'Ada' comes twice: each student once\nAda\n^\n", "a roster naming a student twice", r.stderr)

server = Server(glimmer, page, work, roster=True)
try:
    links = read_links(work)
    check(sorted(links) == sorted(texts), "links.csv names the roster's students", sorted(links))
    tokens = [re.search(r"/join/([0-9a-f]+)$", link).group(1) for link in links.values()]
    check(all(len(t) == 32 for t in tokens) and len(set(tokens)) == 3, "tokens are 128 bits, one each", tokens)

    # Joining: a link sets an HttpOnly SameSite cookie; the class code is refused with a roster.
    students = {}
    for name, link in links.items():
        c = Client(server.port)
        status, headers, _ = c.join_link(link)
        check(status == 303 and headers.get("location") == "/", "a link signs in " + name, (status, headers))
        cookie = headers.get("set-cookie", "")
        check("HttpOnly" in cookie and "SameSite=Lax" in cookie, "the cookie is HttpOnly and SameSite", cookie)
        students[name] = c
    ada, bob, emile = students["Lovelace, Ada"], students["Bob"], students["Émile Zola"]
    stranger = Client(server.port)
    status, headers, _ = stranger.request("GET", "/")
    check(status == 303 and headers.get("location") == "/join", "no cookie: sent to /join", status)
    status, _, body = stranger.request("POST", "/join", "code=ABCD-EFGH&name=Eve",
                                       {"Content-Type": "application/x-www-form-urlencoded"})
    check(status == 403 and b"own link" in body, "a roster class cannot be joined by name", status)
    status, _, _ = stranger.request("GET", "/join/" + "0" * 32)
    check(status == 404, "a made-up link is refused", status)

    # The page: the lesson from the student's own lesson.json, the serve script before the page's.
    status, headers, body = ada.request("GET", "/")
    text = body.decode()
    check(status == 200 and '<meta name="glimmer-serve" content="&quot;Lovelace, Ada&quot;"' not in text
          and 'content="Lovelace, Ada"' in text, "the page names the student", text[:600])
    check(text.find("glimmer-serve.js") < text.find('<script src="glimmer-page.js">') and
          "wasm-unsafe-eval" in headers.get("content-security-policy", ""), "the page keeps its CSP and script order")
    status, headers, body = stranger.request("GET", "/lesson-translations.txt")
    check(status == 200 and body == b"glimmer-web-translations 1 0\n" and headers.get("content-type", "").startswith("text/plain"),
          "the page's kept translations are served beside it", (status, headers, body[:80]))
    status, _, _ = stranger.request("GET", "/notes.txt")
    check(status == 404, "another text file of the page's folder is not served", status)
    status, lesson_json = ada.json("GET", "/lesson.json")
    original = {p: base64.b64decode(d).decode() for p, d in lesson_json["files"].items()}
    check(original.get("blur.frag") == blur and lesson_json["scripts"] == ["blur.glib"], "lesson.json is the lesson")

    # Saves: a version each time something changed, none when nothing did.
    s1 = ada.save({"blur.frag": blur + "\n// draft\n"}, "blur.glib: drawn")
    s2 = ada.save({"blur.frag": blur + "\n// draft\n"}, "blur.glib: drawn")
    check(s1[0] == 200 and s2[1]["version"] == s1[1]["version"], "an unchanged save makes no version", (s1, s2))
    for name, c in students.items():
        status, answer = c.save({"blur.frag": texts[name]}, "saved")
        check(status == 200, "a save by " + name, answer)
    status, lesson_json = bob.json("GET", "/lesson.json")
    check(base64.b64decode(lesson_json["files"]["blur.frag"]).decode() == texts["Bob"],
          "a reload gets the student's own last save")

    # What a save may not do.
    for files, want, what in [({"../../etc/passwd": "x"}, 400, "a path outside the lesson"),
                              ({"notes.txt": "x"}, 400, "a file the lesson has not"),
                              ({"blur.frag": "x" * (1024 * 1024 + 1)}, 413, "a file over 1 MiB"),
                              ({"blur.frag": 3}, 400, "a text that is not a string")]:
        status, answer = ada.save(files)
        check(status == want, "refused: " + what, (status, answer))
    status, _, _ = ada.request("POST", "/api/save", "files=x", {"Content-Type": "application/x-www-form-urlencoded"})
    check(status == 415, "a form post (another site's) is not a save", status)
    status, _, _ = ada.request("POST", "/api/save", b"{" + b" " * (5 * 1024 * 1024) + b"}",
                               {"Content-Type": "application/json"})
    check(status == 413, "a body over 4 MiB is refused", status)
    status, _ = stranger.save({"blur.frag": "x"})
    check(status == 403, "no cookie: no save", status)

    # Hand-ins, graded as they arrive.
    handins = {}
    for name, c in students.items():
        status, answer = c.json("POST", "/api/handin", {})
        check(status == 200, "a hand-in by " + name, answer)
        handins[name] = answer["handin"]
    graded = {name: wait_graded(students[name], handins[name]) for name in students}
    check(all(g and g["state"] == "graded" for g in graded.values()), "every hand-in graded", graded)

    # The same files graded from the command line: the same verdicts and scores.
    klass = os.path.join(work, "class")
    os.makedirs(klass)
    teacher = Client(server.port)
    teacher.request("GET", server.teacher_path)
    folders = {s["name"]: s["folder"] for s in teacher.json("GET", "/api/class")[1]["students"]}
    check(folders == {"Lovelace, Ada": "Lovelace__Ada", "Bob": "Bob", "Émile Zola": "Émile_Zola"},
          "the server names each student's folder", folders)
    for name in texts:
        folder = os.path.join(klass, folders[name])
        subprocess.run(["cp", "-r", lesson, folder], check=True)
        with open(os.path.join(folder, "blur.frag"), "w", encoding="utf-8") as f:
            f.write(texts[name])
    out = os.path.join(work, "graded-by-hand")
    subprocess.run([glimmer, "batch", "--reference", solution, "-o", out, klass], capture_output=True, timeout=600)
    with open(os.path.join(out, "grades.csv"), encoding="utf-8") as f:
        by_hand = {row["student"]: row for row in csv.DictReader(f)}
    for name, folder in folders.items():
        g, h = graded[name], by_hand.get(folder)
        check(g and h and g["verdict"] == h["verdict"] and str(g["score"]) == h["score"],
              "the server's grade is the command line's for " + name, (g, h))
    check(graded["Lovelace, Ada"]["verdict"] == "pass" and graded["Émile Zola"]["verdict"] == "error",
          "the grades are the expected ones", graded)
    check(graded["Émile Zola"]["notes"].find("blur.frag:") >= 0 and work not in graded["Émile Zola"]["notes"],
          "an error names the student's file, not the server's folder", graded["Émile Zola"]["notes"])

    # Feedback: the owner reads it (inert: no script), no one else does.
    mine = "/api/feedback/%d" % handins["Lovelace, Ada"]
    status, headers, body = ada.request("GET", mine)
    check(status == 200 and b"<html" in body.lower() and "default-src 'none'" in headers.get("content-security-policy", ""),
          "the student reads their feedback, under a CSP with no script", (status, headers))
    status, _, _ = bob.request("GET", mine)
    check(status == 404, "another student cannot read it", status)
    status, _, _ = stranger.request("GET", mine)
    check(status == 404, "nor can a stranger", status)

    # The teacher: their link; the class, the export, follow me. A student is not the teacher.
    status, _ = ada.json("GET", "/api/class")
    check(status == 403, "a student cannot read the class", status)
    status, klass_json = teacher.json("GET", "/api/class")
    check(status == 200 and len(klass_json["students"]) == 3 and
          all(s["last"]["state"] == "graded" for s in klass_json["students"]), "the teacher's grid", klass_json)
    status, _, csv_text = teacher.request("GET", "/teacher/export/grades.csv")
    rows = {row["student"]: row for row in csv.DictReader(csv_text.decode().splitlines())}
    check(status == 200 and {k: (v["verdict"], v["score"]) for k, v in rows.items()} ==
          {k: (v["verdict"], v["score"]) for k, v in by_hand.items()}, "grades.csv as batch --reference writes it", rows)
    status, _ = teacher.json("POST", "/api/follow", {"sets": "uAdd=2;uHalfSize=5"})
    status, me = emile.json("GET", "/api/me")
    check(me["follow"]["sets"] == "uAdd=2;uHalfSize=5" and me["follow"]["id"] > 0, "follow me reaches a student", me)
    status, _ = ada.json("POST", "/api/follow", {"sets": "uAdd=0"})
    check(status == 403, "a student cannot push to the class", status)

    # Grading that cannot run (the solution gone) fails the hand-in with batch's reason, the
    # server's and the solution's folders not named (a student reads it).
    os.rename(solution, solution + ".away")
    status, answer = emile.json("POST", "/api/handin", {})
    failed_run = wait_graded(emile, answer["handin"])
    os.rename(solution + ".away", solution)
    check(failed_run and failed_run["state"] == "failed" and "grading did not run (exit 2)" in failed_run["notes"]
          and "blur.glib" in failed_run["notes"] and work not in failed_run["notes"],
          "a run batch refuses fails the hand-in, saying why without the server's paths", failed_run)

    # Rate: a page polling in a loop is slowed, not served without bound.
    codes = [bob.request("GET", "/api/me")[0] for _ in range(120)]
    check(429 in codes and codes[0] == 200, "too many requests get 429", sorted(set(codes)))
finally:
    code = server.stop()
check(code == 0, "SIGTERM stops the server cleanly", code)

# Without a roster: the class code and a name not taken.
open_lab = os.path.join(work, "open")
os.makedirs(open_lab)
make_lab(open_lab)
server = Server(glimmer, page, open_lab)
try:
    form = {"Content-Type": "application/x-www-form-urlencoded"}
    check(re.fullmatch(r"[2-9A-HJKMNP-Z]{4}-[2-9A-HJKMNP-Z]{4}", server.code or ""), "a class code is printed", server.code)
    eve = Client(server.port)
    status, _, body = eve.request("POST", "/join", "code=AAAA-AAAA&name=Eve", form)
    check(status == 403 and b"not this class" in body and not eve.cookies, "a wrong class code is refused", status)
    status, headers, _ = eve.request("POST", "/join", "code=%s&name=Eve+Adams" % server.code.lower(), form)
    check(status == 303 and "glimmer_student" in eve.cookies, "the class code (any case) and a name join", status)
    status, me = eve.json("GET", "/api/me")
    check(status == 200 and me["name"] == "Eve Adams", "the student is who they said", me)
    again = Client(server.port)
    status, _, body = again.request("POST", "/join", "code=%s&name=Eve+Adams" % server.code, form)
    check(status == 409 and b"taken" in body and not again.cookies,
          "a name already in the class is refused (it would hand over their work)", status)
    status, _, _ = again.request("POST", "/join", "code=%s&name=+++" % server.code, form)
    check(status == 400, "an empty name is refused", status)
finally:
    server.stop()
print("serve lab: %d passed, %d failed" % (passed, failed))
if failed == 0:
    import shutil
    shutil.rmtree(work, ignore_errors=True)
sys.exit(1 if failed else 0)
