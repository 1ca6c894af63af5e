// The page's side of src/web/web_check.cpp and web_render.cpp: lists the
// lesson's scripts, checks or draws the chosen one, shows the diagnostics
// as the desktop prints them.
//
// Two folders in the module's file system:
//   /lesson  the bundled scripts, shaders and textures (embedded at build)
//   /user    the user's own: a folder picked or dropped on the page, or a
//            lesson's files (see "A lesson" below); see mountUser.
// A script runs with its folder's root as the working directory, so its
// diagnostics name files as the desktop does when run from that root.
//
// The tests (tools/test-web.sh) open the page with ?check=PATH or
// ?render=PATH[&size=WxH][&set=NAME=VALUE;...] (PATH under /lesson, or
// under /user with ?lesson=) and read the result from the DOM: data-exit
// on #verdict, the text of #diagnostics, and for a render the picture as a
// PNG data URL in data-png on #picture. ?frames=N times N more frames of
// it (data-frame-ms on #picture); data-first-picture-ms on the body is the
// time from the start of loading to the first picture. A refused lesson is
// data-exit="2" and data-lesson="refused" on #verdict, the reason its text.
"use strict";
// What a user's folder may hold: checked before anything is written into
// the module's memory (a dropped folder may be anything).
const kMaxUserFiles = 2000;
const kMaxUserBytes = 256 * 1024 * 1024;

// A lesson is DATA, never code: JSON {"files": {"relative/path": "base64",
// ...}, "name"?: "..."}, parsed with JSON.parse and checked here. A link
// (?lesson=URL) is something anyone can send, and code run in the page's
// origin could read the drafts kept in its storage; so a lesson comes only
// from the page's own origin (a page opened from disk: only from disk), by
// XMLHttpRequest (Chromium's fetch() cannot read file: URLs), never as a
// script. A packed page (tools/web_lesson.py pack --html) carries it in a
// <script type="application/json" id="glimmer-lesson"> data block; a
// --static folder names lesson.json in <meta name="glimmer-lesson">.
// base64 of kMaxUserBytes and room for the names.
const kMaxLessonText = Math.ceil(kMaxUserBytes / 3) * 4 + kMaxUserFiles * 4096;
// A packed lesson holds at most the packer's 64 MiB of files (web_lesson.py's
// LIMIT): its gzip block may not inflate past their base64 and names.
const kMaxPackedLessonText = Math.ceil((64 * 1024 * 1024) / 3) * 4 + kMaxUserFiles * 1024;
const refusal = (why) => Object.assign(new Error(why), { refusal: true });
const shownUrl = (text) => JSON.stringify(text.length > 80 ? text.slice(0, 80) + "..." : text);
const lessonUrlChecked = (text) => {
  let url;
  try { url = new URL(text, location.href); } catch { throw refusal("refused: the lesson " + shownUrl(text) + " is not a URL"); }
  if (location.protocol === "file:") {
    if (url.protocol !== "file:")
      throw refusal("refused: the lesson " + shownUrl(text) + " is not on this disk: a page opened from disk loads a lesson only from a file: URL");
  } else if ((url.protocol !== "http:" && url.protocol !== "https:") || url.origin !== location.origin) {
    throw refusal("refused: the lesson " + shownUrl(text) + " is not on this page's own site (" + location.origin
                  + "): a lesson is loaded only from beside the page");
  }
  return url;
};
const loadLessonText = (url) => new Promise((resolve, reject) => {
  const cannot = (why) => reject(refusal("cannot load the lesson " + shownUrl(url.href) + ": " + why));
  const request = new XMLHttpRequest();
  request.open("GET", url.href);
  request.overrideMimeType("text/plain; charset=utf-8");  // text to parse, whatever the server calls it
  request.onprogress = (e) => { if (e.loaded > kMaxLessonText) { request.abort(); cannot("larger than a lesson may be"); } };
  request.onload = () => {
    if (url.protocol === "file:" ? request.status !== 0 && request.status !== 200 : request.status !== 200)
      return cannot("the server answered " + request.status);
    // A redirect may not take the lesson to another origin.
    if (url.protocol !== "file:" && new URL(request.responseURL || url.href).origin !== location.origin)
      return cannot("it was redirected to another site");
    resolve(request.responseText);
  };
  request.onerror = () => cannot(url.protocol === "file:"
    ? "not readable (from disk, Chromium needs --allow-file-access-from-files; or serve the folder, or pack the lesson with --html)"
    : "no answer");
  request.send();
});
const base64Bytes = (text) => Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
// The lesson's text -> { name, files: [[path, Uint8Array], ...] }, or a
// refusal with the reason; paths are checked where they are mounted.
const parseLesson = (text, where) => {
  const notLesson = () => refusal("refused: " + where + ' is not a lesson: JSON {"files": {"path": "base64", ...}} (a lesson is data, never a script)');
  if (text.length > kMaxLessonText) throw refusal("refused: " + where + " is larger than a lesson may be");
  let lesson;
  try { lesson = JSON.parse(text); } catch { throw notLesson(); }
  const plain = (v) => v !== null && typeof v === "object" && !Array.isArray(v);
  if (!plain(lesson) || !plain(lesson.files)) throw notLesson();
  const entries = Object.entries(lesson.files);
  if (entries.length > kMaxUserFiles) throw refusal("refused: more than " + kMaxUserFiles + " files");
  let bytes = 0;
  for (const [path, data] of entries) {
    if (typeof data !== "string") throw notLesson();
    bytes += Math.floor(data.length / 4) * 3;
  }
  if (bytes > kMaxUserBytes) throw refusal("refused: more than " + kMaxUserBytes / (1024 * 1024) + " MiB");
  const files = entries.map(([path, data]) => {
    try { return [path, base64Bytes(data)]; } catch { throw refusal("refused: the file " + JSON.stringify(path) + " of " + where + " is not base64"); }
  });
  // The packer lists the lesson's scripts (each once, in its order); a
  // lesson without the list shows every script it holds.
  const scripts = Array.isArray(lesson.scripts)
    ? lesson.scripts.filter((s) => typeof s === "string" && Object.hasOwn(lesson.files, s)).slice(0, kMaxUserFiles) : null;
  return { name: typeof lesson.name === "string" ? lesson.name.slice(0, 200) : "", files, scripts };
};

