#!/usr/bin/env python3
"""A lesson for the browser page: files the page mounts at /user.

A lesson is DATA, never code: JSON {"files": {"relative/path": "base64",
...}}. The page (src/web/page/glimmer-page.js) parses it with JSON.parse,
checks it and writes the files into its file system, refusing a path that
leaves the folder; it loads a lesson only from its own origin (from disk,
only from disk), so a link from anyone can never run code in the page.

  web_lesson.py for-script SCRIPT OUT.json
      the files a script can reach: its folder and the sibling shaders/ and
      textures/ folders Glimmer looks in (src/plan/resolve.cpp); prints the
      script's path inside the lesson. tools/render-web.sh uses it
      (index.html?lesson=file:///.../OUT.json).
  web_lesson.py pack FOLDER WEB_DIR --html OUT.html [--glimmer PATH] [--leave-out-failing]
      one self-contained page: the module, its WebAssembly, the page and
      the folder's files in one HTML file that opens from disk, no server.
      The lesson and the WebAssembly are data blocks, gzip-compressed (the
      browser undoes it natively: DecompressionStream); each inline script
      is allowed by its sha256 in the page's Content-Security-Policy.
  web_lesson.py pack FOLDER WEB_DIR --static DIR [--glimmer PATH] [--leave-out-failing]
      the same as a folder for a web server: the page, the module and
      lesson.json side by side.
  Before packing, every script of the folder is checked as the page will
  run it (`glimmer check --web --list-inputs`, the desktop program: PATH,
  $GLIMMER, build/src/app/glimmer or glimmer on PATH): a script that would
  fail in the page is listed with its messages and the pack refused, unless
  --leave-out-failing packs the others. The files a script reads from
  beside the folder (glman's shaders/ and textures/ next to scripts/), within
  the folder's parent, are packed with it, so the page finds what the
  desktop finds. The lesson lists its scripts, each once.
Only regular files are taken: a symbolic link or a hard link (which may be
a file outside the folder) is skipped with a message, as is a name that is
not UTF-8. Sizes are bounded before anything is read whole: 64 MiB of
lesson files.
"""
import base64
import gzip
import hashlib
import json
import os
import re
import shutil
import stat
import subprocess
import sys

LIMIT = 64 * 1024 * 1024
# The page's own policy (src/web/page/index.html); the packed page's is this
# with the inline scripts' hashes in place of 'self'.
CSP_META = re.compile(r'<meta http-equiv="Content-Security-Policy" content="([^"]*)">')


def fail(message):
    sys.stderr.write(f"web_lesson: {message}\n")
    sys.exit(2)


def skip(path, why):
    sys.stderr.write(f"web_lesson: skipped {path}: {why}\n")


def inside(path, root):
    return os.path.commonpath([path, root]) == root


