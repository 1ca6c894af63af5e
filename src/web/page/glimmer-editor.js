// The page's code editor: the open script and its shaders in CodeMirror 5
// (Debian's libjs-codemirror; GLSL through its C-like mode, .glib through a
// small mode below), each diagnostic marked on its line with its message,
// and every edit kept in the browser's storage until it is saved, so a
// reload of the page (or a closed tab) loses nothing a student typed.
//
// The page (glimmer-page.js) hands it the module's file system and is told
// of each edit; the editor writes the edit into the file system itself, so
// the next load of the script sees it.
//
//   const editor = createGlimmerEditor({ element, tabs, note, readFile, writeFile, onEdit, onShow })
//                                   onShow(path): a file is on show (the page keeps it for a reload)
//   editor.setFolder(id)            drafts are kept per folder: "lesson", "user:NAME", ...
//   editor.restoreDrafts(root)      writes this folder's kept edits into the file system
//   editor.setFiles(root, paths)    the script and its shaders, as tabs
//   editor.open(path, line, col)    shows a file (at a line)
//   editor.mark(messages)           [{severity, file, line, col, message}]
//   editor.saveCurrent(writeBack)   writeBack(path, text) -> Promise<bool>;
//                                   false: the page downloads it instead
//   editor.revertCurrent()          the file on show as the folder had it; its kept edit goes
//   editor.watchHere()              watches it (the Watch button, Alt-W); what the core said
//   editor.watchAtCursor()          {path, line, expression} for a watch (issue 28): the selection
//                                   on one line, else the variable under the cursor (with its
//                                   .field and [index]); null on a .glib or an empty spot
"use strict";

