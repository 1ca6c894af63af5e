// Watches in the page against the same shaders hand-edited in the page
// (issue 28; tests/web/watch.sh): for each case, opens SCRIPT in the live
// view at WxH, runs `watch range 0,1` and `watch FILE:LINE EXPR` through
// glimmerPage.command (the viewer core the window runs) and saves the
// picture; then writes the shader with its colour line writing COLOUR (as a
// student would edit it, through glimmerPage.writeFile), reloads, and saves
// that picture. Both are drawn by the same WebGL 2 in the same page, so they
// must be the same bytes. Also the words of a refusal (a variable not in
// scope), to compare with `glimmer check --watch`'s.
//   NODE_PATH=/usr/share/nodejs node tools/page-watch.mjs PAGE_URL CASES_JSON OUT_DIR
// CASES_JSON: [{script, shader, line, expression, colour}], shader as the
// editor's tabs name it (scripts/exercises/bright.frag). Prints one JSON
// object: {said: [the watch's answer per case], refusal: "..."}; the pictures
// are OUT_DIR/watch-N.png and OUT_DIR/hand-N.png.
import { readFileSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { openPage, sleep } from "./cdp-page.mjs";

const [url, casesFile, outDir] = process.argv.slice(2);
if (!outDir) {
  console.error("usage: node tools/page-watch.mjs PAGE_URL CASES_JSON OUT_DIR");
  process.exit(2);
}
const cases = JSON.parse(readFileSync(casesFile, "utf8"));
const page = await openPage(url);
await page.send("Emulation.setDeviceMetricsOverride", { width: 1400, height: 1100, deviceScaleFactor: 1, mobile: false });
await page.navigate();
const ev = (js) => page.evaluate(js);
const savePicture = async (name) => {
  await ev(`glimmerPage.command("save ${name}")`);
  const png = await ev("document.getElementById('picture').dataset.png || ''");
  writeFileSync(join(outDir, name), Buffer.from(png.slice("data:image/png;base64,".length), "base64"));
};
const said = [];
for (const [i, c] of cases.entries()) {
  const opened = await ev(`glimmerPage.view(${JSON.stringify(c.script)}, ${c.size || 96}, ${c.size || 96})`);
  if (opened !== 0) console.error(`${c.script}: the page's view exited ${opened}: ${await ev("document.getElementById('diagnostics').textContent")}`);
  for (const set of c.sets || []) await ev(`glimmerPage.command(${JSON.stringify("set " + set.replace("=", " "))})`);
  await ev(`glimmerPage.command("watch range 0,1")`);
  said.push(await ev(`glimmerPage.command(${JSON.stringify(`watch ${c.shader}:${c.line} ${c.expression}`)})`));
  await savePicture(`watch-${i}.png`);
  await ev(`glimmerPage.command("watch off")`);
  // The hand edit: the shader's last colour line writes the value instead.
  const original = await ev(`glimmerPage.readFile(${JSON.stringify(c.shader)})`);
  const at = original.lastIndexOf("gl_FragColor =");
  const end = original.indexOf("\n", at);
  const edited = original.slice(0, at) + `gl_FragColor = vec4( ${c.colour}, 1. );` + original.slice(end);
  await ev(`glimmerPage.writeFile(${JSON.stringify(c.shader)}, ${JSON.stringify(edited)})`);
  await ev("glimmerPage.reload()");
  for (const set of c.sets || []) await ev(`glimmerPage.command(${JSON.stringify("set " + set.replace("=", " "))})`);
  if (c.unit !== undefined) await ev(`glimmerPage.command("show ${c.unit}")`);
  await savePicture(`hand-${i}.png`);
  await ev(`glimmerPage.command("show screen")`);
  await ev(`glimmerPage.writeFile(${JSON.stringify(c.shader)}, ${JSON.stringify(original)})`);
  await sleep(50);
}
await ev(`glimmerPage.view("scripts/bloom.glib", 96, 96)`);
const refusal = await ev(`glimmerPage.command("watch bloom.frag:11 rgbblur")`);
console.log(JSON.stringify({ said, refusal }));
page.close(0);