def read_checked(path, top):
    """The bytes of the regular file `path`, opened without following a link
    and checked on the open descriptor (what is read is what was checked);
    None, said on stderr, for anything else."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError as e:
        skip(path, "a symbolic link" if os.path.islink(path) else e.strerror)
        return None
    with os.fdopen(fd, "rb") as f:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            skip(path, "not a regular file")
            return None
        if st.st_nlink > 1:
            skip(path, f"a hard link ({st.st_nlink} names; one may be outside the folder)")
            return None
        if st.st_size > LIMIT:
            fail(f"{top}: more than {LIMIT >> 20} MiB of files; a lesson holds at most that")
        data = f.read(st.st_size + 1)
        if len(data) > st.st_size:
            fail(f"{path} grew while it was read")
    return data


def collect(root, tops):
    """Every regular file below each of `tops`, as {path relative to root: bytes}."""
    root = os.path.realpath(root)
    files, total = {}, 0
    for top in tops:
        if os.path.realpath(top) != root and (os.path.islink(top) or not inside(os.path.realpath(top), root)):
            skip(top, "a symbolic link, or outside the lesson's folder")
            continue
        top = os.path.realpath(top)
        for dirpath, dirnames, filenames in os.walk(top):
            # os.walk lists links to folders without entering them: say so.
            for d in [d for d in dirnames if os.path.islink(os.path.join(dirpath, d))]:
                skip(os.path.join(dirpath, d), "a symbolic link (it may lead outside the folder)")
            dirnames[:] = sorted(d for d in dirnames
                                 if not d.startswith(".") and not os.path.islink(os.path.join(dirpath, d)))
            for name in sorted(filenames):
                path = os.path.join(dirpath, name)
                if name.startswith("."):
                    continue
                if os.path.islink(path):
                    skip(path, "a symbolic link (it may lead outside the folder)")
                    continue
                rel = os.path.relpath(path, root)
                try:
                    rel.encode("utf-8")
                except UnicodeEncodeError:
                    skip(path, "its name is not UTF-8")
                    continue
                if rel.split(os.sep)[0] == ".." or os.path.isabs(rel) or not inside(os.path.realpath(path), root):
                    skip(path, "outside the lesson's folder")
                    continue
                data = read_checked(path, top)
                if data is None:
                    continue
                total += len(data)
                if total > LIMIT:
                    fail(f"{top}: more than {LIMIT >> 20} MiB of files; a lesson holds at most that")
                files[rel] = data
    return files


def lesson_json(files, scripts=None, name=None):
    """The lesson as JSON text, ASCII only, with every '<' written \\u003c:
    inside an HTML <script> element nothing in a file's name or text can
    end it ("</script>") or change how it ends ("<!--<script>")."""
    lesson = {"files": {path: base64.b64encode(data).decode() for path, data in files.items()}}
    if scripts is not None:
        lesson["scripts"] = scripts
    if name:
        lesson["name"] = name
    return json.dumps(lesson, ensure_ascii=True).replace("<", "\\u003c")


def find_glimmer(given):
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    for candidate in (given, os.environ.get("GLIMMER"), os.path.join(repo, "build", "src", "app", "glimmer"),
                      shutil.which("glimmer")):
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    fail("the desktop glimmer checks the scripts before they are packed: --glimmer PATH "
         "(build it: cmake --build build)")


def checked_scripts(folder, scripts, glimmer, leave_out_failing):
    """Each of `scripts` (paths in `folder`, the .glib files collect took)
    checked as the page runs it; returns (scripts that run, the files they
    read), paths real. A script that would fail is listed with its
    messages; the pack is refused unless `leave_out_failing`. A script may
    read files beside the folder (its parent's shaders/, textures/), never
    above its parent."""
    allowed = os.path.dirname(folder)
    good, inputs, failed = [], set(), []
    for script in scripts:
        try:
            r = subprocess.run([glimmer, "check", "--web", "--list-inputs", script], capture_output=True, text=True,
                               errors="replace", timeout=120)
            code, said, listed = r.returncode, r.stderr, r.stdout.splitlines()
        except subprocess.TimeoutExpired:
            code, said, listed = 1, "glimmer check --web took more than 120 s\n", []
        reads = [os.path.realpath(p) for p in listed]
        outside = [p for p in reads if not inside(p, allowed)]
        if code == 0 and outside:
            code, said = 1, f"it reads {outside[0]}, outside {allowed}, which a lesson does not carry\n"
        if code != 0:
            failed.append((script, said))
            continue
        good.append(script)
        inputs.update(reads)
    for script, said in failed:
        sys.stderr.write(f"web_lesson: {os.path.relpath(script, folder)} will not run in the page:\n")
        sys.stderr.write("".join("    " + line + "\n" for line in said.rstrip("\n").split("\n")))
    if failed and not leave_out_failing:
        fail(f"{len(failed)} of {len(scripts)} scripts will not run in the page: fix them, "
             "or pack the others with --leave-out-failing")
    if failed:
        sys.stderr.write(f"web_lesson: left out {len(failed)} of {len(scripts)} scripts\n")
    if not good:
        fail(f"{folder}: no .glib script in it runs in the page")
    return good, inputs


def gzip_base64(text):
    # mtime 0: the same lesson packs to the same bytes.
    return base64.b64encode(gzip.compress(text.encode("utf-8") if isinstance(text, str) else text, 9, mtime=0)).decode()


def for_script(script, out):
    # The folder as it really is (paths below are made relative to it).
    folder = os.path.realpath(os.path.dirname(os.path.abspath(script)))
    script = os.path.join(folder, os.path.basename(script))
    parent = os.path.dirname(folder)
    siblings = [os.path.join(parent, d) for d in ("shaders", "textures") if os.path.isdir(os.path.join(parent, d))]
    root = parent if siblings else folder
    with open(out, "w") as f:
        f.write(lesson_json(collect(root, [folder] + siblings)))
    print(os.path.relpath(script, root))


def csp_hash(code):
    return "'sha256-" + base64.b64encode(hashlib.sha256(code.encode("utf-8")).digest()).decode() + "'"


def pack(folder, web, html_out=None, static_dir=None, glimmer=None, leave_out_failing=False):
    if not os.path.isdir(folder):
        fail(f"{folder}: not a folder")
    folder = os.path.realpath(folder)
    # The folder's own files (one walk, with its rules on links and names),
    # its scripts among them checked.
    own = collect(folder, [folder])
    candidates = [os.path.join(folder, p) for p in sorted(own) if p.endswith(".glib")]
    scripts, reads = checked_scripts(folder, candidates, find_glimmer(glimmer), leave_out_failing)
    # Those files but the scripts that would fail, and what the scripts read
    # from beside the folder, under the folder they share (the layout the
    # scripts name them in).
    beside = sorted(p for p in reads if not inside(p, folder))
    root = os.path.commonpath([folder] + beside)
    good = set(scripts)
    files = {os.path.relpath(os.path.join(folder, p), root): data for p, data in own.items()
             if not p.endswith(".glib") or os.path.join(folder, p) in good}
    total = sum(len(d) for d in files.values())
    for path in beside:
        data = read_checked(path, folder)
        if data is not None:
            total += len(data)
            if total > LIMIT:
                fail(f"{folder}: more than {LIMIT >> 20} MiB of files; a lesson holds at most that")
            files[os.path.relpath(path, root)] = data
    listed = sorted(os.path.relpath(s, root) for s in scripts)
    name = os.path.basename(folder)
    # The page and every file it names (scripts, style sheets), and the module's wasm.
    def read(name):
        path = os.path.join(web, name)
        if not os.path.isfile(path):
            fail(f"{path} is missing: build the page first (tools/build-web.sh)")
        with open(path, "rb") as f:
            return f.read()
    page = read("index.html").decode()
    named = re.findall(r'<script src="([^"]+)"></script>|<link rel="stylesheet" href="([^"]+)">', page)
    parts = {name: read(name) for pair in named for name in pair if name}
    parts["glimmer-web.wasm"] = read("glimmer-web.wasm")
    # The bundled lesson's translations, made with the module (issue 39,
    # src/web/web_translations.cpp): the page's first picture of a shader
    # they hold calls no glslang. Carried whole (about 10 KB compressed): a
    # teacher's own shaders are simply not among them, and translated.
    translations = os.path.join(web, "lesson-translations.txt")
    if os.path.isfile(translations):
        parts["lesson-translations.txt"] = read("lesson-translations.txt")
    tag = '<script src="glimmer-web.js"></script>'
    if tag not in page or not CSP_META.search(page):
        fail(f"{web}/index.html has no {tag} or no Content-Security-Policy: the page and this packer disagree")
    if static_dir:
        for name, data in parts.items():
            os.makedirs(os.path.dirname(os.path.join(static_dir, name)), exist_ok=True)
            with open(os.path.join(static_dir, name), "wb") as f:
                f.write(data)
        with open(os.path.join(static_dir, "lesson.json"), "w") as f:
            f.write(lesson_json(files, listed, name))
        # The page loads the lesson beside it, as data (glimmer-page.js).
        with open(os.path.join(static_dir, "index.html"), "w") as f:
            f.write(page.replace("</head>", '<meta name="glimmer-lesson" content="lesson.json">\n</head>', 1))
        print(f"wrote {static_dir}/ ({len(files)} lesson files)")
    if html_out:
        hashes = []
        def inline(code):
            # The HTML parser turns CR and CRLF into LF: hash what it will see.
            code = code.replace("\r\n", "\n").replace("\r", "\n")
            # A script element ends at the first "</script", and "<!--" can
            # change where: keep both out of the code.
            code = code.replace("</script", "<\\/script")
            if "<!--" in code or "\0" in code:
                fail("a script of the page holds '<!--' or a NUL, which an inline script cannot carry")
            hashes.append(csp_hash(code))
            return "<script>" + code + "</script>"
        wasm = gzip_base64(parts["glimmer-web.wasm"])
        for script, sheet in named:
            if sheet:
                css = parts[sheet].decode().replace("</style", "<\\/style")
                page = page.replace(f'<link rel="stylesheet" href="{sheet}">', "<style>" + css + "</style>")
            elif script == "glimmer-web.js":
                # Data blocks (not JavaScript): never run, so they need no hash.
                # Base64 of gzip: nothing in it can end the element.
                page = page.replace(tag, '<script type="application/gzip" id="glimmer-lesson">'
                                    + gzip_base64(lesson_json(files, listed, name)) + "</script>\n"
                                    + '<script type="application/gzip" id="glimmer-wasm">' + wasm + "</script>\n"
                                    + ('<script type="application/gzip" id="glimmer-translations">'
                                       + gzip_base64(parts["lesson-translations.txt"]) + "</script>\n"
                                       if "lesson-translations.txt" in parts else "")
                                    + inline(parts["glimmer-web.js"].decode()))
            else:
                page = page.replace(f'<script src="{script}"></script>', inline(parts[script].decode()))
        policy = CSP_META.search(page).group(1)
        sources = policy.split(";")
        for i, directive in enumerate(sources):
            words = directive.split()
            if words and words[0] == "script-src":
                # No script from anywhere (the page is one file): only these.
                sources[i] = " ".join(["script-src"] + [w for w in words[1:] if w != "'self'"] + hashes)
        page = CSP_META.sub(lambda m: m.group(0).replace(policy, ";".join(sources)), page, count=1)
        with open(html_out, "w", newline="") as f:
            f.write(page)
        print(f"wrote {html_out} ({len(files)} lesson files, {os.path.getsize(html_out)} bytes)")


def main(argv):
    if len(argv) == 3 and argv[0] == "for-script":
        return for_script(argv[1], argv[2])
    if len(argv) >= 5 and argv[0] == "pack" and argv[3] in ("--html", "--static"):
        options = {"html_out": argv[4]} if argv[3] == "--html" else {"static_dir": argv[4]}
        rest = argv[5:]
        while rest:
            if rest[0] == "--leave-out-failing":
                options["leave_out_failing"] = True
                rest = rest[1:]
            elif rest[0] == "--glimmer" and len(rest) > 1:
                options["glimmer"] = rest[1]
                rest = rest[2:]
            else:
                sys.stderr.write(__doc__)
                sys.exit(2)
        return pack(argv[1], argv[2], **options)
    sys.stderr.write(__doc__)
    sys.exit(2)


if __name__ == "__main__":
    main(sys.argv[1:])
