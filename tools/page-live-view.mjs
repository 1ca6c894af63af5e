// The page's live view as a student uses it, for tests/web/live_view.sh: opens
// SCRIPT (a bundled lesson path) in the live view, drags each named slider
// of the panel with the mouse (real input events over the DevTools
// protocol, at the control's place on the canvas), then breaks a shader the
// way a student's typo would, typed into the page's editor (after a line
// added to SCRIPT and Save file, which downloads it: OUT_DIR/downloads): the error on
// its line, a click on the message going to it, the edit surviving a
// reload of the page, Revert. Writes OUT_DIR/slider-NAME.png (the picture
// after each slider) and OUT_DIR/broken.png (after the typo), and prints
// one JSON object: { sliders: [{ name, value, drawn }], warnings, saved, broken, errorLine, clicked,
// reloaded, restored, untyped, selection }, each of broken to restored the page's state then
// (exit, errors, value, diagnostics, the editor's file, cursor line,
// marked lines and messages, text).
// With SHEET=NAME=V1,V2,... in the environment, the page's Save sheet too
// (OUT_DIR/sheet.png).
//   NODE_PATH=/usr/share/nodejs node tools/page-live-view.mjs PAGE_URL SCRIPT SHADER LINE OUT_DIR NAME=FRACTION...
// SHADER (its path as the script's diagnostics name it) gets an undeclared name on LINE
// (SHADER "-": the sliders only); FRACTION is where
// along the slider the mouse presses (0 its left end, 1 its right).
import { existsSync, readdirSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { clickAt, openPage, sleep } from "./cdp-page.mjs";

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
// The script's own warnings in the editor (SCRIPT shown): said quietly, a
// mark each and no open message; a click on the first mark opens its
// message, a second closes it (result.warnings).
const warningState = () => page.evaluate(`({ marks: document.querySelectorAll(".glimmer-mark-warning").length,
  open: [...document.querySelectorAll(".glimmer-message-warning")].map((e) => e.textContent) })`);
await page.evaluate(`glimmerPage.editor().open(${JSON.stringify(script)})`);
await frames();
result.warnings = { opened: await warningState() };
await page.evaluate(`document.querySelector(".glimmer-mark-warning") && document.querySelector(".glimmer-mark-warning").click()`);
result.warnings.clicked = await warningState();
await page.evaluate(`document.querySelector(".glimmer-mark-warning") && document.querySelector(".glimmer-mark-warning").click()`);
result.warnings.again = await warningState();
for (const drag of drags) {
  const [name, fraction] = drag.split("=");
  const [x, y, w, h] = await page.evaluate(`glimmerPage.control(${JSON.stringify(name)})`);
  if (w === undefined) { console.error(`no control ${name} in the panel`); page.close(1); }
  const at = { x: canvasAt[0] + x + Number(fraction) * w, y: canvasAt[1] + y + h / 2 };
  await page.evaluate("glimmerPage.drawn()");  // what was drawn before this slider: forgotten
  await clickAt(page, at, frames);
  // What the frames since the press drew: the passes this slider reaches.
  const drawn = await page.evaluate("glimmerPage.drawn()");
  const value = await page.evaluate(`glimmerPage.value(${JSON.stringify(name)})`);
  result.sliders.push({ name, value, drawn });
  savePng(`slider-${name}.png`, await page.evaluate("glimmerPage.snapshot()"));
}

// With PROBE=X,Y (picture pixels from its top left): the Probe box ticked
// with a click, the pointer moved over that pixel, and the probe's text
// then (result.probe), what the tooltip by the pointer says.
if (process.env.PROBE) {
  const [px, py] = process.env.PROBE.split(",").map(Number);
  const [x, y, w, h] = await page.evaluate(`glimmerPage.control("Probe")`);
  const box = { x: canvasAt[0] + x + 8, y: canvasAt[1] + y + h / 2 };
  await clickAt(page, box, frames);  // the panel sees the pointer, the press and the release each in frames of their own
  const over = { x: canvasAt[0] + px + 0.5, y: canvasAt[1] + py + 0.5 };
  await page.send("Input.dispatchMouseEvent", { type: "mouseMoved", ...over });
  await frames();
  result.probe = await page.evaluate("glimmerPage.probe()");
}

// Save sheet, varying the first slider over three values (the other at
// what its drag left): OUT_DIR/sheet.png.
if (process.env.SHEET) savePng("sheet.png", await page.evaluate(`glimmerPage.sheet(${JSON.stringify(process.env.SHEET)})`));
await frames();

if (shader === "-") {  // sliders only
  console.log(JSON.stringify(result));
  page.close(0);
  await new Promise(() => {});  // close() ends the process once Chromium has gone
}

// Save file with no folder to write into (the bundled lesson): the edited
// script is downloaded as the browser allows, to OUT_DIR/downloads; the
// kept edit stays until Revert.
await page.send("Page.setDownloadBehavior", { behavior: "allow", downloadPath: join(outDir, "downloads") });
await page.evaluate(`glimmerPage.editor().open(${JSON.stringify(script)}, 1, 1);
  glimmerPage.editor().cm.setCursor({ line: glimmerPage.editor().cm.lineCount() - 1, ch: 10000 }); glimmerPage.editor().cm.focus()`);
await page.send("Input.insertText", { text: "\n# saved from the page\n" });
await sleep(800);
await page.evaluate(`document.getElementById("save-file").click()`);
const downloaded = () => existsSync(join(outDir, "downloads")) && readdirSync(join(outDir, "downloads")).some((f) => !f.endsWith(".crdownload"));
for (let i = 0; i < 50 && !downloaded(); ++i) await sleep(100);
result.saved = { note: await page.evaluate(`document.getElementById("edit-note").textContent`),
                 kept: await page.evaluate(`Object.keys(localStorage).filter((k) => k.startsWith("glimmer-draft")).length`) };
await page.evaluate(`document.getElementById("revert").click()`);
await sleep(800);

// A typo typed into the page's editor at the end of LINE of SHADER (real
// key input into CodeMirror); the page reloads the script once typing stops.
const state = () => page.evaluate(`(() => {
  const ed = glimmerPage.editor();
  return { errors: glimmerPage.errors(), value: glimmerPage.value(${JSON.stringify(drags[0].split("=")[0])}),
    exit: Number(document.getElementById("verdict").dataset.exit), verdict: document.getElementById("verdict").textContent,
    diagnostics: document.getElementById("diagnostics").textContent, shown: ed.shown(),
    cursorLine: ed.cm.getCursor().line + 1,
    marked: [...document.querySelectorAll(".glimmer-error-line")].length,
    markedLines: ed.cm.getValue().split("\\n").map((_, i) => i + 1).filter((n) =>
      (ed.cm.lineInfo(n - 1).bgClass || "").includes("glimmer-error-line")).join(" "),
    message: [...document.querySelectorAll(".glimmer-message-error")].map((e) => e.textContent).join("\\n"),
    text: ed.cm.getValue() };
})()`);
const settle = () => sleep(1200);  // the editor's pause after typing, the reload, a few frames
await page.evaluate(`glimmerPage.editor().open(${JSON.stringify(shader)}, ${Number(line)}, 1);
  glimmerPage.editor().cm.setCursor({ line: ${Number(line) - 1}, ch: 10000 }); glimmerPage.editor().cm.focus()`);
await page.send("Input.insertText", { text: " undeclaredTypo;" });
await settle();
result.broken = await state();
savePng("broken.png", await page.evaluate("glimmerPage.snapshot()"));
const shot = await page.send("Page.captureScreenshot", { format: "png" });
writeFileSync(join(outDir, "broken-page.png"), Buffer.from(shot.result.data, "base64"));

// The error's line in the panel clicked with the mouse, as in the window
// (ViewerControls.ClickingAnError...): the panel copies its place and says
// so in its status (result.errorLine: the status, as `panel` gives it).
{
  const [x, y, w, h] = await page.evaluate(`glimmerPage.control("Error 1")`);
  if (w === undefined) result.errorLine = { status: "no control 'Error 1' in the panel" };
  else {
    await clickAt(page, { x: canvasAt[0] + x + Math.min(40, w / 2), y: canvasAt[1] + y + Math.min(8, h / 2) }, frames);
    const panel = await page.evaluate(`glimmerPage.command("panel")`);
    const status = (/(?:^| )status=(\S*)/.exec(panel) || [])[1] || "";
    result.errorLine = { status: decodeURIComponent(status) };
  }
}

// Clicking the error in the diagnostics goes to it (from another file on show).
await page.evaluate(`(() => { const ed = glimmerPage.editor(); ed.open(${JSON.stringify(script)}, 1, 1);
  [...document.querySelectorAll("#diagnostics .jump")].find((e) => e.textContent.includes("error:")).click(); })()`);
result.clicked = await state();

// The page reloaded (a closed tab, a lost network): the typed edit is still there.
await page.navigate();
await settle();
result.reloaded = await state();
if (result.reloaded.shown !== shader) {
  await page.evaluate(`glimmerPage.editor().open(${JSON.stringify(shader)})`);
  result.reloaded = await state();
}
// Revert: the file as the folder has it, the error gone, nothing kept.
await page.evaluate(`document.getElementById("revert").click()`);
await settle();
result.restored = await state();
result.restored.kept = await page.evaluate(`Object.keys(localStorage).filter((k) => k.startsWith("glimmer-draft")).length`);
// A typo typed and taken back (issue 39: it still counted as an edit): the
// text is the folder's again, so nothing is kept.
await page.evaluate(`glimmerPage.editor().open(${JSON.stringify(shader)}, ${Number(line)}, 1);
  glimmerPage.editor().cm.setCursor({ line: ${Number(line) - 1}, ch: 10000 }); glimmerPage.editor().cm.focus()`);
await page.send("Input.insertText", { text: "x" });
await sleep(500);
for (const type of ["keyDown", "keyUp"])
  await page.send("Input.dispatchKeyEvent", { type, key: "Backspace", code: "Backspace", windowsVirtualKeyCode: 8 });
await settle();
result.untyped = { kept: await page.evaluate(`Object.keys(localStorage).filter((k) => k.startsWith("glimmer-draft")).length`),
                   note: await page.evaluate(`document.getElementById("edit-note").textContent`) };
// Selected text in the editor (issue 39: light on light): the colours of
// the selection's background and of the text over it, the editor focused.
result.selection = await page.evaluate(`(() => { const cm = glimmerPage.editor().cm; cm.focus(); cm.execCommand("selectAll");
  const sel = document.querySelector(".CodeMirror-selected"), line = document.querySelector(".CodeMirror-line");
  return { background: sel ? getComputedStyle(sel).backgroundColor : "", text: line ? getComputedStyle(line).color : "" }; })()`);
console.log(JSON.stringify(result));
page.close(0);
