#!/usr/bin/env python3
"""A lesson for the browser page: files the page mounts at /user.

A lesson is a script tag that sets globalThis.glimmerLesson to
{"files": {"relative/path": "base64", ...}}; the page (src/web/page/
glimmer-page.js) writes those files into its file system, refusing a path
that leaves the folder. A script tag, not JSON fetched, because a page
opened from disk may load scripts but not fetch files.

  web_lesson.py for-script SCRIPT OUT.js
      the files a script can reach: its folder and the sibling shaders/ and
      textures/ folders Glimmer looks in (src/plan/resolve.cpp); prints the
      script's path inside the lesson. tools/render-web.sh uses it.
  web_lesson.py pack FOLDER WEB_DIR --html OUT.html
      one self-contained page: the module, its WebAssembly, the page and
      the folder's files in one HTML file that opens from disk, no server.
  web_lesson.py pack FOLDER WEB_DIR --static DIR
      the same as a folder for a web server: the page, the module and
      lesson.js side by side.
Sizes are bounded before anything is read whole: 64 MiB of lesson files.
"""
import base64
import re
import json
import os
import sys

LIMIT = 64 * 1024 * 1024


def fail(message):
    sys.stderr.write(f"web_lesson: {message}\n")
    sys.exit(2)


def collect(root, tops):
    """Every plain file below each of `tops`, as {path relative to root: bytes}."""
    files, total = {}, 0
    for top in tops:
        for dirpath, dirnames, filenames in os.walk(top):
            dirnames[:] = sorted(d for d in dirnames if not d.startswith("."))
            for name in sorted(filenames):
                path = os.path.join(dirpath, name)
                if name.startswith(".") or os.path.islink(path) or not os.path.isfile(path):
                    continue
                total += os.path.getsize(path)
                if total > LIMIT:
                    fail(f"{top}: more than {LIMIT >> 20} MiB of files; a lesson holds at most that")
                with open(path, "rb") as f:
                    files[os.path.relpath(path, root)] = f.read()
    return files


def lesson_js(files):
    encoded = {path: base64.b64encode(data).decode() for path, data in files.items()}
    return "globalThis.glimmerLesson = " + json.dumps({"files": encoded}) + ";\n"


def for_script(script, out):
    script = os.path.abspath(script)
    folder = os.path.dirname(script)
    parent = os.path.dirname(folder)
    siblings = [os.path.join(parent, d) for d in ("shaders", "textures") if os.path.isdir(os.path.join(parent, d))]
    root = parent if siblings else folder
    with open(out, "w") as f:
        f.write(lesson_js(collect(root, [folder] + siblings)))
    print(os.path.relpath(script, root))


def pack(folder, web, html_out=None, static_dir=None):
    if not os.path.isdir(folder):
        fail(f"{folder}: not a folder")
    files = collect(folder, [folder])
    if not any(p.endswith(".glib") for p in files):
        fail(f"{folder}: no .glib script in it")
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
    tag = '<script src="glimmer-web.js"></script>'
    if tag not in page:
        fail(f"{web}/index.html has no {tag}: the page and this packer disagree")
    if static_dir:
        for name, data in parts.items():
            os.makedirs(os.path.dirname(os.path.join(static_dir, name)), exist_ok=True)
            with open(os.path.join(static_dir, name), "wb") as f:
                f.write(data)
        with open(os.path.join(static_dir, "lesson.js"), "w") as f:
            f.write(lesson_js(files))
        with open(os.path.join(static_dir, "index.html"), "w") as f:
            f.write(page.replace(tag, '<script src="lesson.js"></script>\n' + tag))
        print(f"wrote {static_dir}/ ({len(files)} lesson files)")
    if html_out:
        def inline(code):
            # A script element ends at the first "</script": keep it out of the code.
            return "<script>" + code.replace("</script", "<\\/script") + "</script>"
        wasm = base64.b64encode(parts["glimmer-web.wasm"]).decode()
        for script, sheet in named:
            if sheet:
                css = parts[sheet].decode().replace("</style", "<\\/style")
                page = page.replace(f'<link rel="stylesheet" href="{sheet}">', "<style>" + css + "</style>")
            elif script == "glimmer-web.js":
                page = page.replace(tag, inline(lesson_js(files)) + "\n"
                                    + inline(f'globalThis.glimmerWasm = "{wasm}";') + "\n"
                                    + inline(parts["glimmer-web.js"].decode()))
            else:
                page = page.replace(f'<script src="{script}"></script>', inline(parts[script].decode()))
        with open(html_out, "w") as f:
            f.write(page)
        print(f"wrote {html_out} ({len(files)} lesson files, {os.path.getsize(html_out)} bytes)")


def main(argv):
    if len(argv) == 3 and argv[0] == "for-script":
        return for_script(argv[1], argv[2])
    if len(argv) == 5 and argv[0] == "pack" and argv[3] in ("--html", "--static"):
        return pack(argv[1], argv[2], **({"html_out": argv[4]} if argv[3] == "--html" else {"static_dir": argv[4]}))
    sys.stderr.write(__doc__)
    sys.exit(2)


if __name__ == "__main__":
    main(sys.argv[1:])
