// How long the page takes to take a student's input while a heavy pass
// redraws (issue 25): opens SCRIPT in the live view, drags the slider NAME
// back and forth with the mouse for SECONDS (a move every 16 ms, real input
// events over the DevTools protocol), and times each event from sending to
// the page's answer, which comes only when the page's main thread is free
// to handle it. Prints one JSON line per run: the page with its slices
// (the viewer core's budget) and, as the reference in the same process,
// the same page drawing whole frames (?slice-ms=0), and their p95 ratio.
//   NODE_PATH=/usr/share/nodejs node tools/page-input-latency.mjs PAGE_URL SCRIPT NAME [SECONDS]
import { openPage, sleep } from "./cdp-page.mjs";

const [url, script, name, seconds = "4"] = process.argv.slice(2);
if (!name) {
  console.error("usage: node tools/page-input-latency.mjs PAGE_URL SCRIPT NAME [SECONDS]");
  process.exit(2);
}

async function run(sliceMs) {
  const query = `view=${encodeURIComponent(script)}` + (sliceMs === null ? "" : `&slice-ms=${sliceMs}`);
  const page = await openPage(`${url}?${query}`);
  await page.send("Emulation.setDeviceMetricsOverride", { width: 1400, height: 1100, deviceScaleFactor: 1, mobile: false });
  await page.navigate();
  await sleep(1500);  // the first picture, and the GPU (or llvmpipe) warm
  const [cx, cy] = await page.evaluate(`(() => { const r = document.getElementById("canvas").getBoundingClientRect();
    return [r.left, r.top]; })()`);
  const [x, y, w, h] = await page.evaluate(`glimmerPage.control(${JSON.stringify(name)})`);
  const at = (f) => ({ x: cx + x + f * w, y: cy + y + h / 2 });
  const times = [];
  const timed = async (event) => {
    const t0 = performance.now();
    await page.send("Input.dispatchMouseEvent", event);
    times.push(performance.now() - t0);
  };
  await timed({ type: "mouseMoved", ...at(0.1) });
  await timed({ type: "mousePressed", button: "left", buttons: 1, clickCount: 1, ...at(0.1) });
  const end = performance.now() + Number(seconds) * 1000;
  for (let i = 0; performance.now() < end; ++i) {
    const f = 0.1 + 0.8 * Math.abs(((i * 0.02) % 2) - 1);  // back and forth along the slider
    const sent = performance.now();
    await timed({ type: "mouseMoved", button: "left", buttons: 1, ...at(f) });
    const left = 16 - (performance.now() - sent);
    if (left > 0) await sleep(left);
  }
  await timed({ type: "mouseReleased", button: "left", buttons: 0, clickCount: 1, ...at(0.5) });
  await page.close(null);
  times.sort((a, b) => a - b);
  const q = (p) => times[Math.min(times.length - 1, Math.floor(p * times.length))];
  return { sliceMs: sliceMs === null ? "default" : sliceMs, events: times.length, p50: +q(0.5).toFixed(1),
           p95: +q(0.95).toFixed(1), max: +times[times.length - 1].toFixed(1) };
}

const sliced = await run(null);
const whole = await run(0);
console.log(JSON.stringify({ script, slider: name, sliced, whole, p95Ratio: +(sliced.p95 / whole.p95).toFixed(3) }));
process.exit(0);
