// A user picking a folder on the page, as a test can do it: opens the page,
// hands FOLDER to its folder button (the DevTools protocol sets a directory
// on a webkitdirectory input as the browser's dialog would), waits for the
// page to draw the folder's first script, and writes that picture to
// OUT.png. With SAVE_DIR, then presses Save PNG with downloads going to
// SAVE_DIR and waits for the file. Prints the verdict and the diagnostics;
// exits with the page's status (0 drawn, 1 script errors, 2 refused).
// With --drop, the folder is dragged onto the page and dropped instead (the
// DevTools protocol's drag events, as a file manager's drag would send).
//   NODE_PATH=/usr/share/nodejs node tools/page-pick-folder.mjs [--drop] PAGE_URL FOLDER OUT.png [SAVE_DIR]
import { existsSync, readdirSync, writeFileSync } from "node:fs";
import { openPage, sleep } from "./cdp-page.mjs";

const args = process.argv.slice(2);
const drop = args[0] === "--drop" ? args.shift() : null;
const [url, folder, out, saveDir] = args;
if (!out) {
  console.error("usage: NODE_PATH=/usr/share/nodejs node tools/page-pick-folder.mjs PAGE_URL FOLDER OUT.png");
  process.exit(2);
}
const page = await openPage(url);
await page.navigate();
// The page opens drawing the seed bloom (issue 27): what it said then is not
// the answer to the folder.
const before = await page.evaluate(`document.getElementById("verdict").textContent`);
if (drop) {
  // Dragged from a file manager and let go over the page.
  const data = { items: [], files: [folder], dragOperationsMask: 1 };
  for (const type of ["dragEnter", "dragOver", "drop"]) {
    const sent = await page.send("Input.dispatchDragEvent", { type, x: 200, y: 200, data });
    if (sent.error) { console.error(`cannot drop the folder (${type}): ${sent.error.message}`); page.close(1); }
  }
} else {
  const doc = await page.send("DOM.getDocument");
  const input = await page.send("DOM.querySelector", { nodeId: doc.result.root.nodeId, selector: "#folder" });
  const set = await page.send("DOM.setFileInputFiles", { nodeId: input.result.nodeId, files: [folder] });
  if (set.error) { console.error("cannot pick the folder: " + set.error.message); page.close(1); }
}
// The page answers a picked folder by drawing (or refusing) it: wait for
// the verdict to change from what it said before.
let result;
for (let i = 0; i < 600 && !result; ++i) {
  result = await page.evaluate(`(() => {
    const v = document.getElementById("verdict");
    if (!v.dataset.exit || v.textContent === ${JSON.stringify(before)} ||
        !/^(yours|refused|[^:]*\\.glib:)/.test(v.textContent)) return null;
    // A drawn picture's PNG is made a frame after it is shown.
    if (v.dataset.exit === "0" && v.textContent.endsWith(": drawn") && !document.getElementById("picture").dataset.png) return null;
    return { exit: Number(v.dataset.exit), verdict: v.textContent,
             diagnostics: document.getElementById("diagnostics").textContent,
             png: document.getElementById("picture").dataset.png || "" };
  })()`);
  if (!result) await sleep(100);
}
if (!result) { console.error("the page did not answer the picked folder"); page.close(1); }
console.log(result.verdict);
process.stdout.write(result.diagnostics);
if (result.exit === 0 && result.png.startsWith("data:image/png;base64,"))
  writeFileSync(out, Buffer.from(result.png.slice("data:image/png;base64,".length), "base64"));
if (saveDir && result.exit === 0) {
  await page.send("Page.setDownloadBehavior", { behavior: "allow", downloadPath: saveDir });
  await page.evaluate(`document.getElementById("save").click()`);
  // Chromium writes NAME.crdownload, then renames it when done.
  const done = () => existsSync(saveDir) && readdirSync(saveDir).some((f) => f.endsWith(".png"));
  // Up to 30 s: the snapshot, its PNG and the download on a machine busy
  // with other tests (10 s was once too short in CI's -j2 run).
  for (let i = 0; i < 300 && !done(); ++i) await sleep(100);
  if (!done()) { console.error("Save PNG downloaded nothing"); page.close(1); }
  console.log("saved: " + readdirSync(saveDir).filter((f) => f.endsWith(".png")).join(" "));
}
page.close(result.exit);
