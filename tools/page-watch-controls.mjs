// The panel's watch controls clicked in the page as a student would (issue
// 39: they did nothing there; the tests drove the watch by command), for
// tests/web/watch.sh: opens SCRIPT in the live view, clicks the panel's
// Watch field and types WATCH into it (real key events), clicks Watch,
// types LO and HI into the range's two fields, clicks Fix range, then Own
// range, then Stop; after each step the page's watch state
// (glimmerPage.watch(): spec, summary, refusal). Prints one JSON object:
// { typed, fixed, own, stopped }.
//   NODE_PATH=/usr/share/nodejs node tools/page-watch-controls.mjs PAGE_URL SCRIPT WATCH LO HI
import { clickAt, openPage, sleep } from "./cdp-page.mjs";

const [url, script, watch, lo, hi] = process.argv.slice(2);
if (!hi) {
  console.error("usage: node tools/page-watch-controls.mjs PAGE_URL SCRIPT WATCH LO HI");
  process.exit(2);
}
const page = await openPage(`${url}?view=${encodeURIComponent(script)}`);
await page.send("Emulation.setDeviceMetricsOverride", { width: 1400, height: 1100, deviceScaleFactor: 1, mobile: false });
await page.navigate();
const frames = () => sleep(300);
const canvasAt = await page.evaluate(`(() => { const r = document.getElementById("canvas").getBoundingClientRect();
  return [r.left, r.top]; })()`);
await frames();

// The middle of the panel's control `name` (at `fraction` of its width), on the page.
const control = async (name, fraction = 0.5) => {
  const [x, y, w, h] = await page.evaluate(`glimmerPage.control(${JSON.stringify(name)})`);
  if (w === undefined) {
    console.error(`no control ${name} in the panel`);
    page.close(1);
  }
  return { x: canvasAt[0] + x + fraction * w, y: canvasAt[1] + y + h / 2 };
};
const type = async (text) => {
  for (const ch of text) {
    await page.send("Input.dispatchKeyEvent", { type: "keyDown", key: ch, text: ch });
    await page.send("Input.dispatchKeyEvent", { type: "keyUp", key: ch });
  }
  await frames();
};
// A click into a number field puts the cursor at its end: End, then
// Backspace as often as the field can hold characters, then the new text.
const retype = async (at, text) => {
  await clickAt(page, at, frames);
  // The panel reads a key as held at a frame's start: down for a few frames,
  // then up for a few, or a press between two frames is never seen.
  const key = async (k) => {
    await page.send("Input.dispatchKeyEvent", { type: "keyDown", key: k, code: k, windowsVirtualKeyCode: k === "End" ? 35 : 8 });
    await sleep(60);
    await page.send("Input.dispatchKeyEvent", { type: "keyUp", key: k, code: k, windowsVirtualKeyCode: k === "End" ? 35 : 8 });
    await sleep(60);
  };
  await key("End");
  for (let i = 0; i < 12; ++i) await key("Backspace");
  await type(text);
};
const state = () => page.evaluate("glimmerPage.watch()");

const result = {};
await clickAt(page, await control("Watch"), frames);
await type(watch);
await clickAt(page, await control("Watch button"), frames);
await frames();
result.typed = await state();
await retype(await control("Watch range", 0.2), lo);
await retype(await control("Watch range", 0.7), hi);
await clickAt(page, await control("Fix range"), frames);
await frames();
result.fixed = await state();
await clickAt(page, await control("Own range"), frames);
await frames();
result.own = await state();
await clickAt(page, await control("Stop"), frames);
await frames();
result.stopped = await state();
console.log(JSON.stringify(result));
page.close(0);
await new Promise(() => {});  // close() ends the process once Chromium has gone
