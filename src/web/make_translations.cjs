// The bundled lesson's translations to GLSL ES 3.00, made by the page's own
// module (src/web/web_translations.cpp says why), run in node at build time:
//   node make_translations.cjs BUILD/glimmer-web.js OUT.txt
// Every script under the bundled lesson's scripts/ is checked as the page
// runs it; a script that fails its check stops the build with its messages.
"use strict";
const fs = require("fs");
const [modulePath, out] = process.argv.slice(2);
if (!modulePath || !out) {
  console.error("usage: node make_translations.cjs BUILD/glimmer-web.js OUT.txt");
  process.exit(2);
}
const createGlimmer = require(require("path").resolve(modulePath));
// The module as bytes: this Emscripten's loader would fetch() a path in node.
createGlimmer({ wasmBinary: fs.readFileSync(modulePath.replace(/\.js$/, ".wasm")), print: () => {}, printErr: () => {} })
  .then((glimmer) => {
    const inFs = "/kept-translations.txt";
    const made = glimmer.ccall("glimmer_translations_record", "number", ["string", "string"], ["/lesson", inFs]);
    if (made < 0) {
      console.error("make_translations: " + glimmer.ccall("glimmer_last_output", "string", [], []));
      process.exit(1);
    }
    fs.writeFileSync(out, glimmer.FS.readFile(inFs));
    console.log(`make_translations: ${made} translations of the bundled lesson -> ${out}`);
  }, (e) => { console.error("make_translations: the module did not start: " + e); process.exit(1); });
