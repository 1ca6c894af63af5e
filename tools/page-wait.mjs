// Waiting on a page, shared by the engine drivers' steps (page-engine.mjs,
// panel-tour.mjs, page-window-layout.mjs): `until` asks `evaluate` (the
// driver's: a JavaScript expression in the page -> its value) every 100 ms
// until `done(value)` holds or `ms` have passed, and returns the last value
// either way (the caller judges a timeout by it).
export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
export const kPageReady = `document.body && document.body.dataset.ready === "1"`;

export async function until(evaluate, expression, ms, done = (v) => v) {
  let value;
  for (const end = Date.now() + ms; Date.now() < end; await sleep(100)) {
    value = await evaluate(expression);
    if (done(value)) break;
  }
  return value;
}
