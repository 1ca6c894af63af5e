// "Measure blurs on this machine" clicked as a student clicks it, for
// tests/web/tradeoff.sh: opens the page (the seed bloom in the live view),
// keeps the live picture, clicks the button with the mouse, and while the
// methods run records the longest gap between two animation frames and each
// progress line the page showed; once #blurs says done (or failed) prints
// one JSON object: { state, progress, statuses, longestFrameGapMs,
// longestFrameBefore (what the longest step had done), measureMs, rows: [{ method, taps, ms, min, max, modelPsnr, numPsnr,
// numMax, numOver }], fastest, samePicture, verdict }.
//   NODE_PATH=/usr/share/nodejs node tools/page-tradeoff.mjs PAGE_URL [WxH, default 1366x768]
// GLIMMER_TRADEOFF_SHOT=FILE.png: a screenshot of the page once the table is
// there. GLIMMER_PAGE_ANGLE=gl under an X server draws with Mesa's llvmpipe, as
// `glimmer tradeoff` does on the desktop (tools/cdp-page.mjs).
import { writeFileSync } from "node:fs";
import { clickAt, openPage, sleep } from "./cdp-page.mjs";

const [url, size = "1366x768"] = process.argv.slice(2);  // the window, WxH
if (!url) {
  console.error("usage: NODE_PATH=/usr/share/nodejs node tools/page-tradeoff.mjs PAGE_URL [WxH]");
  process.exit(2);
}
const page = await openPage(url, 240);  // about 10 s here; a held page fails within the group's time
const [width, height] = size.split("x").map(Number);
await page.send("Emulation.setDeviceMetricsOverride", { width, height, deviceScaleFactor: 1, mobile: false });
await page.navigate();
await sleep(600);  // the live view's first frames
const before = await page.evaluate("glimmerPage.snapshot()");
// The page's own record of its frames and progress lines while it measures.
await page.evaluate(`(() => {
  const seen = globalThis.blurWatch = { gaps: [], statuses: [], last: 0, longestAfter: "" };
  const frame = (now) => {
    const text = document.getElementById("blurs-progress").textContent;
    if (seen.last) {
      if (now - seen.last > Math.max(0, ...seen.gaps)) seen.longestAfter = text;
      seen.gaps.push(now - seen.last);
    }
    seen.last = now;
    if (seen.statuses.at(-1) !== text) seen.statuses.push(text);
    if (!["done", "failed"].includes(document.getElementById("blurs").dataset.state)) requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
})()`);
const at = await page.evaluate(`(() => {
  const r = document.getElementById("measure-blurs").getBoundingClientRect();
  return { x: r.left + r.width / 2, y: r.top + r.height / 2 };
})()`);
const started = Date.now();
await clickAt(page, at, () => sleep(50));
let state;
while (!["done", "failed"].includes(state = await page.evaluate(`document.getElementById("blurs").dataset.state || ""`)))
  await sleep(200);
const measureMs = Date.now() - started;
await sleep(300);  // a few frames of the live view after it
const result = await page.evaluate(`(() => {
  const w = globalThis.blurWatch;
  return {
    state: document.getElementById("blurs").dataset.state,
    progress: document.getElementById("blurs-progress").textContent,
    statuses: w.statuses,
    longestFrameGapMs: Math.max(0, ...w.gaps),
    longestFrameBefore: w.longestAfter,  // the progress line the page showed once that frame came
    rows: [...document.querySelectorAll("#blurs-table tbody tr")].map((tr) => ({ ...tr.dataset,
      cells: [...tr.cells].map((c) => c.textContent) })),
    fastest: document.getElementById("blurs-fastest").dataset.methods || "",
    fastestText: document.getElementById("blurs-fastest").textContent,
    verdict: document.getElementById("verdict").textContent,
  };
})()`);
result.measureMs = measureMs;
// GLIMMER_TRADEOFF_SHOT=FILE.png keeps a screenshot of the page with its table.
if (process.env.GLIMMER_TRADEOFF_SHOT) {
  const shot = await page.send("Page.captureScreenshot", { format: "png" });
  writeFileSync(process.env.GLIMMER_TRADEOFF_SHOT, Buffer.from(shot.result.data, "base64"));
}
result.samePicture = before !== "" && (await page.evaluate("glimmerPage.snapshot()")) === before;
for (const r of result.rows)
  for (const k of ["taps", "ms", "min", "max", "modelPsnr", "numPsnr", "numMax", "numOver", "rendersPerRun"]) r[k] = r[k] === "null" ? null : Number(r[k]);
console.log(JSON.stringify(result));
page.close(0);
