// The page's live view as a student uses it, for tools/test-web.sh: opens
// SCRIPT (a bundled lesson path) in the live view, drags each named slider
// of the panel with the mouse (real input events over the DevTools
// protocol, at the control's place on the canvas), then breaks a shader the
// way a typo would and reloads. Writes OUT_DIR/slider-NAME.png (the
// picture after each slider) and OUT_DIR/broken.png (after the broken
// reload), and prints one JSON object:
//   { sliders: [{ name, value, drawn }], broken: { exit, errors, value,
//     verdict, diagnostics }, restored: { exit, errors } }
//   NODE_PATH=/usr/share/nodejs node tools/page-live-view.mjs PAGE_URL SCRIPT SHADER LINE OUT_DIR NAME=FRACTION...
// SHADER (a lesson path) gets an undeclared name on LINE; FRACTION is where
// along the slider the mouse presses (0 its left end, 1 its right).
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import { openPage, sleep } from "./cdp-page.mjs";

const [url, script, shader, line, outDir, ...drags] = process.argv.slice(2);
if (!drags.length) {
  console.error("usage: node tools/page-live-view.mjs PAGE_URL SCRIPT SHADER LINE OUT_DIR NAME=FRACTION...");
  process.exit(2);
}
const page = await openPage(`${url}?view=${encodeURIComponent(script)}`);
await page.send("Emulation.setDeviceMetricsOverride", { width: 1400, height: 1100, deviceScaleFactor: 1, mobile: false });
await page.navigate();
const savePng = (name, dataUrl) =>
  writeFileSync(join(outDir, name), Buffer.from(dataUrl.slice("data:image/png;base64,".length), "base64"));
// A few of the browser's frames, so the page has drawn what it was given.
const frames = () => sleep(300);
const canvasAt = await page.evaluate(`(() => { const r = document.getElementById("canvas").getBoundingClientRect();
  return [r.left, r.top]; })()`);
await frames();

const result = { sliders: [] };
for (const drag of drags) {
  const [name, fraction] = drag.split("=");
  const [x, y, w, h] = await page.evaluate(`glimmerPage.control(${JSON.stringify(name)})`);
  if (w === undefined) { console.error(`no control ${name} in the panel`); page.close(1); }
  const at = { x: canvasAt[0] + x + Number(fraction) * w, y: canvasAt[1] + y + h / 2 };
  await page.evaluate("glimmerPage.drawn()");  // what was drawn before this slider: forgotten
  await page.send("Input.dispatchMouseEvent", { type: "mouseMoved", ...at });
  await frames();
  await page.send("Input.dispatchMouseEvent", { type: "mousePressed", button: "left", buttons: 1, clickCount: 1, ...at });
  await frames();
  await page.send("Input.dispatchMouseEvent", { type: "mouseReleased", button: "left", buttons: 0, clickCount: 1, ...at });
  await frames();
  // What the frames since the press drew: the passes this slider reaches.
  const drawn = await page.evaluate("glimmerPage.drawn()");
  const value = await page.evaluate(`glimmerPage.value(${JSON.stringify(name)})`);
  result.sliders.push({ name, value, drawn });
  savePng(`slider-${name}.png`, await page.evaluate("glimmerPage.snapshot()"));
}

// A typo in the shader: an undeclared name on LINE, then Reload.
const state = () => page.evaluate(`({ errors: glimmerPage.errors(), value: glimmerPage.value(${JSON.stringify(drags[0].split("=")[0])}),
  exit: Number(document.getElementById("verdict").dataset.exit), verdict: document.getElementById("verdict").textContent,
  diagnostics: document.getElementById("diagnostics").textContent })`);
const original = await page.evaluate(`glimmerPage.readFile(${JSON.stringify(shader)})`);
const broken = original.split("\n");
broken[Number(line) - 1] += " undeclaredTypo;";
await page.evaluate(`glimmerPage.writeFile(${JSON.stringify(shader)}, ${JSON.stringify(broken.join("\n"))}); glimmerPage.reload()`);
await frames();
result.broken = await state();
savePng("broken.png", await page.evaluate("glimmerPage.snapshot()"));
const shot = await page.send("Page.captureScreenshot", { format: "png" });
writeFileSync(join(outDir, "broken-page.png"), Buffer.from(shot.result.data, "base64"));
// The typo fixed: the same file again, and the errors go.
await page.evaluate(`glimmerPage.writeFile(${JSON.stringify(shader)}, ${JSON.stringify(original)}); glimmerPage.reload()`);
await frames();
result.restored = await state();
console.log(JSON.stringify(result));
page.close(0);
