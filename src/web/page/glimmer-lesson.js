// What the page starts from, before the module runs (glimmer-page.js waits
// on these): the lesson named by the link, packed into the page or beside
// it, checked as data; the folder and state kept from an earlier visit; the
// module's WebAssembly where the page carries it. Globals of the page's
// classic scripts (index.html loads this first), no DOM but the data
// blocks and the query.
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
const loadLessonText = (url, limit = kMaxLessonText) => new Promise((resolve, reject) => {
  const cannot = (why) => reject(refusal("cannot load the lesson " + shownUrl(url.href) + ": " + why));
  const request = new XMLHttpRequest();
  request.open("GET", url.href);
  request.overrideMimeType("text/plain; charset=utf-8");  // text to parse, whatever the server calls it
  request.onprogress = (e) => { if (e.loaded > limit) { request.abort(); cannot("larger than a lesson may be"); } };
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
// A plain loop: Uint8Array.from(atob(text), mapper) called the mapper per
// byte and took 530 ms for a packed page's 3 MB module in V8, the loop 23
// (issue 39: most of the packed lesson's later first picture).
const base64Bytes = (text) => {
  const chars = atob(text);
  const out = new Uint8Array(chars.length);
  for (let i = 0; i < chars.length; ++i) out[i] = chars.charCodeAt(i);
  return out;
};
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
// What a reload brings back (issue 27), kept per page (its address and its
// lesson): the script on show, the file open in the editor and every
// slider's value in localStorage ("glimmer-state\n" + key, JSON); a folder
// picked or dropped, its files (and its handle, where the browser can keep
// one: Chromium's File System Access) in IndexedDB, database "glimmer",
// store "folders", under the same key. Only a page opened without naming a
// script (?check, ?render, ?view) restores or keeps anything.
const stateKey = location.pathname + "\n" + (lessonUrl !== null ? lessonUrl : packedLesson ? "packed" : "");
const restoring = !query.get("check") && !query.get("render") && !query.get("view");
const folderStore = (mode, work) => new Promise((resolve, reject) => {
  const open = indexedDB.open("glimmer", 1);
  open.onupgradeneeded = () => open.result.createObjectStore("folders");
  open.onerror = () => reject(open.error);
  open.onsuccess = () => {
    const db = open.result;
    let request;
    try {
      const tx = db.transaction("folders", mode);
      request = work(tx.objectStore("folders"));
      tx.oncomplete = () => { db.close(); resolve(request && request.result); };
      tx.onerror = tx.onabort = () => { db.close(); reject(tx.error); };
    } catch (e) { db.close(); reject(e); }
  };
});
// The kept folder ({ name, files: [[path, Uint8Array]...], handle? }), or
// null; a browser without IndexedDB (or one that never answers) keeps none.
const folderKept = restoring && globalThis.indexedDB
  ? Promise.race([folderStore("readonly", (s) => s.get(stateKey)), new Promise((r) => setTimeout(r, 3000, null))]).catch(() => null)
  : Promise.resolve(null);
const packedWasm = dataBlock("glimmer-wasm");
const kMaxWasmBytes = 64 * 1024 * 1024;
const moduleOptions = packedWasm ? blockBytes(packedWasm, kMaxWasmBytes).then((bytes) => ({ wasmBinary: bytes }))
                                 : Promise.resolve({});
// The bundled lesson's translations to GLSL ES 3.00, made when the module
// was built (src/web/web_translations.cpp): with them the first picture
// calls no glslang, whose first call Chromium compiles for 0.4-0.8 s (issue
// 39). A packed page carries them as a data block; a served page reads them
// from beside it as it reads a lesson (loadLessonText: its own origin, its
// own bound; a packed page without the block has none: nothing beside it
// is asked for). Only a speed-up: a page without them (?no-translations, a
// failed read) translates every shader, as it did before.
const packedTranslations = dataBlock("glimmer-translations");
const kMaxTranslationsText = 32 * 1024 * 1024;
const translationsLoaded = query.has("no-translations") ? Promise.resolve(null)
  : packedTranslations ? blockText(packedTranslations, kMaxTranslationsText).catch(() => null)
  : packedWasm ? Promise.resolve(null)
  : loadLessonText(new URL("lesson-translations.txt", location.href), kMaxTranslationsText).then((text) => text || null, () => null);
