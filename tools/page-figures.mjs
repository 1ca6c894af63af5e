// Opens the page in headless Chromium over the DevTools protocol and prints
// its figures as JSON: what the page itself measured (data-first-picture-ms,
// data-frame-ms, data-exit), the WebGL renderer it ran on, and the bytes it
// loaded. Real time: the --dump-dom route of the web tests (tests/web/) runs on
// virtual time, where the page's clocks stand still (a frame there
// measures 0 ms).
//   NODE_PATH=/usr/share/nodejs node tools/page-figures.mjs URL
// Used by tools/render-web.sh --frames; tools/cdp-page.mjs opens the page.
import { openPage } from "./cdp-page.mjs";

const url = process.argv[2];
if (!url) {
  console.error("usage: NODE_PATH=/usr/share/nodejs node tools/page-figures.mjs URL");
  process.exit(2);
}
const page = await openPage(url);
const loaded = new Map();  // requestId -> bytes
page.onEvent((msg) => {
  if (msg.method === "Network.loadingFinished") loaded.set(msg.params.requestId, msg.params.encodedDataLength);
});
await page.navigate();
const figures = await page.evaluate(`({
  exit: document.getElementById("verdict").dataset.exit,
  firstPictureMs: Number(document.body.dataset.firstPictureMs),
  moduleReadyMs: Number(document.body.dataset.moduleReadyMs),
  frameMs: Number(document.getElementById("picture").dataset.frameMs),
  renderer: (() => {
    const gl = document.createElement("canvas").getContext("webgl2");
    const info = gl && gl.getExtension("WEBGL_debug_renderer_info");
    return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : "unknown";
  })()
})`);
// What the page loaded, uncompressed (from disk; a server's gzip is measured apart).
figures.loadedBytes = [...loaded.values()].reduce((a, b) => a + b, 0);
console.log(JSON.stringify(figures));
page.close(0);
