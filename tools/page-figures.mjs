// Opens the page in headless Chromium over the DevTools protocol and prints
// its figures as JSON: what the page itself measured (data-first-picture-ms,
// data-frame-ms, data-exit) and the bytes it downloaded. Real time: the
// --dump-dom route of tools/test-web.sh runs on virtual time, where the
// page's clocks stand still (a frame there measures 0 ms).
//   node --experimental-websocket tools/page-figures.mjs URL
// Used by tools/render-web.sh --frames; Node 20's WebSocket and fetch, no
// package needed. GLIMMER_PAGE_ANGLE picks ANGLE's back end: swiftshader
// (default, no display needed) or gl (the system's OpenGL under an X
// server, e.g. xvfb-run: Mesa's llvmpipe, the rasterizer `glimmer render`
// uses, so a frame in the page and one of render compare like for like).
import { spawn } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

const url = process.argv[2];
if (!url) {
  console.error("usage: node --experimental-websocket tools/page-figures.mjs URL");
  process.exit(2);
}
const profile = mkdtempSync(join(tmpdir(), "glimmer-page-"));
const angle = process.env.GLIMMER_PAGE_ANGLE || "swiftshader";
const browser = spawn("chromium", [
  "--headless=new", "--no-sandbox", `--user-data-dir=${profile}`, `--use-angle=${angle}`,
  "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist", "--allow-file-access-from-files",
  "--remote-debugging-port=0", "about:blank"], { stdio: "ignore" });
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const done = (code) => {
  browser.once("exit", () => { rmSync(profile, { recursive: true, force: true }); process.exit(code); });
  browser.kill();
};
setTimeout(() => { console.error("page-figures: no result in 120 s"); done(1); }, 120000);

// Chromium writes its port into the profile once it listens.
let port;
for (let i = 0; i < 200 && !port; ++i) {
  try { port = readFileSync(join(profile, "DevToolsActivePort"), "utf8").split("\n")[0]; } catch { await sleep(50); }
}
if (!port) { console.error("page-figures: Chromium did not start"); done(1); }
const targets = await (await fetch(`http://127.0.0.1:${port}/json/list`)).json();
const socket = new WebSocket(targets.find((t) => t.type === "page").webSocketDebuggerUrl);
await new Promise((r) => { socket.onopen = r; });
let next = 0;
const pending = new Map();
const transferred = new Map();  // requestId -> encoded bytes (compressed, as sent)
socket.onmessage = (event) => {
  const msg = JSON.parse(event.data);
  if (msg.id !== undefined) pending.get(msg.id)?.(msg.result);
  else if (msg.method === "Network.loadingFinished") transferred.set(msg.params.requestId, msg.params.encodedDataLength);
};
const send = (method, params = {}) => new Promise((resolve) => {
  const id = ++next;
  pending.set(id, resolve);
  socket.send(JSON.stringify({ id, method, params }));
});
const evaluate = async (expression) => (await send("Runtime.evaluate", { expression, returnByValue: true }))?.result?.value;

await send("Network.enable");
await send("Page.enable");
await send("Page.navigate", { url });
while ((await evaluate("document.body && document.body.dataset.ready")) !== "1") await sleep(20);
const figures = await evaluate(`({
  exit: document.getElementById("verdict").dataset.exit,
  firstPictureMs: Number(document.body.dataset.firstPictureMs),
  frameMs: Number(document.getElementById("picture").dataset.frameMs),
  renderer: (() => {
    const gl = document.createElement("canvas").getContext("webgl2");
    const info = gl && gl.getExtension("WEBGL_debug_renderer_info");
    return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : "unknown";
  })()
})`);
// What the page loaded, uncompressed (from disk; a server's gzip is measured apart).
figures.loadedBytes = [...transferred.values()].reduce((a, b) => a + b, 0);
console.log(JSON.stringify(figures));
done(0);
