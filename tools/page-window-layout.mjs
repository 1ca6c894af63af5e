// The page's layout in a real window (issue 39), for tools/page-engine.mjs
// --layout=WxH and tests/web/layout.sh: the window's outer size is WxH, so
// the page gets what a laptop's browser leaves it once its bars are drawn
// (not a viewport of WxH). The seed opened (a fresh profile: nothing kept),
// then a watch on (the panel at its longest), then a typo typed into
// bloom.frag (an error showing); each time the places of what a student
// must see, in CSS pixels of the viewport. Screenshots OUT_DIR/WxH-{open,
// watching,broken}.png. measureLayout(browser, pageUrl, outDir, [w, h]) ->
// { outer, open, watching, broken }.
import { writeFileSync } from "node:fs";
import { join } from "node:path";

import { kPageReady, sleep, until } from "./page-wait.mjs";

// The panel's controls a student needs in view: the sliders, and with a
// watch on its buttons (the ones at the right end of their rows).
const kControls = ["uAdd", "uHalfSize", "Reload", "Watch button", "Stop", "Own range", "Error 1"];

const measure = (evaluate) => evaluate(`(() => {
  const rect = (r) => r && r.width > 0 ? { left: r.left, top: r.top, right: r.right, bottom: r.bottom, width: r.width, height: r.height } : null;
  const canvas = document.getElementById("canvas");
  const box = canvas.getBoundingClientRect(), k = box.width / canvas.width;
  const controls = {};
  for (const name of ${JSON.stringify(kControls)}) {
    const [x, y, w, h] = glimmerPage.control(name);
    controls[name] = w === undefined ? null : rect({ left: box.left + x * k, top: box.top + y * k,
      right: box.left + (x + w) * k, bottom: box.top + (y + h) * k, width: w * k, height: h * k });
  }
  const el = (id) => { const e = document.getElementById(id); return e && e.offsetParent ? rect(e.getBoundingClientRect()) : null; };
  const cm = document.querySelector("#edit .CodeMirror");
  return { viewport: [window.innerWidth, window.innerHeight], outer: [window.outerWidth, window.outerHeight],
    scroll: [document.scrollingElement.scrollWidth, document.scrollingElement.scrollHeight],
    canvas: rect(box), controls, editor: cm && cm.offsetParent ? rect(cm.getBoundingClientRect()) : null,
    verdict: el("verdict"), verdictText: document.getElementById("verdict").textContent,
    firstError: el("first-error"), errors: glimmerPage.errors(), panelState: glimmerPage.command("panel") };
})()`);

export async function measureLayout(browser, pageUrl, outDir, [w, h]) {
  const { evaluate } = browser;
  const shoot = async (name) => { try { writeFileSync(join(outDir, `${w}x${h}-${name}.png`), await browser.screenshot()); } catch {} };
  await browser.go(`${pageUrl}?view=${encodeURIComponent("scripts/bloom.glib")}`);
  await until(evaluate, kPageReady, 60000);
  await sleep(800);  // the panel settles its width over a few frames
  const open = await measure(evaluate);
  await shoot("open");
  const watchSaid = await evaluate(`glimmerPage.command("watch bloom.frag:12 rgbblur")`);
  await sleep(1500);
  const watching = { ...(await measure(evaluate)), said: watchSaid };
  await shoot("watching");
  await evaluate(`glimmerPage.command("watch off")`);
  // The typo of the engine groups: " undeclaredTypo;" at the end of line 13.
  await evaluate(`(() => { const ed = glimmerPage.editor(); ed.open("shaders/bloom.frag");
    ed.cm.replaceRange(" undeclaredTypo;", { line: 12, ch: ed.cm.getLine(12).length }); return 1; })()`);
  for (const end = Date.now() + 10000; Date.now() < end; await sleep(200))
    if (await evaluate("glimmerPage.errors()") === 1) break;
  await sleep(800);
  const broken = await measure(evaluate);
  await shoot("broken");
  return { open, watching, broken };
}