// .glib: a command word starts each line; '#' starts a comment; uniform
// ranges are <min default max>; strings are file names.
CodeMirror.defineSimpleMode("glib", {
  start: [
    { regex: /#.*/, token: "comment" },
    { regex: /"(?:[^\\"]|\\.)*"?/, token: "string" },
    { regex: /<[^>]*>?/, token: "string-2" },
    { regex: /[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?/, token: "number" },
    { regex: /[A-Za-z_][A-Za-z0-9_]*/, token: "keyword", sol: true },
    { regex: /[A-Za-z_][\w.\/-]*/, token: "variable" },
  ],
  meta: { lineComment: "#" },
});

// Kept edits: localStorage, one entry per file, "glimmer-draft\n" + folder +
// "\n" + path. A browser keeps about 5 MB per page; a full store is said in
// the note, never silently dropped.
const kDraftPrefix = "glimmer-draft\n";

globalThis.createGlimmerEditor = ({ element, tabs, note, readFile, writeFile, onEdit, onShow = () => {} }) => {
  const cm = CodeMirror(element, {
    lineNumbers: true, indentUnit: 4, tabSize: 4, theme: "glimmer",
    lineWrapping: true,  // a long line wraps in the editor's width: the editor never scrolls sideways
    gutters: ["glimmer-marks", "CodeMirror-linenumbers"],
  });
  let folder = "lesson";
  let root = "/lesson";
  let shown = null;  // the path on show
  let quiet = false; // a file being put into the editor is not an edit
  let widgets = [];
  let lastMessages = [];
  let pending = null;
  let originals = {};  // each edited file's text as the folder had it, for Revert
  const key = (path) => kDraftPrefix + folder + "\n" + path;
  const abs = (path) => root + "/" + path;
  const say = (text, bad = false) => { note.textContent = text; note.title = text; note.className = bad ? "bad" : ""; };

  const modeOf = (path) => path.endsWith(".glib") ? "glib" : "x-shader/x-fragment";
  const show = (path) => {
    let text;
    try { text = readFile(abs(path)); } catch { say(`${path}: not found in the folder`, true); return false; }
    quiet = true;
    cm.setOption("mode", modeOf(path));
    cm.setValue(text);
    cm.clearHistory();
    quiet = false;
    shown = path;
    for (const b of tabs.querySelectorAll("button")) b.classList.toggle("open", b.dataset.path === path);
    mark(lastMessages);
    onShow(path);
    return true;
  };

  // An edit: into the file system now, into the kept drafts, and the page
  // reloads the script a moment after typing stops.
  cm.on("change", () => {
    if (quiet || !shown) return;
    const text = cm.getValue();
    if (!(shown in originals)) originals[shown] = readFile(abs(shown));  // the file system has not seen this edit yet
    writeFile(abs(shown), text);
    if (text === originals[shown]) {  // a typo taken back: the folder's text again, nothing to keep (issue 39)
      localStorage.removeItem(key(shown));
      delete originals[shown];
      say(`${shown}: as the folder has it`);
    } else {
      try { localStorage.setItem(key(shown), text); say(`${shown}: edited (kept in this browser until saved)`); }
      catch { say(`${shown}: edited, but the browser's storage is full: save it to keep it`, true); }
    }
    clearTimeout(pending);
    pending = setTimeout(() => onEdit(shown), 350);
  });

  // Watch (issue 28): the value under the cursor (or the selection) over
  // its pass, through the viewer core's `watch` command, as `glimmer view`
  // runs it; the panel then shows its range and the probe its floats. A
  // button beside Save file and Revert, and Alt-W in the editor.
  const watchHere = () => {
    const page = globalThis.glimmerPage;
    const at = api.watchAtCursor();
    if (!page) return "";
    if (!at) { say("Watch: put the cursor on a variable of a shader (or select an expression)", true); return ""; }
    const said = page.command(`watch ${at.path}:${at.line} ${at.expression}`);
    const first = said.split("\n")[0];
    say(first, !first.startsWith("watch "));
    return said;
  };
  const watchButtons = document.createElement("span");
  watchButtons.id = "watch-buttons";
  watchButtons.innerHTML = ' <button id="watch" title="the value under the cursor (or the selection) over its pass (Alt-W)">' +
    'Watch</button> <button id="watch-off" title="back to the picture">Stop watching</button>';
  tabs.parentElement.appendChild(watchButtons);
  watchButtons.querySelector("#watch").onclick = watchHere;
  watchButtons.querySelector("#watch-off").onclick = () => {
    if (globalThis.glimmerPage) say(globalThis.glimmerPage.command("watch off"));
  };
  cm.setOption("extraKeys", { "Alt-W": () => { watchHere(); } });

  const mark = (messages) => {
    lastMessages = messages;
    for (const w of widgets) w.clear();
    widgets = [];
    cm.clearGutter("glimmer-marks");
    for (let i = 0; i < cm.lineCount(); ++i) cm.removeLineClass(i, "background");
    if (!shown) return;
    for (const m of messages) {
      if (m.file !== shown || m.line < 1 || m.line > cm.lineCount() || m.severity === "note") continue;
      const line = m.line - 1;
      cm.addLineClass(line, "background", m.severity === "error" ? "glimmer-error-line" : "glimmer-warning-line");
      const dot = document.createElement("span");
      dot.className = "glimmer-mark-" + m.severity;
      dot.textContent = m.severity === "error" ? "●" : "▲";
      dot.title = m.message;
      cm.setGutterMarker(line, "glimmer-marks", dot);
      const box = document.createElement("div");
      box.className = "glimmer-message glimmer-message-" + m.severity;
      box.textContent = `${m.severity}: ${m.message}`;
      // in the text's column: the editor wraps its lines, so the message wraps there too
      const open = () => { const w = cm.addLineWidget(line, box, { coverGutter: false }); widgets.push(w); return w; };
      // An error's message is open under its line. A warning's is said
      // quietly: the line tinted, its mark in the gutter, its text there on
      // hover and in the list below; a click on the mark opens or closes it
      // (issue 39: the seed's own warnings opened as three yellow blocks).
      if (m.severity === "error") open();
      else {
        let shownBox = null;
        dot.style.cursor = "pointer";
        dot.onclick = () => {
          if (shownBox) { shownBox.clear(); widgets = widgets.filter((w) => w !== shownBox); shownBox = null; }
          else shownBox = open();
        };
      }
    }
  };

  const api = {
    cm,
    watchHere,
    setFolder: (id) => { folder = id; originals = {}; shown = null; },
    // Kept edits of this folder's files back into the file system (a
    // reloaded page, a folder picked again); returns the paths restored.
    restoreDrafts: (rootDir) => {
      root = rootDir;
      const restored = [];
      for (let i = 0; i < localStorage.length; ++i) {
        const k = localStorage.key(i);
        if (!k.startsWith(kDraftPrefix + folder + "\n")) continue;
        const path = k.slice((kDraftPrefix + folder + "\n").length);
        let original;
        try { original = readFile(abs(path)); } catch { continue; }  // only files the folder has
        if (localStorage.getItem(k) === original) {  // kept before a typo was taken back: no edit
          localStorage.removeItem(k);
          --i;
          continue;
        }
        if (!(path in originals)) originals[path] = original;
        writeFile(abs(path), localStorage.getItem(k));
        restored.push(path);
      }
      if (restored.length) say(`restored your unsaved edits of ${restored.join(", ")} (Revert drops them)`);
      return restored;
    },
    setFiles: (rootDir, paths) => {
      root = rootDir;
      const before = [...tabs.querySelectorAll("button")].map((b) => b.dataset.path).join("\n");
      if (before !== paths.join("\n")) {
        tabs.textContent = "";
        for (const path of paths) {
          const b = document.createElement("button");
          b.dataset.path = path;
          b.textContent = path.split("/").pop();
          b.title = path;
          b.onclick = () => show(path);
          tabs.appendChild(b);
        }
      }
      if (!shown || !paths.includes(shown)) show(paths[0]);
    },
    open: (path, line = 0, col = 0) => {
      if (path !== shown && !show(path)) return;
      if (line > 0) {
        cm.setCursor({ line: line - 1, ch: Math.max(0, col - 1) });
        cm.scrollIntoView(null, 80);
        cm.focus();
      }
    },
    mark,
    shown: () => shown,
    hasDraft: (path) => localStorage.getItem(key(path)) !== null,
    saveCurrent: async (writeBack) => {
      if (!shown) return false;
      const ok = await writeBack(shown, cm.getValue());
      if (ok) { localStorage.removeItem(key(shown)); delete originals[shown]; say(`${shown}: saved`); }
      return ok;
    },
    watchAtCursor: () => {
      if (!shown || shown.endsWith(".glib")) return null;
      const from = cm.getCursor("from"), to = cm.getCursor("to");
      if (from.line === to.line && from.ch !== to.ch) {
        const expression = cm.getRange(from, to).trim();
        return expression ? { path: shown, line: from.line + 1, expression } : null;
      }
      // The word under the cursor, with what it is made of on either side:
      // rgbblur.g, weights[i], vST.
      const text = cm.getLine(from.line);
      const part = /[A-Za-z0-9_.\[\]]/;
      let a = from.ch, b = from.ch;
      while (a > 0 && part.test(text[a - 1])) --a;
      while (b < text.length && part.test(text[b])) ++b;
      const expression = text.slice(a, b).replace(/^[.\]]+|[.\[]+$/g, "");
      return /^[A-Za-z_]/.test(expression) ? { path: shown, line: from.line + 1, expression } : null;
    },
    // The file as the folder had it: the kept edit goes.
    revertCurrent: () => {
      if (!shown || !(shown in originals)) return;
      localStorage.removeItem(key(shown));
      writeFile(abs(shown), originals[shown]);
      delete originals[shown];
      show(shown);
      say(`${shown}: reverted`);
      onEdit(shown);
    },
  };
  return api;
};
