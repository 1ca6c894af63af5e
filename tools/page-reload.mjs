// A reload in the middle of a lesson, for tests/web/reload.sh: opens the
// page, picks FOLDER with its folder button (as tools/page-pick-folder.mjs
// does), chooses SCRIPT of it and presses Draw, drags each named slider of
// the panel with the mouse, opens SHADER's tab in the editor and types a
// comment at its end; then reloads the page (a closed tab, a lost network)
// and reads the page again; last presses "Close folder" (the page reloads
// with the lesson's own scripts). Prints one JSON object { before, after,
// closed }, each the page's state then: the script chosen (select's value),
// the verdict, the file on show in the editor and whether its text holds
// the comment, each slider's value (glimmerPage.value), the scripts listed,
// the watch on (a watch of line 12 of SHADER is started before the reload),
// and the picture (a data URL).
//   NODE_PATH=/usr/share/nodejs node tools/page-reload.mjs PAGE_URL FOLDER SCRIPT SHADER NAME=FRACTION...
import { clickAt, openPage, sleep } from "./cdp-page.mjs";

const [url, folder, script, shader, ...drags] = process.argv.slice(2);
if (!drags.length) {
  console.error("usage: node tools/page-reload.mjs PAGE_URL FOLDER SCRIPT SHADER NAME=FRACTION...");
  process.exit(2);
}
const page = await openPage(url);
await page.send("Emulation.setDeviceMetricsOverride", { width: 1366, height: 768, deviceScaleFactor: 1, mobile: false });
await page.navigate();
const frames = () => sleep(300);
const names = drags.map((d) => d.split("=")[0]);
const comment = "// typed before the reload";
const state = () => page.evaluate(`(() => {
  const ed = glimmerPage.editor();
  const values = {};
  for (const name of ${JSON.stringify(names)}) values[name] = glimmerPage.value(name);
  return { script: document.getElementById("script").value, verdict: document.getElementById("verdict").textContent,
    shown: ed.shown(), typed: ed.cm.getValue().includes(${JSON.stringify(comment)}), values,
    scripts: [...document.getElementById("script").options].map((o) => o.value),
    labels: [...document.getElementById("script").options].map((o) => o.text),
    watch: glimmerPage.watch().summary ? glimmerPage.watch().spec : "", picture: glimmerPage.snapshot() };
})()`);
const waitFor = async (condition, what) => {
  for (let i = 0; i < 300; ++i) {
    if (await page.evaluate(condition)) return;
    await sleep(100);
  }
  console.error(`the page did not ${what}`);
  page.close(1);
  await new Promise(() => {});
};

// The folder picked with the page's button (the DevTools protocol sets it
// as the browser's dialog would).
const doc = await page.send("DOM.getDocument");
const input = await page.send("DOM.querySelector", { nodeId: doc.result.root.nodeId, selector: "#folder" });
const set = await page.send("DOM.setFileInputFiles", { nodeId: input.result.nodeId, files: [folder] });
if (set.error) { console.error("cannot pick the folder: " + set.error.message); page.close(1); }
await waitFor(`[...document.getElementById("script").options].some((o) => o.value.startsWith("/user:"))`, "list the picked folder");
await page.evaluate(`document.getElementById("script").value = ${JSON.stringify("/user:" + script)};
  document.getElementById("draw").click()`);
await waitFor(`document.getElementById("verdict").textContent === ${JSON.stringify(script + ": drawn")}`, `draw ${script}`);
await frames();

// Each slider dragged with the mouse, at its place on the canvas.
for (const drag of drags) {
  const [name, fraction] = drag.split("=");
  const at = await page.evaluate(`(() => {
    const canvas = document.getElementById("canvas"), box = canvas.getBoundingClientRect(), k = box.width / canvas.width;
    const [x, y, w, h] = glimmerPage.control(${JSON.stringify(name)});
    return w === undefined ? null : { x: box.left + (x + ${Number(fraction)} * w) * k, y: box.top + (y + h / 2) * k };
  })()`);
  if (!at) { console.error(`no control ${name} in the panel`); page.close(1); }
  await clickAt(page, at, frames);
}
// SHADER's tab clicked, a comment typed at its end.
await page.evaluate(`[...document.querySelectorAll("#tabs button")].find((b) => b.dataset.path === ${JSON.stringify(shader)}).click();
  glimmerPage.editor().cm.setCursor({ line: glimmerPage.editor().cm.lineCount() - 1, ch: 10000 }); glimmerPage.editor().cm.focus()`);
await page.send("Input.insertText", { text: "\n" + comment + "\n" });
await sleep(1200);  // the editor's pause after typing, the reload of the script
// A watch on (as the editor's Watch button starts it), kept with the values.
await page.evaluate(`glimmerPage.command("watch ${shader.split("/").pop()}:12 rgbblur")`);
await sleep(600);
const before = await state();

// The page reloaded.
await page.navigate();
await frames();
const after = await state();

// Close folder: the page reloads with the lesson's own scripts.
await page.evaluate(`document.getElementById("forget-folder").click()`);
await sleep(500);
await waitFor(`document.body && document.body.dataset.ready === "1"`, "reload after Close folder");
await frames();
const closed = await state();
console.log(JSON.stringify({ before, after, closed }));
page.close(0);