// A packed lesson (tools/web_lesson.py pack) carries its files and the
// module's WebAssembly in the page itself, as data blocks: it opens from
// disk, no server.
const query = new URLSearchParams(location.search);
const dataBlock = (id) => {
  const block = document.getElementById(id);
  return block && block.tagName === "SCRIPT" && block.type !== "" && !/javascript|module/i.test(block.type) ? block : null;
};
const packedLesson = dataBlock("glimmer-lesson");
// A packed page's data blocks are base64 of gzip ("application/gzip": the
// packer compresses the module and the lesson, 8.5 MB down to under 3) and
// the browser undoes it natively (DecompressionStream), stopping at `limit`
// bytes so a hostile block cannot inflate without bound. Older packs wrote
// plain blocks: those are read as they are.
const gunzip = async (bytes, limit) => {
  if (typeof DecompressionStream === "undefined")
    throw refusal("refused: this browser cannot unpack the packed lesson (no DecompressionStream): use a current browser");
  const reader = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip")).getReader();
  const chunks = [];
  let size = 0;
  for (let r = await reader.read(); !r.done; r = await reader.read()) {
    size += r.value.length;
    if (size > limit) { reader.cancel(); throw refusal("refused: the packed lesson is larger than a lesson may be"); }
    chunks.push(r.value);
  }
  const out = new Uint8Array(size);
  let at = 0;
  for (const c of chunks) { out.set(c, at); at += c.length; }
  return out;
};
const blockBytes = (block, limit) =>
  block.type === "application/gzip" ? gunzip(base64Bytes(block.textContent), limit) : Promise.resolve(base64Bytes(block.textContent));
const blockText = async (block, limit) =>
  block.type === "application/gzip" ? new TextDecoder().decode(await blockBytes(block, limit)) : block.textContent;
