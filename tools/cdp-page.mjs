// Headless Chromium driven over the DevTools protocol, in real time: the
// one place tools/page-figures.mjs and tools/page-pick-folder.mjs open the
// page. Debian's node-ws for the socket (NODE_PATH=/usr/share/nodejs; the
// same on Debian's Node 18 and a newer one) and Node's own fetch. GLIMMER_PAGE_ANGLE picks ANGLE's back end: swiftshader
// (default, no display needed) or gl (the system's OpenGL under an X
// server, e.g. xvfb-run: Mesa's llvmpipe, the rasterizer `glimmer render`
// uses, so a frame in the page and one of render compare like for like).
import { spawn } from "node:child_process";
import { createRequire } from "node:module";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

const WebSocket = createRequire(import.meta.url)("ws");

export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// A click as a student makes one, at `at` ({ x, y } in CSS pixels): the
// pointer moved there, pressed, released, each followed by `settle()` so
// the page sees them in frames of their own (the panel needs the hover
// before the press).
export async function clickAt(page, at, settle = () => sleep(300)) {
  await page.send("Input.dispatchMouseEvent", { type: "mouseMoved", ...at });
  await settle();
  await page.send("Input.dispatchMouseEvent", { type: "mousePressed", button: "left", buttons: 1, clickCount: 1, ...at });
  await settle();
  await page.send("Input.dispatchMouseEvent", { type: "mouseReleased", button: "left", buttons: 0, clickCount: 1, ...at });
  await settle();
}

// Starts Chromium on `url` and resolves once the page says it is ready
// (data-ready on the body). Gives up after `seconds` with exit status 1.
export async function openPage(url, seconds = 120) {
  const profile = mkdtempSync(join(tmpdir(), "glimmer-page-"));
  const angle = process.env.GLIMMER_PAGE_ANGLE || "swiftshader";
  const browser = spawn("chromium", [
    "--headless=new", "--no-sandbox", `--user-data-dir=${profile}`, `--use-angle=${angle}`,
    "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist", "--allow-file-access-from-files",
    "--remote-debugging-port=0", "about:blank"], { stdio: "ignore" });
  let timer;
  // Ends Chromium, then the process with `code`; with `code` null it only
  // ends Chromium (a caller opening another page), resolving once it is gone.
  const close = (code) => new Promise((resolve) => {
    clearTimeout(timer);
    // Chromium's helpers may still be writing the profile as it exits: retry,
    // and never let a leftover folder turn a result into a crash.
    browser.once("exit", () => {
      try { rmSync(profile, { recursive: true, force: true, maxRetries: 10, retryDelay: 100 }); } catch {}
      if (code === null) resolve();
      else process.exit(code);
    });
    browser.kill();
  });
  timer = setTimeout(() => { console.error(`no result from the page in ${seconds} s`); close(1); }, seconds * 1000);

  // Chromium writes its port into the profile once it listens.
  let port;
  for (let i = 0; i < 600 && !port; ++i) {  // up to 30 s: a loaded machine starts it slowly
    try { port = readFileSync(join(profile, "DevToolsActivePort"), "utf8").split("\n")[0]; } catch { await sleep(50); }
  }
  if (!port) { console.error("Chromium did not start"); close(1); }
  const targets = await (await fetch(`http://127.0.0.1:${port}/json/list`)).json();
  const socket = new WebSocket(targets.find((t) => t.type === "page").webSocketDebuggerUrl);
  await new Promise((r) => { socket.onopen = r; });
  let next = 0;
  const pending = new Map();
  const listeners = [];
  socket.onmessage = (event) => {
    const msg = JSON.parse(event.data);
    if (msg.id !== undefined) pending.get(msg.id)?.(msg);
    else for (const listen of listeners) listen(msg);
  };
  const send = (method, params = {}) => new Promise((resolve) => {
    const id = ++next;
    pending.set(id, resolve);
    socket.send(JSON.stringify({ id, method, params }));
  });
  const evaluate = async (expression) =>
    (await send("Runtime.evaluate", { expression, returnByValue: true })).result?.result?.value;
  const onEvent = (listen) => listeners.push(listen);

  await send("Network.enable");
  await send("Page.enable");
  return { send, evaluate, onEvent, close, navigate: async () => {
    await send("Page.navigate", { url });
    while ((await evaluate("document.body && document.body.dataset.ready")) !== "1") await sleep(20);
  } };
}
