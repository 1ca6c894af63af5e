// "Measure blurs": `glimmer tradeoff` on the student's own machine (the
// lesson's minutes 30 to 38; web_tradeoff.cpp runs the desktop's measuring
// code). Made by glimmer-page.js once the module is up. The methods run
// one piece of work per animation frame (a method prepared, a part of its
// warm-up, one timed run, its CPU references), so the page keeps painting and
// shows how far it is; the table is filled when the last method is done.
//
// For the tests (tests/web/tradeoff.sh): #blurs has data-state "running",
// "done" or "failed"; each row of #blurs-table tbody carries the figures
// unrounded in data-* attributes (method, taps, ms, min, max, model-psnr,
// num-psnr, num-max, num-over), #blurs-fastest data-methods the fastest's
// name(s), comma-separated.
"use strict";
const blurMeasurement = (glimmer) => {
  // The lesson's set (docs/teaching.md, minutes 30 to 38) at the size its
  // desktop command uses, and dual Kawase, which costs 12 taps a pixel.
  const size = 256, repeat = 5, words = "superblur sep9 linear5 kawase";
  const box = document.getElementById("blurs");
  const button = document.getElementById("measure-blurs");
  const progress = document.getElementById("blurs-progress");
  const body = document.querySelector("#blurs-table tbody");
  const fastest = document.getElementById("blurs-fastest");
  const status = () => glimmer.UTF8ToString(glimmer._glimmer_tradeoff_status());
  // The GPU's own name where the browser tells it (WebGL's GL_RENDERER is
  // the browser's); the canvas's context is the module's, asked again.
  // WebKit answers "Apple GPU" on every machine (it masks the name even
  // there): said as what it is, not as a GPU this machine has.
  const gpuName = () => {
    const gl = document.getElementById("canvas").getContext("webgl2");
    const info = gl && gl.getExtension("WEBGL_debug_renderer_info");
    const name = info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : "";
    const mac = /Mac/.test(navigator.platform || "");
    return name === "Apple GPU" && !mac ? "a GPU the browser does not name (it says \"Apple GPU\" on any machine)" : name;
  };
  const cell = (row, text, title = "") => {
    const td = row.insertCell();
    td.textContent = text;
    if (title) td.title = title;
  };
  const fixed = (v, digits) => (v === null ? "inf" : v.toFixed(digits));
  const show = (result) => {
    body.textContent = "";
    for (const m of result.methods) {
      const row = body.insertRow();
      Object.assign(row.dataset, { method: m.method, taps: m.taps, ms: m.ms, min: m.min, max: m.max,
        modelPsnr: m.model.psnr, numPsnr: m.numerical.psnr, numMax: m.numerical.max, numOver: m.numerical.over_one_step });
      cell(row, m.method, m.family + ", sigma " + m.sigma.toFixed(2) + " texels");
      cell(row, String(m.taps));
      cell(row, m.ms.toFixed(2), `fastest run ${m.min.toFixed(2)} ms, slowest ${m.max.toFixed(2)} ms (${m.runs} runs of ` +
           `${result.min_run_ms} ms or more, up to ${m.renders_per_run} render${m.renders_per_run > 1 ? "s" : ""} each)`);
      row.dataset.rendersPerRun = m.renders_per_run;
      cell(row, fixed(m.model.psnr, 1), `RMSE ${m.model.rmse.toExponential(2)}, largest error ${m.model.max.toExponential(2)}`);
      cell(row, fixed(m.numerical.psnr, 1),
           `RMSE ${m.numerical.rmse.toExponential(2)}, largest error ${m.numerical.max.toExponential(2)}, ` +
           `${m.numerical.over_one_step} pixels off by more than an 8-bit step`);
      if (!m.healthy) row.classList.add("bad");
    }
    // The desktop's verdict (app/tradeoff_report.cpp): a winner only when
    // its slowest run beats every other candidate's fastest.
    const f = result.fastest, near = `within ${f.near_gaussian_psnr} dB of its Gaussian`;
    fastest.dataset.methods = f.methods.join(",");
    if (!f.methods.length) fastest.textContent = `No method came ${near}.`;
    else if (f.clear_winner) {
      const w = result.methods.find((m) => m.method === f.methods[0]);
      fastest.textContent = `Fastest ${near}: ${w.method}, ${w.ms.toFixed(2)} ms (runs ${w.min.toFixed(2)} to ` +
        `${w.max.toFixed(2)}), ${fixed(w.model.psnr, 1)} dB` + (f.candidates > 1 ? "; its slowest run beats every other's fastest." : ".");
    } else fastest.textContent = `Fastest ${near}: a tie within the noise of the runs: ${f.methods.join(", ")}.`;
  };
  let running = false;
  const start = () => {
    if (running) return;
    box.hidden = false;
    body.textContent = "";
    fastest.textContent = "";
    delete fastest.dataset.methods;
    const count = glimmer.ccall("glimmer_tradeoff_start", "number", ["number", "number", "number", "string"],
                                [size, size, repeat, words]);
    if (count < 0) {
      box.dataset.state = "failed";
      progress.textContent = glimmer.ccall("glimmer_last_output", "string", [], []).trim();
      return;
    }
    running = true;
    button.disabled = true;
    box.dataset.state = "running";
    progress.textContent = `measuring ${count} methods at ${size}x${size}, ${repeat} runs each...`;
    const step = () => {
      const more = glimmer._glimmer_tradeoff_step();
      if (more > 0) {
        progress.textContent = "measuring " + status() + "...";
        requestAnimationFrame(step);
        return;
      }
      running = false;
      button.disabled = false;
      if (more < 0) {
        box.dataset.state = "failed";
        progress.textContent = status() + "\n" + glimmer.ccall("glimmer_last_output", "string", [], []).trim();
        return;
      }
      const result = JSON.parse(glimmer.UTF8ToString(glimmer._glimmer_tradeoff_rows()));
      show(result);
      const gpu = gpuName();
      progress.textContent = `${result.width}x${result.height} grid, ${result.format} targets, median of ` +
        `${result.repeat} runs, on ${gpu || result.renderer}`;
      box.dataset.state = "done";
    };
    requestAnimationFrame(step);
  };
  button.onclick = start;
  document.getElementById("blurs-close").onclick = () => { if (!running) box.hidden = true; };
  return { start };
};
