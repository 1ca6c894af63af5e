// The panel tour in the page (issue 39), for tools/page-engine.mjs --tour:
// tests/data/panel_tour.txt's steps (that file says what each means), each
// control found with the core's `where` (glimmerPage.control) and pressed,
// dragged or typed into with the engine's real mouse and keys, its effect
// read back with `panel` (glimmerPage.command). The window takes the same
// tour (tests/viewer/panel_tour_test.cpp): one table, one core answering.
// runTour(browser, pageUrl) -> { steps, failures: [ "panel_tour.txt:N: ..." ] }
import { readFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

import { kPageReady, sleep, until } from "./page-wait.mjs";
const tablePath = join(dirname(fileURLToPath(import.meta.url)), "..", "tests", "data", "panel_tour.txt");

export function readTour(text = readFileSync(tablePath, "utf8")) {
  const tour = [];
  text.split("\n").forEach((raw, i) => {
    const line = raw.trim();
    if (!line || line.startsWith("#")) return;
    if (line.startsWith("script ")) { tour.push({ script: line.slice(7).trim(), steps: [] }); return; }
    const parts = line.split(" | ").map((p) => p.trim());
    if (parts.length !== 3 || !tour.length) throw new Error(`panel_tour.txt:${i + 1}: not a step`);
    const [verbAt, ...rest] = parts[1].split(" ");
    const [action, at] = verbAt.split("@");
    tour.at(-1).steps.push({ line: i + 1, control: parts[0], action, at: at === undefined ? 0.5 : Number(at),
                             text: rest.join(" "), expect: parts[2].split(/\s+/).filter(Boolean) });
  });
  return tour;
}

const parseState = (line) => {
  const out = {};
  for (const w of (line || "").split(" ")) {
    const eq = w.indexOf("=");
    if (eq > 0 && !(w.slice(0, eq) in out)) out[w.slice(0, eq)] = w.slice(eq + 1);
  }
  return out;
};

// The size a PNG data URL's header gives, "WxH".
const pngSize = (href) => {
  const bytes = Buffer.from(href.slice(href.indexOf(",") + 1), "base64");
  return bytes.length < 24 ? "?" : `${bytes.readUInt32BE(16)}x${bytes.readUInt32BE(20)}`;
};

export async function runTour(browser, pageUrl) {
  const { evaluate } = browser;
  const failures = [];
  let steps = 0;
  const state = async () => parseState(await evaluate(`glimmerPage.command("panel")`));
  const freshState = async () => { await state(); await sleep(400); return state(); };
  // The control's middle (at `at` of its width) in the viewport, the page
  // scrolled so it is in view; null when the panel has no such control now.
  const locate = (name, at = 0.5) => evaluate(`(() => {
    const [x, y, w, h] = glimmerPage.control(${JSON.stringify(name)});
    if (w === undefined) return null;
    const canvas = document.getElementById("canvas");
    let r = canvas.getBoundingClientRect();
    const scale = r.width / canvas.width, py = r.top + (y + h / 2) * scale;
    if (py < 40 || py > window.innerHeight - 40) { window.scrollBy(0, py - window.innerHeight / 2); r = canvas.getBoundingClientRect(); }
    return [r.left + (x + ${at} * w) * scale, r.top + (y + h / 2) * scale];
  })()`);
  // Each event 300 ms apart: the panel (Dear ImGui 1.86) reads the button
  // as held or not at each frame, so a press and release inside one slow
  // frame (a loaded CI machine) would be no click at all.
  const press = async (x, y, button) => {
    for (const kind of ["move", "down", "up"]) { await browser.mouse(kind, x, y, button); await sleep(300); }
  };
  const act = async (s) => {
    let at = null;
    for (let i = 0; i < 20 && !at; ++i) { at = await locate(s.control, s.at); if (!at) await sleep(250); }
    if (!at) return `no control '${s.control}' in the panel`;
    const [x, y] = at;
    if (s.action === "click") await press(x, y, "left");
    else if (s.action === "rclick") await press(x, y, "right");
    else if (s.action === "drag") {
      const dx = Number(s.text);
      await browser.mouse("move", x, y); await sleep(150);
      await browser.mouse("down", x, y); await sleep(200);
      for (let k = 1; k <= 8; ++k) { await browser.mouse("move", x + dx * k / 8, y); await sleep(50); }
      await sleep(200);
      await browser.mouse("up", x + dx, y); await sleep(300);
    } else if (s.action === "type" || s.action === "write") {
      // As in the window: what the field holds selected (Ctrl+A), the text typed over it.
      await press(x, y, "left");
      await sleep(150);
      await browser.hold(["Control", "a"]);
      await sleep(150);
      await browser.type(s.text);
      if (s.action === "type") { await sleep(200); await browser.hold(["Enter"]); }
      await sleep(300);
    } else return `unknown action '${s.action}'`;
    return "";
  };
  const saves = () => evaluate("(globalThis.__tourSaved || []).length");
  const check = async (e, before, after, savesBefore) => {
    const value = (m, k) => (k in m ? m[k] : "(none)");
    if (e.startsWith("shown:") || e.startsWith("gone:")) {
      const want = e.startsWith("shown:");
      const name = e.slice(e.indexOf(":") + 1).replaceAll("%20", " ");
      const found = (await evaluate(`glimmerPage.control(${JSON.stringify(name)}).length`)) === 4;
      return found === want ? "" : `${want ? "no control" : "still a control"} ${name}`;
    }
    if (e.startsWith("saved")) {
      const saved = await evaluate("globalThis.__tourSaved || []");
      if (saved.length <= savesBefore) return "no new PNG";
      const size = pngSize(saved.at(-1).href);
      return e.length > 6 && size !== e.slice(6) ? `saved ${saved.at(-1).name} at ${size}` : "";
    }
    if (e.endsWith("^")) {
      const k = e.slice(0, -1);
      return value(before, k) !== value(after, k) ? "" : `${k} still ${value(after, k)}`;
    }
    for (const op of ["~", "="]) {
      const at = e.indexOf(op);
      if (at < 0) continue;
      const k = e.slice(0, at), want = e.slice(at + 1), got = value(after, k);
      if (op === "~") return got.includes(want) ? "" : `${k}=${got}`;
      const pm = want.indexOf("+-");
      if (pm >= 0) return Math.abs(Number(got) - Number(want.slice(0, pm))) <= Number(want.slice(pm + 2)) ? "" : `${k}=${got}`;
      return got === want ? "" : `${k}=${got}`;
    }
    return `cannot read the expectation '${e}'`;
  };

  for (const section of readTour()) {
    await browser.go(`${pageUrl}?view=${encodeURIComponent(section.script)}`);
    if (!(await until(evaluate, kPageReady, 60000))) { failures.push(`${section.script}: the page was not ready in 60 s`); continue; }
    // The page's downloads (Save PNG, Save at size) caught, not made: their names and pictures kept.
    await evaluate(`(() => { globalThis.__tourSaved = [];
      HTMLAnchorElement.prototype.click = function () { globalThis.__tourSaved.push({ name: this.download, href: this.href }); };
      return 1; })()`);
    for (const s of section.steps) {
      const where = `panel_tour.txt:${s.line}: ${s.control} | ${s.action} ${s.text}`;
      const before = await freshState(), savesBefore = await saves();
      const why = await act(s);
      if (why) { failures.push(`${where}: ${why}`); break; }
      let failed = [];
      for (const end = Date.now() + 10000; ;) {
        await sleep(300);
        const after = await state();
        failed = [];
        for (const e of s.expect) {
          const not = await check(e, before, after, savesBefore);
          if (not) failed.push(`${e}: ${not}`);
        }
        if (!failed.length || Date.now() > end) break;
      }
      for (const f of failed) failures.push(`${where}: ${f}`);
      ++steps;
    }
  }
  return { steps, failures };
}
