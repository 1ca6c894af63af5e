// The page's checks in one browser engine (issue 27), for tests/web/engine_*.sh
// (tests/web/engine_lib.sh compares what it saw with the desktop): Chromium
// and Firefox ESR through puppeteer-core (the DevTools protocol, WebDriver
// BiDi for Firefox; tools/package.json, installed by tools/install-deps.sh
// into tools/node_modules; it downloads no browser), WebKitGTK (Safari's
// engine) through Debian's WebKitWebDriver and its MiniBrowser, over plain
// W3C WebDriver with Node's own fetch. Every engine is Debian's package,
// each a real window on the X server in DISPLAY (the groups start an Xvfb
// of their own; headless Firefox has no WebGL 2 here). The steps are the
// same in every engine, through the page's own code, real mouse and key
// input, and its test API (globalThis.glimmerPage):
//   1. the seed opened in the live view (PAGE_URL?view=scripts/bloom.glib):
//      OUT_DIR/seed.png, the page's first picture;
//   2. Save PNG pressed: the name and the picture the page hands the browser
//      to download (the link it clicks), OUT_DIR/save.png;
//   3. the uAdd slider of the panel pressed with the mouse halfway along:
//      its value, OUT_DIR/slider.png;
//   4. a live edit, glimmerPage.set("uAdd=2"): OUT_DIR/add2.png;
//   5. a typo typed at the end of line 13 of shaders/bloom.frag in the
//      page's editor (a click past the line's end, then the keys): the
//      error, its mark, the picture after it (OUT_DIR/broken.png);
//   6. the page reloaded: the typed edit comes back from the browser's
//      storage, with its error; then Revert, and the error goes;
//   7. figures: the first picture's time (data-first-picture-ms), and the
//      seed's full redraw at uAdd 2, uHalfSize 11 (a 23x23 superblur, the
//      heavy frame PERFORMANCE.md times) after a slider change, three times,
//      as `frames` (the viewer core's command) measures it.
// Prints one JSON object: { engine, version, renderer, url, first, saved,
// slider, added, clickedAt, broken, reloaded, reverted, figures } (failed:
// why, when a step could not be done); the page's console errors and
// warnings go to stderr.
//   node tools/page-engine.mjs ENGINE PAGE_URL OUT_DIR [--opening | --serve]
//   ENGINE: chromium | firefox | webkit; PAGE_URL: the page (file:// or http://)
//   --opening: only how PAGE_URL opens with nothing asked (see below).
//   --serve: PAGE_URL is a student's link of `glimmer serve` (see below).
//   --tour: the panel tour (tools/panel-tour.mjs): { engine, version, steps,
//   failures }.
//   --layout=WxH: the page in a real window of that outer size, opened,
//   with a watch on and with an error showing (tools/page-window-layout.mjs).
//   --first=WxH: the page opened in a real window of that outer size, a
//   fresh profile: the first picture's marks the page sets on its body
//   ({ engine, version, url, ready, verdict, and every data-...-ms mark:
//   firstPictureMs, moduleReadyMs, firstOpenMs, firstFramesMs...});
//   tools/first-picture.sh runs it (issue 39).
import { spawn } from "node:child_process";
import { mkdtempSync, rmSync, writeFileSync } from "node:fs";
import { createServer } from "node:net";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { until as waitUntil } from "./page-wait.mjs";

