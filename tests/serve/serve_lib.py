"""What the tests of `glimmer serve` share (tests/serve/*.py, tools/serve-load.py):
a lab made in a temporary folder (the blur exercise of tests/data/grading as
the lesson, a copy of it outside as the solution), the server started on a
free port and read back from what it prints, and an HTTP client that keeps
one student's (or the teacher's) cookie. Python's own urllib: no package."""
import http.client
import json
import os
import re
import shutil
import signal
import subprocess
import time
import urllib.parse

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BLUR = os.path.join(ROOT, "tests", "data", "grading", "blur")


def make_page(where):
    """A stand-in for the page's build (these tests serve it, never run it):
    an index.html shaped as src/web/page/index.html is where the server
    inserts the student's lesson and the serve script, and a module file."""
    page = os.path.join(where, "page")
    os.makedirs(page)
    with open(os.path.join(page, "index.html"), "w") as f:
        f.write('<!doctype html>\n<html><head><meta charset="utf-8">\n<meta http-equiv="Content-Security-Policy" '
                'content="script-src \'self\' \'wasm-unsafe-eval\'">\n<title>Glimmer</title></head><body>\n'
                '<script src="glimmer-lesson.js"></script>\n<script src="glimmer-page.js"></script>\n</body></html>\n')
    with open(os.path.join(page, "glimmer-web.wasm"), "wb") as f:
        f.write(b"\0asm\1\0\0\0")
    # The kept translations the page asks for beside it, and a text file the
    # build might leave there, which is not the page's.
    with open(os.path.join(page, "lesson-translations.txt"), "w") as f:
        f.write("glimmer-web-translations 1 0\n")
    with open(os.path.join(page, "notes.txt"), "w") as f:
        f.write("not served\n")
    return page


def make_lab(where, roster=None):
    """lesson/ and solution/ under `where` (and roster.csv when given names)."""
    shutil.copytree(BLUR, os.path.join(where, "lesson"))
    shutil.copytree(BLUR, os.path.join(where, "solution"))
    if roster is not None:
        with open(os.path.join(where, "roster.csv"), "w", encoding="utf-8") as f:
            f.write("name,email\n" + "".join(line + "\n" for line in roster))
    return os.path.join(where, "lesson"), os.path.join(where, "solution", "blur.glib")


class Server:
    """`glimmer serve` as a child process; what it printed, parsed."""

    def __init__(self, glimmer, page, where, roster=False, extra=()):
        self.where = where
        args = [glimmer, "serve", os.path.join(where, "lesson"), "--solution",
                os.path.join(where, "solution", "blur.glib"), "--port", str(getattr(self, "port", 0)),
                "--host", "127.0.0.1", "--page", page, "--state", os.path.join(where, "state"), *extra]
        if roster:
            args += ["--roster", os.path.join(where, "roster.csv")]
        self.args = args
        self.start()

    def start(self):
        self.out = open(os.path.join(self.where, "serve.out"), "w+")
        self.proc = subprocess.Popen(self.args, stdout=self.out, stderr=subprocess.STDOUT)
        deadline = time.time() + 30
        text = ""
        while time.time() < deadline:
            self.out.seek(0)
            text = self.out.read()
            if "kept in:" in text:
                break
            if self.proc.poll() is not None:
                raise RuntimeError("glimmer serve exited %d:\n%s" % (self.proc.returncode, text))
            time.sleep(0.05)
        else:
            raise RuntimeError("glimmer serve did not start:\n" + text)
        self.text = text
        self.port = int(re.search(r"\(port (\d+)\)", text).group(1))
        self.teacher_path = re.search(r"teacher:\s+http://[^/]+(/teacher/[0-9a-f]+)", text).group(1)
        code = re.search(r"class code ([A-Z0-9-]+)", text)
        self.code = code.group(1) if code else None
        # The same port again after a restart: the pages' links stay good.
        self.args[self.args.index("--port") + 1] = str(self.port)

    def kill9(self):
        self.proc.send_signal(signal.SIGKILL)
        self.proc.wait()
        self.out.close()

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                self.proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        self.out.close()
        return self.proc.returncode


class Client:
    """One browser's cookies against the server at 127.0.0.1:port."""

    def __init__(self, port):
        self.port = port
        self.cookies = {}

    def request(self, method, path, body=None, headers=None, timeout=30):
        conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=timeout)
        h = dict(headers or {})
        if self.cookies:
            h["Cookie"] = "; ".join("%s=%s" % kv for kv in self.cookies.items())
        if isinstance(body, (dict, list)):
            body = json.dumps(body).encode()
            h.setdefault("Content-Type", "application/json")
        elif isinstance(body, str):
            body = body.encode()
        conn.request(method, path, body=body, headers=h)
        r = conn.getresponse()
        data = r.read()
        for header, value in r.getheaders():
            if header.lower() == "set-cookie":
                name, rest = value.split("=", 1)
                self.cookies[name] = rest.split(";", 1)[0]
        conn.close()
        return r.status, dict((k.lower(), v) for k, v in r.getheaders()), data

    def json(self, method, path, body=None, headers=None):
        status, _, data = self.request(method, path, body, headers)
        try:
            return status, json.loads(data)
        except ValueError:
            return status, data.decode(errors="replace")

    def join_link(self, link):
        path = urllib.parse.urlparse(link).path
        return self.request("GET", path)

    def save(self, files, status=""):
        return self.json("POST", "/api/save", {"files": files, "status": status})


def wait_graded(client, handin, seconds=180):
    """The student's hand-in `handin` once graded (or failed); None on time-out."""
    deadline = time.time() + seconds
    while time.time() < deadline:
        status, me = client.json("GET", "/api/me")
        if status == 200:
            for h in me["handins"]:
                if h["id"] == handin and h["state"] in ("graded", "failed"):
                    return h
        time.sleep(0.3)
    return None


def read_links(where):
    """name -> link, from the links.csv the server wrote."""
    import csv
    with open(os.path.join(where, "state", "links.csv"), encoding="utf-8") as f:
        return {row["name"]: row["link"] for row in csv.DictReader(f)}
