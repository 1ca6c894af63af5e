// The page's layout as a laptop shows it, for tests/web/layout.sh: opens
// the page (the seed bloom, as it opens with nothing asked) in a window of
// each WxH (the DevTools protocol's Emulation.setDeviceMetricsOverride, at
// devicePixelRatio 1) and measures, in CSS pixels of the viewport: the
// canvas (the picture with its panel), the uAdd and uHalfSize sliders of the
// panel (glimmerPage.control, canvas pixels, mapped onto the page), the
// editor, how far the page scrolls. Then it types a long broken line (an
// undeclared name 300 characters long) into bloom.frag in the page's
// editor and measures again, and last the presentation mode
// (glimmerPage.present). Writes OUT_DIR/WxH-{open,broken,present}.png
// (screenshots) and prints one JSON object: { "WxH": { open, broken,
// present }, ... }, each a measure as below.
//   NODE_PATH=/usr/share/nodejs node tools/page-layout.mjs PAGE_URL OUT_DIR WxH...
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import { openPage, sleep } from "./cdp-page.mjs";

const [url, outDir, ...sizes] = process.argv.slice(2);
if (!sizes.length) {
  console.error("usage: node tools/page-layout.mjs PAGE_URL OUT_DIR WxH...");
  process.exit(2);
}
const page = await openPage(url);
// { viewport, scroll, canvas, picture, sliders: { name: rect }, editor, firstError, errors, factor }:
// rects as { left, top, right, bottom, width, height }.
const measure = () => page.evaluate(`(() => {
  const rect = (r) => ({ left: r.left, top: r.top, right: r.right, bottom: r.bottom, width: r.width, height: r.height });
  const canvas = document.getElementById("canvas");
  const box = canvas.getBoundingClientRect();
  const k = box.width / canvas.width;  // CSS pixels per canvas pixel
  const sliders = {};
  for (const name of ["uAdd", "uHalfSize"]) {
    const [x, y, w, h] = glimmerPage.control(name);
    sliders[name] = w === undefined ? null : rect({ left: box.left + x * k, top: box.top + y * k,
      right: box.left + (x + w) * k, bottom: box.top + (y + h) * k, width: w * k, height: h * k });
  }
  const cm = document.querySelector("#edit .CodeMirror");
  const first = document.getElementById("first-error");
  return { viewport: [window.innerWidth, window.innerHeight],
    scroll: [document.scrollingElement.scrollWidth, document.scrollingElement.scrollHeight],
    canvas: rect(box), canvasPixels: [canvas.width, canvas.height], sliders,
    editor: cm && cm.offsetParent ? rect(cm.getBoundingClientRect()) : null,
    firstError: first.textContent ? rect(first.getBoundingClientRect()) : null, firstErrorText: first.textContent,
    count: document.getElementById("message-count").textContent, errors: glimmerPage.errors(),
    verdict: document.getElementById("verdict").textContent };
})()`);
// A measure once the page has settled: `ready` holds of it and two measures
// 200 ms apart agree (a reload's frames and the panel's refit are done).
// Fixed sleeps measured a state on the way: 1.5 s after typing an error
// came before the page's cap had shrunk the picture for it (issue 39).
const settled = async (ready, limitMs = 20000) => {
  const until = Date.now() + limitMs;
  let last = null;
  for (;;) {
    const now = await measure();
    if (ready(now) && last !== null && JSON.stringify(now) === JSON.stringify(last)) return now;
    if (Date.now() > until) return now;
    last = ready(now) ? now : null;
    await sleep(200);
  }
};
const shoot = async (name) => {
  const shot = await page.send("Page.captureScreenshot", { format: "png" });
  writeFileSync(join(outDir, name), Buffer.from(shot.result.data, "base64"));
};
const result = {};
for (const size of sizes) {
  const [width, height] = size.split("x").map(Number);
  await page.send("Emulation.setDeviceMetricsOverride", { width, height, deviceScaleFactor: 1, mobile: false });
  // Each size from a page as a student first opens it: nothing kept from the last.
  await page.evaluate(`localStorage.clear(); indexedDB.deleteDatabase("glimmer")`);
  await page.navigate();
  const open = await settled((m) => m.verdict === "scripts/bloom.glib: drawn");  // the panel settles over a few frames
  await shoot(`${size}-open.png`);

  // A broken line typed into bloom.frag after its line 12: an undeclared
  // name 300 characters long, so the error's message and its source line
  // are both longer than any window.
  const name = "notDeclared" + "X".repeat(289);
  await page.evaluate(`glimmerPage.editor().open("shaders/bloom.frag", 12, 1);
    glimmerPage.editor().cm.setCursor({ line: 11, ch: 10000 }); glimmerPage.editor().cm.focus()`);
  await page.send("Input.insertText", { text: `\n    vec3 broken = rgb * ${name};` });
  // The editor's pause after typing, the reload, its frames: until the error shows and stays.
  const broken = await settled((m) => m.errors === 1);
  await shoot(`${size}-broken.png`);
  await page.evaluate(`document.getElementById("revert").click()`);
  await sleep(800);

  // The presentation mode, fitted to the window.
  await page.evaluate(`glimmerPage.present(true)`);
  await sleep(1500);
  const present = await measure();
  present.factor = await page.evaluate(`glimmerPage.present(true)`);
  await shoot(`${size}-present.png`);
  await page.evaluate(`glimmerPage.present(false)`);
  await sleep(600);
  const after = await measure();
  result[size] = { open, broken, present, after };
}
console.log(JSON.stringify(result));
page.close(0);
