// The page's side of src/web/web_check.cpp: lists the lesson's scripts,
// checks the chosen one, shows the diagnostics as the desktop prints them.
// A test (tests/web) opens the page with ?check=PATH and reads the result
// from the DOM: data-exit on #verdict and the text of #diagnostics.
"use strict";
createGlimmer().then((glimmer) => {
  const check = glimmer.cwrap("glimmer_check", "number", ["string"]);
  const output = glimmer.cwrap("glimmer_last_output", "string", []);
  const select = document.getElementById("script");
  const verdict = document.getElementById("verdict");
  const shown = document.getElementById("diagnostics");

  // Every .glib under /lesson, as "scripts/bloom.glib".
  const scripts = [];
  const walk = (dir) => {
    for (const name of glimmer.FS.readdir(dir)) {
      if (name === "." || name === "..") continue;
      const path = dir + "/" + name;
      if (glimmer.FS.isDir(glimmer.FS.stat(path).mode)) walk(path);
      else if (name.endsWith(".glib")) scripts.push(path.slice("/lesson/".length));
    }
  };
  walk("/lesson");
  scripts.sort();
  for (const s of scripts) select.add(new Option(s, s));

  const run = (path) => {
    // The paths in diagnostics are relative to the lesson, as on the desktop
    // when run from the repository root.
    glimmer.FS.chdir("/lesson");
    const exit = check(path);
    verdict.dataset.exit = String(exit);
    verdict.className = exit === 0 ? "ok" : "bad";
    verdict.textContent = exit === 0 ? path + ": no errors" : exit === 1 ? path + ": errors" : path + ": cannot be read";
    shown.textContent = output();
  };
  document.getElementById("check").onclick = () => run(select.value);
  const asked = new URLSearchParams(location.search).get("check");
  if (asked) { select.value = asked; run(asked); }
  document.body.dataset.ready = "1";
});
