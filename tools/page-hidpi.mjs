// The live view on a screen of devicePixelRatio RATIO (a Retina Mac's 2),
// for tests/web/hidpi.sh: opens SCRIPT in the live view, reports the
// canvas's backing size and its box on the page, drags the slider NAME with
// the mouse to FRACTION of its width (in CSS pixels, as a user's pointer
// is; with TOUCH=1 in the environment, a finger slid there), and writes a screenshot of the page to OUT.png. Prints one JSON
// object: { backing: [w, h], box: [w, h], value, control: [x, y, w, h] }.
//   NODE_PATH=/usr/share/nodejs node tools/page-hidpi.mjs PAGE_URL SCRIPT RATIO NAME FRACTION OUT.png
import { writeFileSync } from "node:fs";
import { clickAt, openPage, sleep } from "./cdp-page.mjs";

const [url, script, ratio, name, fraction, out] = process.argv.slice(2);
if (!out) {
  console.error("usage: node tools/page-hidpi.mjs PAGE_URL SCRIPT RATIO NAME FRACTION OUT.png");
  process.exit(2);
}
const page = await openPage(`${url}?view=${encodeURIComponent(script)}`);
await page.send("Emulation.setDeviceMetricsOverride", { width: 1400, height: 1200, deviceScaleFactor: Number(ratio), mobile: false });
await page.navigate();
await sleep(500);
const state = () => page.evaluate(`(() => { const c = document.getElementById("canvas"), r = c.getBoundingClientRect();
  return { backing: [c.width, c.height], box: [r.width, r.height], at: [r.left, r.top] }; })()`);
const before = await state();
// The control's rectangle is in the canvas's pixels; the pointer moves in CSS pixels.
const control = await page.evaluate(`glimmerPage.control(${JSON.stringify(name)})`);
const k = before.box[0] / before.backing[0];
const at = { x: before.at[0] + (control[0] + Number(fraction) * control[2]) * k, y: before.at[1] + (control[1] + control[3] / 2) * k };
if (process.env.TOUCH) {
  // A finger: down at the control's left end, slid to the point, lifted.
  await page.send("Emulation.setTouchEmulationEnabled", { enabled: true, maxTouchPoints: 1 });
  const start = { x: before.at[0] + (control[0] + 2) * k, y: at.y };
  for (const [type, point] of [["touchStart", start], ["touchMove", at], ["touchEnd", null]]) {
    await page.send("Input.dispatchTouchEvent", { type, touchPoints: point ? [point] : [] });
    await sleep(300);
  }
} else {
  await clickAt(page, at);
}
const value = await page.evaluate(`glimmerPage.value(${JSON.stringify(name)})`);
const shot = await page.send("Page.captureScreenshot", { format: "png" });
writeFileSync(out, Buffer.from(shot.result.data, "base64"));
console.log(JSON.stringify({ ...before, value, control }));
page.close(0);
