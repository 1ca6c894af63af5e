// The page's side of src/web/page_check.cpp and web_render.cpp: lists the
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
// time from the start of loading to the first picture; data-translations
// how many kept translations the page uses (-1: refused) and
// data-first-translations "HITS MISSES KEPT" at the first picture
// (web_translations.cpp). A refused lesson is
// data-exit="2" and data-lesson="refused" on #verdict, the reason its text.
// ?present opens in the presentation mode (the Present button's). Opened
// with none of ?check, ?render, ?view, the page keeps what a reload brings
// back (see stateKey below).
"use strict";
// What it starts from (glimmer-lesson.js, loaded before it): the lesson,
// the kept folder and the module's options, each a promise.
// Each start's own mark (data-module-ms, data-lesson-ms, data-kept-ms: ms
// since the page began to load), so the first picture's time can be split.
const marked = (name, promise) => promise.then((v) => { document.body.dataset[name] = performance.now().toFixed(0); return v; });
Promise.all([marked("moduleMs", moduleOptions.then((options) => createGlimmer(options))), marked("lessonMs", lessonLoaded),
             marked("keptMs", folderKept), translationsLoaded]).then(([glimmer, loaded, kept, translations]) => {
  // Since the page began to load: the module fetched, compiled and started
  // (PERFORMANCE.md splits the first picture's time at this mark).
  document.body.dataset.moduleReadyMs = performance.now().toFixed(0);
  // ?no-float-targets: behave as a browser without EXT_color_buffer_float.
  if (query.has("no-float-targets")) glimmer._glimmer_without_float_targets();
  // ?slice-ms=N: the live view's slice budget (0: whole frames), for tools/page-input-latency.mjs.
  if (query.has("slice-ms")) glimmer._glimmer_view_slice_ms(Number(query.get("slice-ms")) || 0);
  const FS = glimmer.FS;
  // The bundled lesson's translations (glimmer-lesson.js): data-translations
  // is how many are in use (-1: refused, the page translates everything).
  if (translations !== null) {
    FS.writeFile("/kept-translations.txt", translations);
    document.body.dataset.translations = glimmer.ccall("glimmer_translations_use", "number", ["string"], ["/kept-translations.txt"]);
  }
  const translationStats = () => glimmer.UTF8ToString(glimmer._glimmer_translations_stats());
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
  // A right click over the panel is ImGui's (a merged slider's "Split per
  // pass"): the browser's own menu would take the release (WebKit's does).
  canvas.addEventListener("contextmenu", (e) => e.preventDefault());

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
  // a student would click and find broken on purpose (issue 27). "yours: "
  // marks a folder the student picked or dropped, never a lesson's own
  // scripts (issue 39: a packed lesson's every script read "yours:").
  const listScripts = () => {
    select.length = 0;
    const lessons = lesson && lesson.scripts;
    for (const root of lesson ? ["/user"] : ["/user", "/lesson"])
      for (const s of root === "/user" && lessons ? lesson.scripts : scriptsUnder(root))
        if (root === "/user" || !s.startsWith("tests/"))
          select.add(new Option((root === "/user" && !lessons ? "yours: " : "") + s, root + ":" + s));
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
  // Under the canvas, folded: a count ("2 errors, 6 warnings") that opens
  // to them all, and the first error shown whole, wrapped in the canvas's
  // width, so a message never moves the picture or the editor.
  const firstError = document.getElementById("first-error");
  const allMessages = document.getElementById("all-messages");
  const messageCount = document.getElementById("message-count");
  const diagnosticStart = /^[^\s:][^:]*(?::\d+:\d+)?: (error|warning|note):/;
  const jumpTo = (line) => {
    const at = /^([^\s:]+):(\d+):(\d+): (error|warning|note):/.exec(line);
    if (!at) return document.createTextNode(line);
    const jump = document.createElement("span");
    jump.className = "jump";
    jump.textContent = line;
    jump.title = "open " + at[1] + " at line " + at[2];
    jump.onclick = () => editor.open(at[1], Number(at[2]), Number(at[3]));
    return jump;
  };
  const foldMessages = (text) => {
    const lines = text.split(/(?<=\n)/);
    let errors = 0, warnings = 0, first = null;
    for (const [i, line] of lines.entries()) {
      const m = diagnosticStart.exec(line);
      if (!m) continue;
      if (m[1] === "error") { if (first === null) first = i; ++errors; } else if (m[1] === "warning") ++warnings;
    }
    firstError.textContent = "";
    if (first !== null) {
      firstError.append(jumpTo(lines[first]));
      for (const line of lines.slice(first + 1)) {
        if (diagnosticStart.test(line) || /^\d+ errors?, \d+ warnings?/.test(line)) break;
        firstError.append(line);
      }
    }
    const plural = (n, word) => n + " " + word + (n === 1 ? "" : "s");
    if (errors + warnings > 0) {
      allMessages.dataset.count = String(errors + warnings);
      messageCount.textContent = [errors ? plural(errors, "error") : "", warnings ? plural(warnings, "warning") : ""]
        .filter(Boolean).join(", ") + (errors > 1 || warnings ? ": all messages" : "");
    } else if (text.trim()) {
      allMessages.dataset.count = "0";
      messageCount.textContent = "messages";
    } else {
      delete allMessages.dataset.count;
    }
  };
  const showDiagnostics = (text) => {
    foldMessages(text);
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
    foldMessages("");
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
    canvas.style.width = canvas.style.height = view.style.minWidth = "";  // the live view's box, if any, is not a render's
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
  // The kept state (see stateKey above).
  const stateName = "glimmer-state\n" + stateKey;
  let state = {};
  try { state = JSON.parse(localStorage.getItem(stateName)) || {}; } catch {}
  if (typeof state !== "object" || Array.isArray(state)) state = {};
  if (typeof state.values !== "object" || state.values === null) state.values = {};
  // Per script, the watch on (its `watch` command's FILE:LINE EXPRESSION):
  // a reload brings it back, as it brings the sliders (issue 39).
  if (typeof state.watches !== "object" || state.watches === null) state.watches = {};
  const keepState = () => { try { localStorage.setItem(stateName, JSON.stringify(state)); } catch {} };
  const viewSets = glimmer.cwrap("glimmer_view_sets", "string", []);
  // The watch: { spec, summary, error } (each "" when there is none).
  const watchNow = () => {
    const [spec = "", summary = "", error = ""] = glimmer.UTF8ToString(glimmer._glimmer_view_watch()).split("\t");
    return { spec, summary, error };
  };
  // `kept[key] = text` ("" drops it), the newest last: at most 50 scripts'
  // are kept. True when it changed anything.
  const keepNewest = (kept, key, text) => {
    if ((kept[key] || "") === text) return false;
    delete kept[key];
    if (text) kept[key] = text;
    for (const old of Object.keys(kept).slice(0, -50)) delete kept[old];
    return true;
  };
  let lastKept = 0;
  const keepValues = () => {
    const key = live.root + ":" + live.path, sets = viewSets(), watch = watchNow();
    const watching = watch.summary ? watch.spec : "";  // a spec with no summary: stopped, or refused
    const changed = keepNewest(state.watches, key, watching);
    if ((sets && keepNewest(state.values, key, sets)) || changed) keepState();
  };
  // The canvas no taller than what the page shows of its column, less the
  // verdict and the start of the first error below it: a long panel (a
  // watch on, many Programs) scrolls inside itself, and the picture, the
  // verdict and the error stay in the window (issue 39). Not where the
  // column grows with its content (a small screen's stacked layout) or in
  // the presentation mode, which fits the canvas by scaling it.
  const view = document.getElementById("view");
  // Where even the picture is taller than that (a 720-pixel laptop
  // screen's Chromium leaves the column about 500), the canvas is drawn
  // smaller to fit, to 60% at the least; the input maps back by its box.
  let lastFit = -1e9, shrink = 1;
  const fitCanvas = (now) => {
    if (now - lastFit < 250) return;
    lastFit = now;
    let fit = 8192, want = 1;
    if (getComputedStyle(view).overflowY !== "visible" && !document.body.classList.contains("present")) {
      const ratio = window.devicePixelRatio || 1;
      const lineH = parseFloat(getComputedStyle(verdict).lineHeight) || 20;
      const below = verdict.offsetHeight + lineH * 0.6 + Math.min(firstError.offsetHeight, lineH * 4);
      const room = view.clientHeight - below;
      fit = Math.floor(room * ratio);
      const tall = glimmer._glimmer_view_height() / ratio;
      if (room > 0 && tall > room) want = Math.max(0.6, room / tall);
    }
    glimmer._glimmer_view_fit_height(Math.max(64, fit));
    if (Math.abs(want - shrink) > 0.005) { shrink = want; if (canvas.width) styleCanvas(); }
  };
  let lastTick = 0;
  const tick = (now) => {
    if (!live) return;
    fitCanvas(now);
    const asked = glimmer._glimmer_view_frame(lastTick ? (now - lastTick) / 1000 : 0);
    lastTick = now;
    // The layout's size for the next frame (resizing clears the canvas).
    const w = glimmer._glimmer_view_width(), h = glimmer._glimmer_view_height();
    if (w > 0 && h > 0 && (canvas.width !== w || canvas.height !== h)) sizeCanvas(w, h);
    if (asked & 1) runView(live.root + ":" + live.path, live.width, live.height, "");  // Reload: the files as they are now
    if (asked & 6) { keepPicture(); download(asked & 4 ? "glimmer-hardcopy.png" : savedName); }
    if (restoring && live && now - lastKept > 250) { lastKept = now; keepValues(); }
    requestAnimationFrame(tick);
  };
  // The canvas's backing store in its own pixels, its box on the page in
  // CSS pixels: the same size at every devicePixelRatio (the input maps
  // back, web_view_input.cpp).
  let scaled = false;
  // The canvas's column keeps the widest the canvas has been at this width
  // in this window: a message that shrinks the picture (fitCanvas's cap,
  // to keep the first error in the window) moves neither the column's edge
  // nor the editor beside it, where the student is typing.
  let columnFor = "", columnWidth = 0;
  const styleCanvas = () => {
    const ratio = window.devicePixelRatio || 1;
    const width = canvas.width / ratio * shrink;
    canvas.style.width = width + "px";
    canvas.style.height = canvas.height / ratio * shrink + "px";
    const key = [canvas.width, ratio, window.innerWidth, window.innerHeight].join(" ");
    if (key !== columnFor) { columnFor = key; columnWidth = 0; }
    columnWidth = Math.max(columnWidth, width);
    // Its content's width and the scrollbar's gutter beside it (stable: reserved either way).
    view.style.minWidth = columnWidth + (view.offsetWidth - view.clientWidth) + "px";
  };
  const sizeCanvas = (w, h) => {
    canvas.width = w;
    canvas.height = h;
    styleCanvas();
  };
  // `values`: sets kept from an earlier visit ("NAME=V;..."), each given back
  // through glimmer_view_set before the first frame (one the script no
  // longer takes is dropped, never an error).
  let keeping = Promise.resolve();  // the live view's picture copied (runView): the page is ready after it
  const runView = (value, width, height, sets, values = "") => {
    const [root, path] = locate(value);
    FS.chdir(root);
    const wasLive = live;
    // The copy of the earlier picture goes; this one's comes a frame after
    // it is shown (below), so a reader of data-png waits for it.
    delete picture.dataset.png;
    const opening = performance.now();
    if (!document.body.dataset.firstOpenAtMs) document.body.dataset.firstOpenAtMs = opening.toFixed(0);
    const exit = viewOpen(path, width, height, sets);
    if (!document.body.dataset.firstOpenMs) document.body.dataset.firstOpenMs = (performance.now() - opening).toFixed(0);
    if (exit === 0) for (const set of values.split(";").filter(Boolean)) viewSet(set);
    report(path, exit, "drawn");
    const files = glimmer.UTF8ToString(glimmer._glimmer_view_files()).split("\n").filter(Boolean);
    const marks = glimmer.UTF8ToString(glimmer._glimmer_view_messages()).split("\n").filter(Boolean).map((l) => {
      const [severity, file, line, col, message] = l.split("\t");
      return { severity, file, line: Number(line), col: Number(col), message };
    });
    const fillEditor = () => {
      if (files.length) editor.setFiles(root, files);
      editor.mark(marks);
    };
    const shows = exit === 0 || (exit === 1 && glimmer._glimmer_view_snapshot());
    // The page's first picture comes before the editor's files (about 100 ms
    // of CodeMirror on this machine's Chromium, issue 39); later opens, and
    // a script that shows nothing, fill the editor at once.
    const first = exit === 0 && !document.body.dataset.firstPictureMs;
    if (!first) fillEditor();
    live = shows ? { root, path, width, height } : null;
    if (shows && restoring) { state.script = root + ":" + path; keepState(); }
    save.disabled = !shows;
    if (!shows) return exit;
    savedName = path.split("/").pop().replace(/\.glib$/, "") + ".png";
    if (!wasLive || wasLive.path !== path || wasLive.root !== root)
      vary.value = glimmer.UTF8ToString(glimmer._glimmer_view_sheet_suggestion());
    // The panel and the picture at the screen's devicePixelRatio (a Retina
    // Mac's 2): the canvas's pixels are the screen's, its box the same size
    // on the page, the panel's text rasterised at that scale, not stretched.
    if (!scaled && (window.devicePixelRatio || 1) !== 1) viewCommand("scale " + Math.min(4, Math.max(0.5, window.devicePixelRatio)));
    scaled = true;
    lastFit = -1e9;
    fitCanvas(performance.now());
    const framing = performance.now();
    if (!document.body.dataset.firstFramesAtMs) document.body.dataset.firstFramesAtMs = framing.toFixed(0);
    glimmer._glimmer_view_frame(0);  // the first picture, then the canvas at the layout's size
    sizeCanvas(glimmer._glimmer_view_width(), glimmer._glimmer_view_height());
    glimmer._glimmer_view_frame(0);
    if (!document.body.dataset.firstFramesMs) document.body.dataset.firstFramesMs = (performance.now() - framing).toFixed(0);
    // The picture is on the canvas; the browser shows it in its next frame
    // (the first picture's mark: that frame's callback). The copy a reload,
    // Save and the tests read (a read-back, a PNG) is made after that frame,
    // not before it, where it held the first picture back (issue 39).
    const shown = live;
    keeping = new Promise((resolve) => requestAnimationFrame(() => {
      if (first && !document.body.dataset.firstPictureMs) {
        document.body.dataset.firstPictureMs = performance.now().toFixed(0);
        // "HITS MISSES KEPT": the first picture's shaders from the kept
        // translations and translated (tests/web/opening.sh reads it).
        document.body.dataset.firstTranslations = translationStats();
      }
      setTimeout(() => {
        if (first) fillEditor();
        if (live === shown && glimmer._glimmer_view_snapshot()) keepPicture();
        resolve();
      }, 0);
    }));
    if (!wasLive) { lastTick = 0; requestAnimationFrame(tick); }
    return exit;
  };
  // The editor (glimmer-editor.js): an edit is written into the module's
  // file system and the script reloads a moment after typing stops.
  let folderHandle = null;  // a folder opened in place (showDirectoryPicker): Save writes into it
  const editor = createGlimmerEditor({
    element: document.getElementById("editor"), tabs: document.getElementById("tabs"),
    note: document.getElementById("edit-note"),
    readFile: (path) => FS.readFile(path, { encoding: "utf8" }),
    // Served by `glimmer serve`, each edit also goes to the server (glimmer-serve.js).
    writeFile: (path, text) => { FS.writeFile(path, text); if (globalThis.glimmerServe) globalThis.glimmerServe.edited(path, text); },
    onShow: (path) => { if (restoring && live) { state.shown = path; keepState(); } },
    onEdit: () => live ? runView(live.root + ":" + live.path, live.width, live.height, "") : runView(select.value, 512, 512, ""),
  });
  // Save file: into the folder opened in place where the browser allows it
  // (Chromium's File System Access), else a download of the file.
  const writeBack = async (path, text) => {
    if (!folderHandle || !live || live.root !== "/user") return false;
    try {
      // A handle kept from an earlier visit asks again (Save file is the click it needs).
      if (folderHandle.queryPermission && (await folderHandle.queryPermission({ mode: "readwrite" })) !== "granted" &&
          (await folderHandle.requestPermission({ mode: "readwrite" })) !== "granted") return false;
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

  // Presentation mode (glimmer-present.js): the Present button, ?present, Esc.
  const presentation = presentationMode(canvas, viewCommand, () => live !== null);
  const present = presentation.present;
  blurMeasurement(glimmer);  // Measure blurs on this machine (glimmer-tradeoff.js)

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
    // The watch: { spec, summary, error } (each "" when there is none).
    watch: watchNow,
    // One of `glimmer view`'s commands (set, show, values, probe X Y, split,
    // save, frames...) through the same viewer core; what the window would
    // print for it. A save keeps the picture for Save PNG (and snapshot()).
    command: (line) => {
      const said = viewCommand(line);
      if (said.startsWith("saved ")) keepPicture();
      return said;
    },
    errors: () => glimmer._glimmer_view_errors(),
    // "HITS MISSES KEPT" since the page opened (web_translations.cpp).
    translations: translationStats,
    snapshot: () => { if (glimmer._glimmer_view_snapshot()) keepPicture(); return picture.dataset.png || ""; },
    readFile: (path) => FS.readFile(path, { encoding: "utf8" }),
    writeFile: (path, text) => FS.writeFile(path, text),
    reload: () => live && runView(live.root + ":" + live.path, live.width, live.height, ""),
    editor: () => editor,
    sheet: (text) => { vary.value = text; document.getElementById("save-sheet").click(); return picture.dataset.png || ""; },
    // The presentation mode on or off; its factor then (1: off, or not fitted yet).
    present: (on) => { present(on); return presentation.factor(); },
  };

  // A folder picked or dropped: its files, their paths below the folder.
  const takeFiles = async (entries, name, handle = null) => {
    const files = [];
    for (const [path, file] of entries) {
      if (files.length > kMaxUserFiles) break;
      files.push([path, new Uint8Array(await file.arrayBuffer())]);
    }
    if (!useFolder(files, name, handle)) return;
    keepFolder(files, name, handle);
    if (select.length) { select.selectedIndex = 0; runView(select.value, 512, 512, ""); }
  };
  // A folder's files into /user, its kept edits on them; false: refused.
  const useFolder = (files, name, handle) => {
    if (lesson) lesson.scripts = null;  // the picked folder's scripts are listed now, not the lesson's
    forget.hidden = false;  // a kept folder refused can be forgotten too
    const why = mountUser(files);
    if (why) { refuse(why); return false; }
    folderHandle = handle;
    editor.setFolder("user:" + name);
    editor.restoreDrafts("/user");
    return true;
  };
  // The folder kept for the next visit: its files, and its handle where the
  // browser can keep one (else the files alone). Storage refused (full,
  // private browsing) is said in the editor's note.
  const keepFolder = (files, name, handle) => {
    if (!restoring || !globalThis.indexedDB) return;
    const put = (record) => folderStore("readwrite", (s) => s.put(record, stateKey));
    put({ name, files, handle }).catch(() => put({ name, files, handle: null })).catch((e) => {
      document.getElementById("edit-note").textContent = "your folder is not kept in this browser for a reload: " + e;
    });
  };
  const forget = document.getElementById("forget-folder");
  forget.onclick = async () => {
    try { await folderStore("readwrite", (s) => s.delete(stateKey)); } catch {}
    delete state.script; delete state.shown;
    keepState();
    location.reload();
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
  // A reload brings back the folder kept in this browser (issue 27).
  if (restoring && kept && Array.isArray(kept.files) && typeof kept.name === "string")
    useFolder(kept.files, kept.name, kept.handle || null);
  // Opened with no script named, the page draws one: the script on show
  // before a reload, with its sliders' values and the file that was open in
  // the editor; else a lesson's first script, or the bundled seed bloom
  // (issue 27: it was blank until Draw).
  if (restoring && select.length) {
    const seed = [...select.options].find((o) => o.value === "/lesson:scripts/bloom.glib");
    const wasShown = state.shown;
    if ([...select.options].some((o) => o.value === state.script)) select.value = state.script;
    else if (!lesson && seed) select.value = seed.value;
    runView(select.value, 512, 512, "", typeof state.values[select.value] === "string" ? state.values[select.value] : "");
    const watched = state.watches[select.value];
    if (live && typeof watched === "string" && watched) viewCommand("watch " + watched.slice(0, 2000));
    // The editor's tabs come with the files, after the first picture.
    keeping.then(() => {
      if (wasShown && [...document.querySelectorAll("#tabs button")].some((b) => b.dataset.path === wasShown)) editor.open(wasShown);
    });
  }
  if (query.has("present")) present(true);
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
  keeping.then(() => { document.body.dataset.ready = "1"; });
}).catch((e) => {
  // Said, not left as a blank page (from disk, the module's .wasm needs
  // --allow-file-access-from-files or a packed lesson).
  const verdict = document.getElementById("verdict");
  verdict.className = "bad";
  verdict.dataset.exit = "2";
  verdict.textContent = "the page could not start: " + e;
  // Opened from disk (a double-click on index.html), the browser does not
  // let the page read glimmer-web.wasm beside it: what to do instead.
  const box = document.getElementById("cannot-start");
  box.hidden = false;
  document.getElementById("work").style.display = "none";  // an empty canvas and editor say nothing
  box.dataset.fromDisk = location.protocol === "file:" ? "1" : "0";
  const say = (html) => { box.innerHTML = html; };
  if (location.protocol === "file:") {
    say(`<strong>This page was opened from disk, and the browser will not let it load its WebAssembly module
      (glimmer-web.wasm) from there.</strong> Do one of these:
      <ul><li>Open the one-file lesson instead: your teacher makes it with
        <code>python3 tools/web_lesson.py pack LESSON_FOLDER build-web/src/web --html lesson.html</code>; it opens from
        disk with a double-click, in any browser.</li>
      <li>Or serve this folder: in a terminal in the folder that holds this index.html, run
        <code>python3 -m http.server</code> and open <code>http://localhost:8000/</code>.</li>
      <li>(Chromium only: start it with <code>--allow-file-access-from-files</code>.)</li></ul>`);
  } else {
    say(`<strong>The page could not start.</strong> This browser may lack WebAssembly or WebGL 2: use a current
      Chrome, Edge, Firefox or Safari.`);
  }
  box.append(document.createElement("small"));
  box.lastChild.textContent = "(" + e + ")";
});