const [engine, pageUrl, outDir, mode] = process.argv.slice(2);
// --layout=WxH: a real window of that outer size (see tools/page-window-layout.mjs).
// --first=WxH: the same window, and only the first picture's marks.
const sized = mode && (mode.startsWith("--layout=") || mode.startsWith("--first="));
const windowSize = sized ? mode.slice(mode.indexOf("=") + 1).split("x").map(Number) : null;
if (!["chromium", "firefox", "webkit"].includes(engine) || !pageUrl || !outDir ||
    (mode && !["--opening", "--serve", "--tour"].includes(mode) && !(windowSize && windowSize.length === 2 && windowSize.every((n) => n > 0)))) {
  console.error("usage: node tools/page-engine.mjs chromium|firefox|webkit PAGE_URL OUT_DIR [--opening | --serve | --tour | --layout=WxH | --first=WxH]");
  process.exit(2);
}
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const url = `${pageUrl}?view=${encodeURIComponent("scripts/bloom.glib")}`;
// The whole run is bounded: an engine that hangs fails the group, never stalls CI.
const kSeconds = Number(process.env.GLIMMER_ENGINE_SECONDS || 120);
let closeBrowser = async () => {};
const watchdog = setTimeout(async () => {
  console.error(`page-engine ${engine}: no result in ${kSeconds} s`);
  await Promise.race([closeBrowser(), sleep(5000)]);
  process.exit(1);
}, kSeconds * 1000);

// The run's one JSON line, then the browser closed and the exit status
// (1 when a step failed).
const finishWith = async (result) => {
  console.log(JSON.stringify(result));
  clearTimeout(watchdog);
  await Promise.race([closeBrowser(), sleep(10000)]);
  process.exit(result.failed ? 1 : 0);
};

// Ended from outside (the group's timeout): the browser goes too.
process.on("SIGTERM", async () => {
  await Promise.race([closeBrowser(), sleep(5000)]);
  process.exit(1);
});

