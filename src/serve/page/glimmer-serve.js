// The page's side of `glimmer serve` (src/serve/class_server.cpp injects
// this before glimmer-page.js, with <meta name="glimmer-serve"> naming the
// student, and the lesson from lesson.json: theirs, as last saved).
//   - each edit is saved to the server a moment after typing stops (every
//     version kept there); an edit not yet acknowledged is said, and sent
//     again until it is;
//   - Hand in: the work as saved, graded on the server; the verdict and the
//     feedback page appear here when grading is done;
//   - the teacher's "follow me": pushed slider values (and "script=PATH":
//     the lesson's script to show) applied once each;
//   - now and then a small picture of the view for the teacher's grid.
// Data only goes to the page's own origin (fetch of relative URLs).
"use strict";
globalThis.glimmerServe = (() => {
  const meta = document.querySelector('meta[name="glimmer-serve"]');
  if (!meta) return null;
  const kSaveDelayMs = 800, kPollMs = 2000, kThumbnailMs = 15000;
  const bar = document.getElementById("bar");
  const box = document.createElement("span");
  box.className = "group";
  box.id = "serve";
  box.innerHTML = '<span id="serve-who"></span> <span id="serve-saved"></span> ' +
    '<button id="serve-hand-in" title="hand in your work as it is now saved; it is graded on the server">Hand in</button> ' +
    '<span id="serve-grade"></span>';
  bar.appendChild(box);
  const saved = box.querySelector("#serve-saved"), grade = box.querySelector("#serve-grade");
  box.querySelector("#serve-who").textContent = meta.content + ":";
  const pending = new Map();  // path -> text not yet acknowledged
  let timer = 0, sending = false, version = 0;
  const statusLine = () => {
    const v = document.getElementById("verdict"), e = document.getElementById("first-error");
    return ((v ? v.textContent : "") + (e && e.textContent ? "\n" + e.textContent.split("\n")[0] : "")).slice(0, 1900);
  };
  const post = (url, body, type = "application/json") =>
    fetch(url, { method: "POST", headers: { "Content-Type": type }, body, credentials: "same-origin" });
  const flush = async () => {
    if (sending || pending.size === 0) return;
    sending = true;
    const files = Object.fromEntries(pending);
    try {
      const r = await post("api/save", JSON.stringify({ files, status: statusLine() }));
      const answer = await r.json();
      if (!r.ok) throw new Error(answer.error || r.status);
      for (const [path, text] of Object.entries(files)) if (pending.get(path) === text) pending.delete(path);
      version = answer.version;
      saved.textContent = "saved (version " + version + ", " + new Date().toLocaleTimeString() + ")";
      saved.className = "ok";
    } catch (e) {
      saved.textContent = "NOT saved yet (" + e.message + "): trying again";
      saved.className = "bad";
      setTimeout(flush, 3000);
    } finally {
      sending = false;
      if (pending.size) schedule();
    }
  };
  const schedule = () => { clearTimeout(timer); timer = setTimeout(flush, kSaveDelayMs); };
  // Called by glimmer-page.js for each file the editor writes ("/user/PATH").
  const edited = (path, text) => {
    if (!path.startsWith("/user/")) return;
    pending.set(path.slice("/user/".length), text);
    saved.textContent = "saving...";
    saved.className = "";
    schedule();
  };
  const handIn = box.querySelector("#serve-hand-in");
  handIn.onclick = async () => {
    handIn.disabled = true;
    try {
      clearTimeout(timer);
      await flush();
      if (pending.size) throw new Error("your last edit is not saved yet");
      const r = await post("api/handin", "{}");
      if (!r.ok) throw new Error((await r.json()).error || r.status);
      grade.textContent = "handed in: grading...";
      grade.className = "";
      poll();
    } catch (e) {
      grade.textContent = "not handed in: " + e.message;
      grade.className = "bad";
    } finally { handIn.disabled = false; }
  };
  // The verdict of the newest hand-in, and the teacher's pushes.
  const followKey = "glimmer-serve-follow\n" + location.host;
  const applyFollow = (follow) => {
    const seen = Number(localStorage.getItem(followKey) || 0);
    if (!follow || !follow.id || follow.id <= seen || !globalThis.glimmerPage) return;
    // "script=PATH" shows that script of the lesson first (the projector's), then the sliders.
    const sets = follow.sets.split(";").map((s) => s.trim()).filter(Boolean);
    const script = sets.find((s) => s.startsWith("script="));
    const select = document.getElementById("script");
    if (script && [...select.options].some((o) => o.value === "/user:" + script.slice(7))) {
      select.value = "/user:" + script.slice(7);
      globalThis.glimmerPage.view(select.value);
    }
    for (const set of sets.filter((s) => s !== script)) globalThis.glimmerPage.set(set);
    try { localStorage.setItem(followKey, String(follow.id)); } catch {}
  };
  const showHandIn = (h) => {
    if (!h) return;
    grade.textContent = "";
    if (h.state === "graded") {
      grade.append("hand-in " + h.id + ": " + h.verdict + ", " + h.score + " ");
      grade.className = h.verdict === "pass" ? "ok" : "bad";
      if (h.feedback) {
        const a = document.createElement("a");
        a.href = "api/feedback/" + h.id;
        a.target = "_blank";
        a.rel = "noopener";
        a.textContent = "feedback";
        grade.append(a);
      }
      grade.title = h.notes;
    } else {
      grade.textContent = "hand-in " + h.id + ": " + h.state + (h.state === "failed" ? " (" + h.notes.split("\n")[0] + ")" : "...");
      grade.className = h.state === "failed" ? "bad" : "";
    }
  };
  let polling = false;
  const poll = async () => {
    if (polling) return;
    polling = true;
    try {
      const r = await fetch("api/me", { credentials: "same-origin" });
      if (r.ok) {
        const me = await r.json();
        showHandIn(me.handins.at(-1));
        applyFollow(me.follow);
      }
    } catch {} finally { polling = false; }
  };
  setInterval(poll, kPollMs);
  poll();
  // The teacher's grid: the view at 160 pixels, when it changed.
  let lastThumbnail = "";
  const sendThumbnail = async () => {
    if (!globalThis.glimmerPage) return;
    const png = globalThis.glimmerPage.snapshot();
    if (!png || png === lastThumbnail) return;
    lastThumbnail = png;
    const image = new Image();
    image.src = png;
    await image.decode();
    const c = document.createElement("canvas");
    const s = 160 / Math.max(image.width, image.height);
    c.width = Math.max(1, Math.round(image.width * s));
    c.height = Math.max(1, Math.round(image.height * s));
    c.getContext("2d").drawImage(image, 0, 0, c.width, c.height);
    const blob = await new Promise((resolve) => c.toBlob(resolve, "image/png"));
    if (blob && blob.size <= 96 * 1024) post("api/thumbnail", blob, "image/png").catch(() => {});
  };
  setInterval(() => sendThumbnail().catch(() => {}), kThumbnailMs);
  setTimeout(() => sendThumbnail().catch(() => {}), 3000);
  // Nothing lost on leaving: what is pending goes with the page's last request.
  addEventListener("pagehide", () => {
    if (pending.size) navigator.sendBeacon("api/save", new Blob([JSON.stringify({ files: Object.fromEntries(pending), status: statusLine() })],
                                                                { type: "application/json" }));
  });
  return { edited, flush, pending: () => pending.size, version: () => version };
})();