const lessonMeta = document.querySelector('meta[name="glimmer-lesson"]');
const lessonUrl = query.has("lesson") ? query.get("lesson") : lessonMeta ? lessonMeta.content : null;
// Resolves to { lesson } (null: none) or { refused: reason }.
const lessonLoaded = (async () => {
  if (lessonUrl !== null) {
    const url = lessonUrlChecked(lessonUrl);
    return parseLesson(await loadLessonText(url), "the lesson " + shownUrl(lessonUrl));
  }
  return packedLesson ? parseLesson(await blockText(packedLesson, kMaxPackedLessonText), "the packed lesson") : null;
})().then((lesson) => ({ lesson }), (e) => ({ refused: e.refusal ? e.message : "refused: the lesson: " + e }));
const packedWasm = dataBlock("glimmer-wasm");
const kMaxWasmBytes = 64 * 1024 * 1024;
const moduleOptions = packedWasm ? blockBytes(packedWasm, kMaxWasmBytes).then((bytes) => ({ wasmBinary: bytes }))
                                 : Promise.resolve({});
Promise.all([moduleOptions.then(createGlimmer), lessonLoaded]).then(([glimmer, loaded]) => {
  // Since the page began to load: the module fetched, compiled and started
  // (PERFORMANCE.md splits the first picture's time at this mark).
  document.body.dataset.moduleReadyMs = performance.now().toFixed(0);
  // ?no-float-targets: behave as a browser without EXT_color_buffer_float.
  if (query.has("no-float-targets")) glimmer._glimmer_without_float_targets();
  // ?slice-ms=N: the live view's slice budget (0: whole frames), for tools/page-input-latency.mjs.
  if (query.has("slice-ms")) glimmer._glimmer_view_slice_ms(Number(query.get("slice-ms")) || 0);
  const FS = glimmer.FS;
  const check = glimmer.cwrap("glimmer_check", "number", ["string"]);
  const render = glimmer.cwrap("glimmer_render", "number", ["string", "number", "number", "string"]);
  const output = glimmer.cwrap("glimmer_last_output", "string", []);
  const viewOpen = glimmer.cwrap("glimmer_view_open", "number", ["string", "number", "number", "string"]);
  const viewSet = glimmer.cwrap("glimmer_view_set", "number", ["string"]);
  const viewValue = glimmer.cwrap("glimmer_view_value", "string", ["string"]);
  const viewControl = glimmer.cwrap("glimmer_view_control", "string", ["string"]);
  const viewDrawn = glimmer.cwrap("glimmer_view_drawn", "string", []);
  const viewCommand = glimmer.cwrap("glimmer_view_command", "string", ["string"]);
  const select = document.getElementById("script");
  const verdict = document.getElementById("verdict");
  const shown = document.getElementById("diagnostics");
  const canvas = document.getElementById("canvas");
  const picture = document.getElementById("picture");

  // Every .glib under a root, as its path below it ("scripts/bloom.glib").
  const scriptsUnder = (root) => {
    const found = [];
    const walk = (dir) => {
      for (const name of FS.readdir(dir)) {
        if (name === "." || name === "..") continue;
        const path = dir + "/" + name;
        if (FS.isDir(FS.stat(path).mode)) walk(path);
        else if (name.endsWith(".glib")) found.push(path.slice(root.length + 1));
      }
    };
    walk(root);
    return found.sort();
  };
  // The select's values are "ROOT:PATH"; the user's scripts come first. A
  // lesson (packed or linked) lists its own scripts only, each once; the
  // bundled lesson leaves out the project's test scripts (tests/...), which
  // a student would click and find broken on purpose (issue 27).
  const listScripts = () => {
    select.length = 0;
    for (const root of lesson ? ["/user"] : ["/user", "/lesson"])
      for (const s of root === "/user" && lesson && lesson.scripts ? lesson.scripts : scriptsUnder(root))
        if (root === "/user" || !s.startsWith("tests/"))
          select.add(new Option((root === "/user" ? "yours: " : "") + s, root + ":" + s));
  };

  // Replaces /user with `files`: [relativePath, Uint8Array] pairs. A path
  // that would leave /user ("..", absolute) is refused, as are more files
  // or bytes than the bounds above; the reason goes to the verdict.
  const mountUser = (files) => {
    let bytes = 0;
    for (const [path, data] of files) {
      bytes += data.length;
      if (path.split("/").some((part) => part === ".." || part === "") )
        return "refused: the path " + JSON.stringify(path) + " leaves the folder";
    }
    if (files.length > kMaxUserFiles) return "refused: more than " + kMaxUserFiles + " files";
    if (bytes > kMaxUserBytes) return "refused: more than " + kMaxUserBytes / (1024 * 1024) + " MiB";
    const clear = (dir) => {
      for (const name of FS.readdir(dir)) {
        if (name === "." || name === "..") continue;
        const path = dir + "/" + name;
        if (FS.isDir(FS.stat(path).mode)) { clear(path); FS.rmdir(path); } else FS.unlink(path);
      }
    };
    clear("/user");
    let at = "";
    try {
      for (const [path, data] of files) {
        at = path;
        const parts = path.split("/");
        let dir = "/user";
        for (const part of parts.slice(0, -1)) {
          dir += "/" + part;
          if (!FS.analyzePath(dir).exists) FS.mkdir(dir);
        }
        FS.writeFile("/user/" + path, data);
      }
    } catch (e) {  // "a" and "a/b" both, ".", a NUL: the folder cannot be written as it is
      clear("/user");
      listScripts();
      return "refused: the folder cannot be written as it is (at " + JSON.stringify(at) + ")";
    }
    listScripts();
    return "";
  };
  FS.mkdir("/user");

  // The diagnostics as the desktop prints them; each "file:line:col:" opens
  // that file at that place in the editor.
  const showDiagnostics = (text) => {
    shown.textContent = "";
    for (const line of text.split(/(?<=\n)/)) {
      const at = /^([^\s:]+):(\d+):(\d+): (error|warning|note):/.exec(line);
      if (!at) { shown.append(line); continue; }
      const jump = document.createElement("span");
      jump.className = "jump";
      jump.textContent = line;
      jump.title = "open " + at[1] + " at line " + at[2];
      jump.onclick = () => editor.open(at[1], Number(at[2]), Number(at[3]));
      shown.append(jump);
    }
  };
  const report = (path, exit, what) => {
    verdict.dataset.exit = String(exit);
    verdict.className = exit === 0 ? "ok" : "bad";
    verdict.textContent = path + ": " + (exit === 0 ? what : exit === 1 ? "errors" : "not run (usage: an unreadable script or a bad value)");
    showDiagnostics(output());
  };
  const refuse = (why) => {
    verdict.dataset.exit = "2";
    verdict.className = "bad";
    verdict.textContent = why;
    shown.textContent = "";
  };
  // "ROOT:PATH" or a bare PATH (under /user when a lesson was loaded, else
  // under /lesson) -> [root, path]; the script runs from its root.
  const locate = (value) => {
    const at = value.indexOf(":");
    if (at > 0 && value.startsWith("/")) return [value.slice(0, at), value.slice(at + 1)];
    return [lesson ? "/user" : "/lesson", value];
  };
  const runCheck = (value) => {
    const [root, path] = locate(value);
    FS.chdir(root);
    report(path, check(path), "no errors");
  };
  // The picture glimmer_render kept, as a PNG (the canvas shows the same).
  const keepPicture = () => {
    const w = glimmer._glimmer_pixels_width(), h = glimmer._glimmer_pixels_height();
    const at = glimmer._glimmer_pixels();
    const copy = document.createElement("canvas");
    copy.width = w; copy.height = h;
    const ctx = copy.getContext("2d");
    const img = ctx.createImageData(w, h);
    img.data.set(glimmer.HEAPU8.subarray(at, at + w * h * 4));
    ctx.putImageData(img, 0, 0);
    picture.dataset.png = copy.toDataURL("image/png");
  };
  // Save PNG downloads the picture as SCRIPT.png, the name `glimmer render`
  // users give it (the browser asks where, or puts it in Downloads); the
  // live view's picture as it is now, without the panel.
  const save = document.getElementById("save");
  let savedName = "glimmer.png";
  const download = (name) => {
    const link = document.createElement("a");
    link.href = picture.dataset.png;
    link.download = name;
    link.click();
  };
  save.onclick = () => {
    if (live && glimmer._glimmer_view_snapshot()) keepPicture();
    download(savedName);
  };
  const runRender = (value, width, height, sets) => {
    live = null;  // the one-shot render takes the canvas from the live view
    const [root, path] = locate(value);
    FS.chdir(root);
    canvas.width = width || 512;
    canvas.height = height || 512;
    const exit = render(path, width, height, sets);
    report(path, exit, "drawn");
    save.disabled = exit !== 0;
    if (exit === 0) {
      keepPicture();
      savedName = path.split("/").pop().replace(/\.glib$/, "") + ".png";
      // Since the page began to load: what a user waits for the first picture.
      if (!document.body.dataset.firstPictureMs) document.body.dataset.firstPictureMs = performance.now().toFixed(0);
    }
    return exit;
  };

  // The live view (web_view.cpp): the picture with the desktop's panel
  // beside it on the canvas, a frame each time the browser paints. A load
  // with errors keeps the last good picture and the slider values.
  let live = null;  // { root, path, width, height } of the open script
  let lastTick = 0;
  const tick = (now) => {
    if (!live) return;
    const asked = glimmer._glimmer_view_frame(lastTick ? (now - lastTick) / 1000 : 0);
    lastTick = now;
    // The layout's size for the next frame (resizing clears the canvas).
    const w = glimmer._glimmer_view_width(), h = glimmer._glimmer_view_height();
    if (w > 0 && h > 0 && (canvas.width !== w || canvas.height !== h)) { canvas.width = w; canvas.height = h; }
    if (asked & 1) runView(live.root + ":" + live.path, live.width, live.height, "");  // Reload: the files as they are now
    if (asked & 6) { keepPicture(); download(asked & 4 ? "glimmer-hardcopy.png" : savedName); }
    requestAnimationFrame(tick);
  };
  const runView = (value, width, height, sets) => {
    const [root, path] = locate(value);
    FS.chdir(root);
    const wasLive = live;
    const exit = viewOpen(path, width, height, sets);
    report(path, exit, "drawn");
    const files = glimmer.UTF8ToString(glimmer._glimmer_view_files()).split("\n").filter(Boolean);
    if (files.length) editor.setFiles(root, files);
    editor.mark(glimmer.UTF8ToString(glimmer._glimmer_view_messages()).split("\n").filter(Boolean).map((l) => {
      const [severity, file, line, col, message] = l.split("\t");
      return { severity, file, line: Number(line), col: Number(col), message };
    }));
    const shows = exit === 0 || (exit === 1 && glimmer._glimmer_view_snapshot());
    live = shows ? { root, path, width, height } : null;
    save.disabled = !shows;
    if (!shows) return exit;
    savedName = path.split("/").pop().replace(/\.glib$/, "") + ".png";
    if (!wasLive || wasLive.path !== path || wasLive.root !== root)
      vary.value = glimmer.UTF8ToString(glimmer._glimmer_view_sheet_suggestion());
    glimmer._glimmer_view_frame(0);  // the first picture, then the canvas at the layout's size
    canvas.width = glimmer._glimmer_view_width();
    canvas.height = glimmer._glimmer_view_height();
    glimmer._glimmer_view_frame(0);
    if (glimmer._glimmer_view_snapshot()) keepPicture();
    if (exit === 0 && !document.body.dataset.firstPictureMs) document.body.dataset.firstPictureMs = performance.now().toFixed(0);
    if (!wasLive) { lastTick = 0; requestAnimationFrame(tick); }
    return exit;
  };
  // The editor (glimmer-editor.js): an edit is written into the module's
  // file system and the script reloads a moment after typing stops.
  let folderHandle = null;  // a folder opened in place (showDirectoryPicker): Save writes into it
  const editor = createGlimmerEditor({
    element: document.getElementById("editor"), tabs: document.getElementById("tabs"),
    note: document.getElementById("edit-note"),
    readFile: (path) => FS.readFile(path, { encoding: "utf8" }), writeFile: (path, text) => FS.writeFile(path, text),
    onEdit: () => live ? runView(live.root + ":" + live.path, live.width, live.height, "") : runView(select.value, 512, 512, ""),
  });
  // Save file: into the folder opened in place where the browser allows it
  // (Chromium's File System Access), else a download of the file.
  const writeBack = async (path, text) => {
    if (!folderHandle || !live || live.root !== "/user") return false;
    try {
      let dir = folderHandle;
      const parts = path.split("/");
      for (const part of parts.slice(0, -1)) dir = await dir.getDirectoryHandle(part);
      const out = await (await dir.getFileHandle(parts.at(-1))).createWritable();
      await out.write(text);
      await out.close();
      return true;
    } catch (e) { return false; }
  };
  document.getElementById("save-file").onclick = async () => {
    const path = editor.shown();
    if (!path) return;
    if (await editor.saveCurrent(writeBack)) return;
    const link = document.createElement("a");
    link.href = URL.createObjectURL(new Blob([editor.cm.getValue()], { type: "text/plain" }));
    link.download = path.split("/").pop();
    link.click();
    document.getElementById("edit-note").textContent =
      `${path}: downloaded (this browser cannot write into the folder; your edit stays kept here)`;
  };
  document.getElementById("revert").onclick = () => editor.revertCurrent();

  // Save sheet: `glimmer sheet`'s labelled grid of the picture at several
  // values (one or two NAME=V1,V2,...), the other sliders as they are now.
  const vary = document.getElementById("vary");
  document.getElementById("save-sheet").onclick = () => {
    if (!live) return;
    const exit = glimmer.ccall("glimmer_view_sheet", "number", ["string"], [vary.value]);
    if (exit !== 0) { refuse(output().trim()); return; }
    keepPicture();
    download(live.path.split("/").pop().replace(/\.glib$/, "") + "-sheet.png");
  };

  canvas.tabIndex = 0;  // the panel's text fields take keys once the canvas is clicked
  canvas.addEventListener("mousedown", () => canvas.focus());
  document.getElementById("check").onclick = () => runCheck(select.value);
  document.getElementById("draw").onclick = () => runView(select.value, 512, 512, "");
  // For tests and the console (tools/test-web.sh drives these over the
  // DevTools protocol): the live view's state and a file written as an
  // editor would.
  globalThis.glimmerPage = {
    view: (value, width = 512, height = 512, sets = "") => runView(value, width, height, sets),
    set: (text) => viewSet(text),
    value: (name) => viewValue(name),
    control: (name) => viewControl(name).split(" ").filter(Boolean).map(Number),
    drawn: () => viewDrawn(),
    probe: () => glimmer.UTF8ToString(glimmer._glimmer_view_probe()),
    // One of `glimmer view`'s commands (set, show, values, probe X Y, split,
    // save, frames...) through the same viewer core; what the window would
    // print for it. A save keeps the picture for Save PNG (and snapshot()).
    command: (line) => {
      const said = viewCommand(line);
      if (said.startsWith("saved ")) keepPicture();
      return said;
    },
    errors: () => glimmer._glimmer_view_errors(),
    snapshot: () => { if (glimmer._glimmer_view_snapshot()) keepPicture(); return picture.dataset.png || ""; },
    readFile: (path) => FS.readFile(path, { encoding: "utf8" }),
    writeFile: (path, text) => FS.writeFile(path, text),
    reload: () => live && runView(live.root + ":" + live.path, live.width, live.height, ""),
    editor: () => editor,
    sheet: (text) => { vary.value = text; document.getElementById("save-sheet").click(); return picture.dataset.png || ""; },
  };

  // A folder picked or dropped: its files, their paths below the folder.
  const takeFiles = async (entries, name, handle = null) => {
    const files = [];
    for (const [path, file] of entries) {
      if (files.length > kMaxUserFiles) break;
      files.push([path, new Uint8Array(await file.arrayBuffer())]);
    }
    if (lesson) lesson.scripts = null;  // the picked folder's scripts are listed now, not the lesson's
    const why = mountUser(files);
    if (why) { refuse(why); return; }
    folderHandle = handle;
    editor.setFolder("user:" + name);
    editor.restoreDrafts("/user");
    if (select.length) { select.selectedIndex = 0; runView(select.value, 512, 512, ""); }
  };
  // webkitRelativePath is "folder/sub/file": the picked folder's own name goes.
  document.getElementById("folder").onchange = (e) =>
    takeFiles([...e.target.files].map((f) => [f.webkitRelativePath.split("/").slice(1).join("/"), f]),
              e.target.files.length ? e.target.files[0].webkitRelativePath.split("/")[0] : "");
  // A folder opened in place: the same files, and Save file writes back.
  const inPlace = document.getElementById("in-place");
  if (globalThis.showDirectoryPicker) {
    const walk = async (dir, prefix, out) => {
      for await (const [name, entry] of dir.entries()) {
        if (out.length > kMaxUserFiles) return;
        if (entry.kind === "file") out.push([prefix + name, await entry.getFile()]);
        else await walk(entry, prefix + name + "/", out);
      }
    };
    inPlace.onclick = async () => {
      let dir;
      try { dir = await showDirectoryPicker({ mode: "readwrite" }); } catch { return; }  // the user cancelled
      const out = [];
      await walk(dir, "", out);
      takeFiles(out, dir.name, dir);
    };
  } else {
    inPlace.hidden = true;  // Firefox, Safari: edits are downloaded
  }
  const readEntry = (entry, prefix, out) => new Promise((resolve) => {
    if (entry.isFile) entry.file((f) => { out.push([prefix + entry.name, f]); resolve(); }, resolve);
    else {
      const reader = entry.createReader();
      const more = () => reader.readEntries(async (list) => {
        if (!list.length) return resolve();
        for (const child of list) await readEntry(child, prefix + entry.name + "/", out);
        more();
      }, resolve);
      more();
    }
  });
  document.body.ondragover = (e) => e.preventDefault();
  document.body.ondrop = async (e) => {
    e.preventDefault();
    const out = [];
    for (const item of e.dataTransfer.items) {
      const entry = item.webkitGetAsEntry && item.webkitGetAsEntry();
      if (entry) await readEntry(entry, "", out);
    }
    // One dropped folder: paths below it, as with the picker.
    const top = new Set(out.map(([p]) => p.split("/")[0]));
    const strip = top.size === 1 && out.every(([p]) => p.includes("/"));
    takeFiles(out.map(([p, f]) => [strip ? p.slice(p.indexOf("/") + 1) : p, f]), strip ? [...top][0] : "dropped");
  };

  // Edits kept from an earlier visit come back before anything is drawn. A
  // refused lesson is said and nothing named in the query runs: its paths
  // were the lesson's.
  let lesson = loaded.lesson;
  const refused = loaded.refused || (lesson ? mountUser(lesson.files) : "");
  if (refused) lesson = null;
  if (lesson) {
    editor.setFolder("lesson:" + (lesson.name || lessonUrl || document.title));
    editor.restoreDrafts("/user");
  } else {
    listScripts();
    editor.setFolder("bundled");
    editor.restoreDrafts("/lesson");
  }
  if (refused) {
    refuse(refused);
    verdict.dataset.lesson = "refused";
    document.body.dataset.ready = "1";
    return;
  }
  // Opened with no script named, the page draws one: a lesson's first
  // script, or the bundled seed bloom (issue 27: it was blank until Draw).
  if (!query.get("check") && !query.get("render") && !query.get("view") && select.length) {
    const seed = [...select.options].find((o) => o.value === "/lesson:scripts/bloom.glib");
    if (!lesson && seed) select.value = seed.value;
    runView(select.value, 512, 512, "");
  }
  if (query.get("check")) runCheck(query.get("check"));
  if (query.get("render")) {
    const [w, h] = (query.get("size") || "512x512").split("x").map(Number);
    const exit = runRender(query.get("render"), w, h, query.get("set") || "");
    // ?frames=N: N more frames timed (PERFORMANCE.md's page-against-render figure).
    const frames = Number(query.get("frames") || 0);
    if (exit === 0 && frames > 0) picture.dataset.frameMs = glimmer._glimmer_time_frames(frames).toFixed(3);
  }
  // ?view=PATH[&size=WxH][&set=...]: the live view of a script.
  if (query.get("view")) {
    const [w, h] = (query.get("size") || "512x512").split("x").map(Number);
    runView(query.get("view"), w, h, query.get("set") || "");
  }
  document.body.dataset.ready = "1";
}).catch((e) => {
  // Said, not left as a blank page (from disk, the module's .wasm needs
  // --allow-file-access-from-files or a packed lesson).
  const verdict = document.getElementById("verdict");
  verdict.className = "bad";
  verdict.textContent = "the page could not start: " + e + (location.protocol === "file:"
    ? " (opened from disk, Chromium needs --allow-file-access-from-files; or serve the folder, or pack the lesson with --html)" : "");
});
