// `glimmer view`'s commands run in the page's live view, for the test that
// drives both shells with the same commands (tests/web/both_shells.sh):
// opens SCRIPT in the live view at WxH with the slice budget SLICE_MS, then
// runs each line of COMMANDS_FILE through glimmerPage.command (the same
// viewer core as the window's), letting the page draw between them as a
// window would between lines on its standard input. A line "wait MS" only
// waits; "quit" ends the list, as it ends the window. `save NAME` writes the picture to OUT_DIR/NAME. Prints one JSON
// object: { said: [what each command answered, "" for nothing] }.
//   NODE_PATH=/usr/share/nodejs node tools/page-commands.mjs PAGE_URL SCRIPT WxH SLICE_MS COMMANDS_FILE OUT_DIR
import { readFileSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { openPage, sleep } from "./cdp-page.mjs";

const [url, script, size, sliceMs, commandsFile, outDir] = process.argv.slice(2);
if (!outDir) {
  console.error("usage: node tools/page-commands.mjs PAGE_URL SCRIPT WxH SLICE_MS COMMANDS_FILE OUT_DIR");
  process.exit(2);
}
const page = await openPage(`${url}?view=${encodeURIComponent(script)}&size=${size}&slice-ms=${sliceMs}`);
await page.send("Emulation.setDeviceMetricsOverride", { width: 1400, height: 1100, deviceScaleFactor: 1, mobile: false });
await page.navigate();
await sleep(500);  // a few of its frames
const said = [];
for (const line of readFileSync(commandsFile, "utf8").split("\n")) {
  const wait = /^wait (\d+)$/.exec(line.trim());
  if (wait) { await sleep(Number(wait[1])); continue; }
  if (!line.trim()) continue;
  if (line.trim() === "quit") break;  // the window's end; the page's is closing its tab
  said.push(await page.evaluate(`glimmerPage.command(${JSON.stringify(line)})`));
  const save = /^save (\S+)$/.exec(line.trim());
  if (save) {
    const png = await page.evaluate("document.getElementById('picture').dataset.png || ''");
    writeFileSync(join(outDir, save[1]), Buffer.from(png.slice("data:image/png;base64,".length), "base64"));
  }
  await sleep(100);  // a few of the page's frames, as a window draws between two lines of input
}
console.log(JSON.stringify({ said }));
page.close(0);