// A driver: evaluate(expression) -> its JSON value, type(text) (key input
// into what has focus), open(url) (navigates and waits for data-ready),
// version, close().
const puppeteerDriver = async () => {
  const { default: puppeteer } = await import("puppeteer-core");
  const profile = mkdtempSync(join(tmpdir(), `glimmer-${engine}-`));
  closeBrowser = async () => { rmSync(profile, { recursive: true, force: true }); };
  const options = engine === "chromium" ? {
    browser: "chrome", executablePath: "/usr/bin/chromium", headless: !windowSize, userDataDir: profile,
    // ANGLE over the X server's OpenGL (Mesa's llvmpipe, the rasterizer
    // `glimmer render` uses and Firefox and WebKitGTK draw with here);
    // without a display, SwiftShader as the other groups use.
    args: ["--no-sandbox", "--allow-file-access-from-files", "--ignore-gpu-blocklist",
           process.env.DISPLAY ? "--use-angle=gl" : "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
           ...(windowSize ? [`--window-size=${windowSize[0]},${windowSize[1]}`, "--window-position=0,0"] : []),
           // GLIMMER_CHROMIUM_FLAGS: more flags, for an experiment (space-separated).
           ...(process.env.GLIMMER_CHROMIUM_FLAGS || "").split(" ").filter(Boolean)],
    ...(windowSize ? { defaultViewport: null } : {}),
  } : {
    // Headless Firefox has no WebGL 2 here: a real window under Xvfb.
    browser: "firefox", executablePath: "/usr/bin/firefox-esr", headless: false, userDataDir: profile,
    args: windowSize ? [`--width=${windowSize[0]}`, `--height=${windowSize[1]}`] : ["--width=1400", "--height=1000"],
    defaultViewport: null,
    // Opened from disk, Firefox reads the files beside the page (its
    // module's .wasm) as it is: no preference is changed.
  };
  const browser = await puppeteer.launch({ ...options, protocolTimeout: kSeconds * 1000 });
  closeBrowser = async () => {
    await browser.close().catch(() => {});
    try { rmSync(profile, { recursive: true, force: true, maxRetries: 10, retryDelay: 100 }); } catch {}
  };
  const page = (await browser.pages())[0] || await browser.newPage();
  if (engine === "chromium" && !windowSize) await page.setViewport({ width: 1400, height: 1000 });
  // What the page says on the console goes to stderr (the group keeps it).
  page.on("pageerror", (e) => console.error(`page error: ${e.message}`));
  page.on("console", (m) => { if (m.type() === "error" || m.type() === "warn") console.error(`console ${m.type()}: ${m.text()}`); });
  return {
    // "Chrome/156.0.8078.108", "firefox/153.7.0": as the tables write them.
    version: (await browser.version()).replace(/^Chrome\//, "Chromium ").replace(/^firefox\//i, "Firefox ESR "),
    evaluate: (expression) => page.evaluate(expression),
    type: (text) => page.keyboard.type(text),
    // Keys pressed in order, held a moment (a few of the page's frames: its
    // panel reads keys as held or not at each frame), let go in reverse.
    hold: async (keys) => {
      for (const k of keys) await page.keyboard.down(k);
      await sleep(300);
      for (const k of [...keys].reverse()) await page.keyboard.up(k);
    },
    // The mouse at (x, y) of the page's viewport: "move", "down" or "up";
    // button "left" (the default) or "right".
    mouse: (kind, x, y, button = "left") => kind === "move" ? page.mouse.move(x, y) : page.mouse[kind]({ button }),
    go: (to) => page.goto(to, { waitUntil: "load" }),
    screenshot: async () => Buffer.from(await page.screenshot()),
    close: closeBrowser,
  };
};

// --serve: a student of `glimmer serve` (tests/web/serve.sh) in this engine:
// their link opened (the lesson drawn, their name in the toolbar); a
// comment typed on blur.frag's second line (blank) after a click there, as
// a person types (near the top: the editor need not scroll); the page says
// it is saved; the browser closed and a fresh
// one (a new profile: another machine) opens the link and finds the edit;
// Hand in clicked: the grade and the feedback link appear. Prints { engine,
// version, who, saved, continued, grade, feedbackHref } (failed: why).
async function serveJourney() {
  const seen = { engine, version: browser.version };
  const comment = "// typed in " + engine;
  const waitFor = async (expression, what, seconds = 60) => {
    for (const end = Date.now() + seconds * 1000; Date.now() < end; await sleep(200)) {
      // Asked while the link's redirect is still loading the page, WebKitWebDriver may answer
      // "Could not parse script result" (seen once in three runs on a loaded machine): asked again.
      const v = await browser.evaluate(expression).catch(() => null);
      if (v) return v;
    }
    throw new Error(`the page did not ${what}: ` + await browser.evaluate(`document.body.innerText.slice(0, 400)`));
  };
  const opened = async () => {
    await browser.go(pageUrl);
    await waitFor(`document.body && document.body.dataset.ready === "1" &&
      document.getElementById("verdict").textContent.endsWith(": drawn")`, "draw the lesson");
  };
  try {
    await opened();
    seen.who = await browser.evaluate(`document.getElementById("serve-who").textContent`);
    const lineEnd = await browser.evaluate(`(() => { const ed = glimmerPage.editor();
      [...document.querySelectorAll("#tabs button")].find((b) => b.dataset.path === "blur.frag").click();
      document.getElementById("editor").scrollIntoView({ block: "nearest" });
      const at = ed.cm.charCoords({ line: 1, ch: ed.cm.getLine(1).length }, "window");
      return [at.right + 30, (at.top + at.bottom) / 2]; })()`);
    for (const kind of ["move", "down", "up"]) { await browser.mouse(kind, lineEnd[0], lineEnd[1]); await sleep(150); }
    await browser.type(" " + comment);
    seen.saved = await waitFor(`(() => { const t = document.getElementById("serve-saved").textContent;
      return t.startsWith("saved (version") ? t : ""; })()`, "say the edit was saved");
    await browser.close();
    browser = engine === "webkit" ? await webkitDriver() : await puppeteerDriver();
    await opened();
    seen.continued = await browser.evaluate(`(glimmerPage.editor().open("blur.frag"),
      glimmerPage.editor().cm.getValue().includes(${JSON.stringify(comment)}))`);
    await browser.evaluate(`(document.getElementById("serve-hand-in").click(), 1)`);
    seen.grade = await waitFor(`(() => { const g = document.getElementById("serve-grade");
      return g.querySelector("a") ? g.textContent : ""; })()`, "show the grade", 180);
    seen.feedbackHref = await browser.evaluate(`document.querySelector("#serve-grade a").getAttribute("href")`);
  } catch (e) {
    seen.failed = String(e && e.stack || e);
  }
  await finishWith(seen);
}

// WebKitGTK: WebKitWebDriver on a free loopback port, the session's
// browser Debian's MiniBrowser in automation mode.
const freePort = () => new Promise((resolve, reject) => {
  const server = createServer();
  server.listen(0, "127.0.0.1", () => { const { port } = server.address(); server.close(() => resolve(port)); });
  server.on("error", reject);
});
const webkitDriver = async () => {
  const port = await freePort();
  const driver = spawn("WebKitWebDriver", [`--port=${port}`, "--host=127.0.0.1"], { stdio: "ignore" });
  const base = `http://127.0.0.1:${port}`;
  const call = async (method, path, body) => {
    const response = await fetch(base + path, {
      method, headers: { "content-type": "application/json" }, body: body === undefined ? undefined : JSON.stringify(body),
    });
    const reply = await response.json();
    if (reply.value && reply.value.error) throw new Error(`WebDriver ${path}: ${reply.value.error}: ${reply.value.message}`);
    return reply.value;
  };
  closeBrowser = async () => { driver.kill(); };
  for (let i = 0; i < 300; ++i) {  // 30 s: a loaded machine starts it slowly
    try { await call("GET", "/status"); break; } catch { await sleep(100); }
  }
  const session = await call("POST", "/session", { capabilities: { alwaysMatch: {
    "webkitgtk:browserOptions": {
      binary: "/usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser",
      // No setting changed: opened from disk, WebKit (as Safari) lets the
      // page read no file beside it (its module's .wasm), so the group
      // serves the page over loopback HTTP, as a class would have it.
      args: ["--automation"],
    },
  } } });
  const id = session.sessionId;
  closeBrowser = async () => {
    await call("DELETE", `/session/${id}`).catch(() => {});
    driver.kill();
  };
  await call("POST", `/session/${id}/window/rect`, windowSize ? { x: 0, y: 0, width: windowSize[0], height: windowSize[1] }
                                                              : { width: 1400, height: 1000 }).catch(() => {});
  // Key input as a keyboard gives it: a press and a release a character.
  const keys = (text) => [...text].flatMap((c) => [{ type: "keyDown", value: c }, { type: "keyUp", value: c }]);
  return {
    version: `WebKitGTK ${session.capabilities.browserVersion} (${session.capabilities.browserName})`,
    evaluate: (expression) => call("POST", `/session/${id}/execute/sync`,
      { script: `return (${expression});`, args: [] }),
    type: (text) => call("POST", `/session/${id}/actions`, { actions: [{ type: "key", id: "keyboard", actions: keys(text) }] }),
    hold: (names) => {
      const code = (k) => ({ Control: "\uE009", Enter: "\uE007", Shift: "\uE008" })[k] || k;
      return call("POST", `/session/${id}/actions`, { actions: [{ type: "key", id: "keyboard", actions: [
        ...names.map((k) => ({ type: "keyDown", value: code(k) })), { type: "pause", duration: 300 },
        ...[...names].reverse().map((k) => ({ type: "keyUp", value: code(k) }))] }] });
    },
    // A right press and release through WebDriver come to the page as a
    // press of button 2 and a release of button 0 with no pointerup
    // (WebKitGTK 2.50's automation, seen here), so ImGui never sees the right
    // button let go: those two are given to the page as DOM mouse events at
    // the same place instead, what a real right click makes.
    mouse: (kind, x, y, button = "left") => kind !== "move" && button === "right"
      ? call("POST", `/session/${id}/execute/sync`, { script: `const [type, x, y] = arguments;
          const at = document.elementFromPoint(x, y) || document.body;
          at.dispatchEvent(new MouseEvent(type, { bubbles: true, cancelable: true, clientX: x, clientY: y, button: 2,
                                                  buttons: type === "mousedown" ? 2 : 0 }));
          if (type === "mouseup") at.dispatchEvent(new MouseEvent("contextmenu", { bubbles: true, cancelable: true, clientX: x, clientY: y, button: 2 }));
          return 1;`, args: [kind === "down" ? "mousedown" : "mouseup", x, y] })
      : call("POST", `/session/${id}/actions`, { actions: [{ type: "pointer", id: "mouse",
      parameters: { pointerType: "mouse" }, actions: [kind === "move"
        ? { type: "pointerMove", x: Math.round(x), y: Math.round(y), origin: "viewport" }
        : { type: kind === "down" ? "pointerDown" : "pointerUp", button: 0 }] }] }),
    go: (to) => call("POST", `/session/${id}/url`, { url: to }),
    screenshot: async () => Buffer.from(await call("GET", `/session/${id}/screenshot`), "base64"),
    close: closeBrowser,
  };
};

let browser;
try {
  browser = engine === "webkit" ? await webkitDriver() : await puppeteerDriver();
  if (mode === "--serve") await serveJourney();
  if (mode && mode.startsWith("--first=")) {
    await browser.go(pageUrl);
    // Every mark the page sets (data-...-ms), as numbers.
    const seen = await waitUntil(browser.evaluate, `(() => { const d = document.body ? document.body.dataset : {};
        return { ready: d.ready || "", verdict: (document.getElementById("verdict") || {}).textContent || "",
          ...Object.fromEntries(Object.entries(d).filter(([k]) => k.endsWith("Ms")).map(([k, v]) => [k, Number(v)])) };
      })()`, 30000, (s) => s.ready === "1" && s.firstPictureMs > 0);
    await finishWith({ engine, version: browser.version, url: pageUrl, size: windowSize.join("x"), ...seen });
  }
  if (windowSize) {
    const { measureLayout } = await import("./page-window-layout.mjs");
    await finishWith({ engine, version: browser.version, url: pageUrl, size: windowSize.join("x"),
                       ...(await measureLayout(browser, pageUrl, outDir, windowSize)) });
  }
  if (mode === "--tour") {
    const { runTour } = await import("./panel-tour.mjs");
    await finishWith({ engine, version: browser.version, url: pageUrl, ...(await runTour(browser, pageUrl)) });
  }
} catch (e) {
  console.log(JSON.stringify({ engine, url: pageUrl, failed: `the browser did not start: ${e && e.stack || e}` }));
  await Promise.race([closeBrowser(), sleep(5000)]);
  process.exit(1);
}

const savePng = (name, dataUrl) => {
  if (typeof dataUrl === "string" && dataUrl.startsWith("data:image/png;base64,"))
    writeFileSync(join(outDir, name), Buffer.from(dataUrl.slice("data:image/png;base64,".length), "base64"));
};

// --opening: only how the page opens with nothing asked (PAGE_URL as it
// is): { engine, version, ready, verdict, firstTranslations (the page's
// "HITS MISSES KEPT" at its first picture), cannotStart: { shown, fromDisk,
// text } }, once it is ready or says it cannot start (20 s at most); the
// picture it opened with, OUT_DIR/opening.png.
if (mode === "--opening") {
  const evaluate = browser.evaluate;
  await browser.go(pageUrl);
  const seen = await waitUntil(browser.evaluate, `(() => { const box = document.getElementById("cannot-start");
      return { ready: document.body.dataset.ready || "", verdict: document.getElementById("verdict").textContent,
        firstTranslations: document.body.dataset.firstTranslations || "",
        cannotStart: box ? { shown: !box.hidden, fromDisk: box.dataset.fromDisk || "", text: box.textContent } : null }; })()`,
    20000, (s) => s.ready === "1" || (s.cannotStart && s.cannotStart.shown));
  if (seen.ready === "1") savePng("opening.png", await evaluate("glimmerPage.snapshot()"));
  console.log(JSON.stringify({ engine, version: browser.version, url: pageUrl, ...seen }));
  clearTimeout(watchdog);
  await Promise.race([browser.close(), sleep(10000)]);
  process.exit(0);
}
const evaluate = browser.evaluate;
// A press and a release at (x, y), a few of the page's frames apart: the
// panel (Dear ImGui) sees the pointer, the press and the release each in
// frames of their own, as a hand gives them.
const click = async (x, y) => {
  for (const kind of ["move", "down", "up"]) { await browser.mouse(kind, x, y); await sleep(150); }
};
// Opens the page and waits until it is ready (data-ready on the body); a
// page that says it could not start, or is not ready in 60 s, is a failure.
const open = async () => {
  await browser.go(url);
  for (const end = Date.now() + 60000; Date.now() < end; await sleep(100)) {
    const [ready, verdict] = await evaluate(`[document.body && document.body.dataset.ready || "",
      document.getElementById("verdict") ? document.getElementById("verdict").textContent : ""]`);
    if (ready === "1") return;
    if (verdict.startsWith("the page could not start")) throw new Error(verdict);
  }
  throw new Error("the page was not ready in 60 s");
};
// What the page shows: the verdict, the errors, the editor's file and its marks.
const state = () => evaluate(`(() => {
  const ed = glimmerPage.editor();
  return { exit: Number(document.getElementById("verdict").dataset.exit),
    verdict: document.getElementById("verdict").textContent, errors: glimmerPage.errors(),
    diagnostics: document.getElementById("diagnostics").textContent, uAdd: glimmerPage.value("uAdd"),
    shown: ed.shown(), note: document.getElementById("edit-note").textContent,
    markedLines: ed.cm.getValue().split("\\n").map((_, i) => i + 1).filter((n) =>
      (ed.cm.lineInfo(n - 1).bgClass || "").includes("glimmer-error-line")).join(" "),
    message: [...document.querySelectorAll(".glimmer-message-error")].map((e) => e.textContent).join("\\n"),
    file: glimmerPage.readFile("/lesson/shaders/bloom.frag"),
    kept: Object.keys(localStorage).filter((k) => k.startsWith("glimmer-draft")).length };
})()`);
const until = async (condition, ms = 8000) => Boolean(await waitUntil(evaluate, condition, ms));
const result = { engine, version: browser.version, url };

try {
  // 1. The seed, as the page opens it.
  await open();
  result.renderer = await evaluate(`(() => {
    const gl = document.createElement("canvas").getContext("webgl2");
    if (!gl) return "no WebGL 2";
    const info = gl.getExtension("WEBGL_debug_renderer_info");
    return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
  })()`);
  result.first = { ...(await state()), firstPictureMs: Number(await evaluate("document.body.dataset.firstPictureMs")),
                   moduleReadyMs: Number(await evaluate("document.body.dataset.moduleReadyMs")),
                   firstTranslations: await evaluate("document.body.dataset.firstTranslations || ''") };
  delete result.first.file;
  savePng("seed.png", await evaluate("glimmerPage.snapshot()"));

  // 2. Save PNG: the page's own button; the link it clicks to download is
  // caught (each engine saves downloads its own way), its name and picture kept.
  result.saved = await evaluate(`(() => {
    const click = HTMLAnchorElement.prototype.click;
    let got = null;
    HTMLAnchorElement.prototype.click = function () { got = { name: this.download, href: this.href }; };
    try { document.getElementById("save").click(); } finally { HTMLAnchorElement.prototype.click = click; }
    return got;
  })()`);
  if (result.saved) { savePng("save.png", result.saved.href); result.saved.href = result.saved.href.slice(0, 40); }

  // 3. The uAdd slider of the panel pressed with the mouse halfway along
  // (the picture then is render's with --set at the value it shows).
  const slider = await evaluate(`(() => {
    const canvas = document.getElementById("canvas");
    canvas.scrollIntoView({ block: "nearest" });
    const r = canvas.getBoundingClientRect(), scale = r.width / canvas.width;
    const [x, y, w, h] = glimmerPage.control("uAdd");
    return w === undefined ? null : [r.left + (x + w / 2) * scale, r.top + (y + h / 2) * scale];
  })()`);
  if (slider) await click(slider[0], slider[1]);
  await sleep(300);
  result.slider = { at: slider, value: await evaluate(`glimmerPage.value("uAdd")`) };
  savePng("slider.png", await evaluate("glimmerPage.snapshot()"));

  // 4. A live edit: uAdd to 2.
  result.added = { set: await evaluate(`glimmerPage.set("uAdd=2")`) };
  await sleep(300);
  result.added.value = await evaluate(`glimmerPage.value("uAdd")`);
  savePng("add2.png", await evaluate("glimmerPage.snapshot()"));

  // 5. A typo typed into bloom.frag at the end of line 13 in the page's
  // editor, as a student does it: its tab opened, a click past the end of
  // line 13, the keys; the page reloads the script once typing stops. The
  // click matters in Firefox: its window under Xvfb (no window manager) is
  // never the active one, so focus() alone sends the editor no focus event
  // and CodeMirror drops every key; a press in the editor gives it focus
  // itself, as a person's click does.
  const lineEnd = await evaluate(`(() => { const ed = glimmerPage.editor();
    [...document.querySelectorAll("#tabs button")].find((b) => b.dataset.path === "shaders/bloom.frag").click();
    document.getElementById("editor").scrollIntoView({ block: "nearest" });
    const at = ed.cm.charCoords({ line: 12, ch: ed.cm.getLine(12).length }, "window");
    return [at.right + 30, (at.top + at.bottom) / 2]; })()`);
  await click(lineEnd[0], lineEnd[1]);
  await sleep(200);
  result.clickedAt = await evaluate(`[glimmerPage.editor().cm.getCursor().line + 1, glimmerPage.editor().cm.getCursor().ch]`);
  await browser.type(" undeclaredTypo;");
  await until("glimmerPage.errors() === 1");
  await sleep(500);
  result.broken = await state();
  savePng("broken.png", await evaluate("glimmerPage.snapshot()"));

  // 6. The page reloaded: the typed edit comes back from the browser's storage.
  await open();
  await until("glimmerPage.errors() === 1", 3000);
  await evaluate(`(glimmerPage.editor().open("shaders/bloom.frag"), 1)`);
  result.reloaded = await state();
  // Revert: the folder's text, the error gone, nothing kept.
  await evaluate(`(document.getElementById("revert").click(), 1)`);
  await until("glimmerPage.errors() === 0");
  result.reverted = await state();

  // 7. Figures: the full redraw of the heavy seed after a slider change.
  const redraws = [];
  await evaluate(`glimmerPage.set("uAdd=2")`);
  for (const half of [11, 10, 11]) {
    await evaluate(`glimmerPage.command("frames")`);  // the intervals so far: forgotten
    await evaluate(`glimmerPage.set("uHalfSize=${half}")`);
    await sleep(400);
    let said = "";
    for (let i = 0; i < 200; ++i) {
      said = await evaluate(`glimmerPage.command("frames")`);
      if (!said.includes("being drawn")) break;
      await sleep(100);
    }
    const m = /last picture ([\d.]+) ms after its last change \(([\d.]+) ms drawing, (\d+) slice/.exec(said);
    redraws.push(m ? { pictureMs: Number(m[1]), drawingMs: Number(m[2]), slices: Number(m[3]) } : { said });
  }
  // The browser's frames while nothing changes: what the page's loop costs.
  await evaluate(`glimmerPage.command("frames")`);
  await sleep(1500);
  const idle = /median ([\d.]+) ms/.exec(await evaluate(`glimmerPage.command("frames")`));
  result.figures = { firstPictureMs: result.first.firstPictureMs, redraws, idleFrameMs: idle ? Number(idle[1]) : null };
} catch (e) {
  result.failed = String(e && e.stack || e);
}
await finishWith(result);
