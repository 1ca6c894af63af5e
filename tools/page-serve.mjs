// A student and the teacher in Chromium against `glimmer serve`, for
// tests/web/serve.sh (issue 41): the student opens their link, types into a
// shader, sees it saved; a fresh profile (another machine) opens the same
// link and finds the edit; Hand in shows the grade and a feedback link; the
// teacher's page lists the student with that grade; the teacher's "follow
// me" moves the student's slider. Prints one JSON object of what was seen.
//   NODE_PATH=/usr/share/nodejs node tools/page-serve.mjs STUDENT_LINK TEACHER_LINK SHADER
import { openPage, sleep } from "./cdp-page.mjs";

const [studentLink, teacherLink, shader] = process.argv.slice(2);
if (!shader) {
  console.error("usage: node tools/page-serve.mjs STUDENT_LINK TEACHER_LINK SHADER");
  process.exit(2);
}
const waitFor = async (page, condition, what, seconds = 60) => {
  for (let i = 0; i < seconds * 10; ++i) {
    const v = await page.evaluate(condition);
    if (v) return v;
    await sleep(100);
  }
  console.error(`the page did not ${what}; it shows: ` + await page.evaluate("document.body.innerText.slice(0, 600)"));
  page.close(1);
  await new Promise(() => {});
};
const comment = "// typed in the lab";
const seen = {};

// The student's link: the lesson drawn, the serve bar there.
let student = await openPage(studentLink);
await student.navigate();
await waitFor(student, `document.getElementById("verdict").textContent.endsWith(": drawn")`, "draw the lesson");
seen.who = await student.evaluate(`document.getElementById("serve-who").textContent`);
seen.scriptLabels = await student.evaluate(`[...document.getElementById("script").options].map((o) => o.text)`);
// A comment typed at the end of SHADER, as a student types it.
await student.evaluate(`[...document.querySelectorAll("#tabs button")].find((b) => b.dataset.path === ${JSON.stringify(shader)}).click();
  glimmerPage.editor().cm.setCursor({ line: glimmerPage.editor().cm.lineCount() - 1, ch: 10000 }); glimmerPage.editor().cm.focus()`);
await student.send("Input.insertText", { text: "\n" + comment + "\n" });
seen.saved = await waitFor(student, `(() => { const t = document.getElementById("serve-saved").textContent;
  return t.startsWith("saved (version") ? t : ""; })()`, "say the edit was saved");
await student.close(null);

// Another machine: a fresh profile, the same link.
student = await openPage(studentLink);
await student.navigate();
await waitFor(student, `document.getElementById("verdict").textContent.endsWith(": drawn")`, "draw the lesson again");
await student.evaluate(`[...document.querySelectorAll("#tabs button")].find((b) => b.dataset.path === ${JSON.stringify(shader)}).click()`);
seen.continued = await student.evaluate(`glimmerPage.editor().cm.getValue().includes(${JSON.stringify(comment)})`);

// Hand in: the grade and the feedback link appear in the page.
await student.evaluate(`document.getElementById("serve-hand-in").click()`);
seen.grade = await waitFor(student, `(() => { const g = document.getElementById("serve-grade");
  return g.querySelector("a") ? g.textContent : ""; })()`, "show the grade", 180);
seen.feedbackHref = await student.evaluate(`document.querySelector("#serve-grade a").getAttribute("href")`);

// The teacher's page: the student in the grid, graded; follow me.
const teacher = await openPage(teacherLink);
await teacher.send("Page.navigate", { url: teacherLink });
seen.card = await waitFor(teacher, `(() => { const c = document.querySelector(".card .handin");
  return c && /pass|look|wrong|error/.test(c.textContent) ? c.textContent : ""; })()`, "show the graded student");
seen.studentsInGrid = await teacher.evaluate(`document.querySelectorAll(".card").length`);
seen.uAddBefore = await student.evaluate(`glimmerPage.value("uAdd")`);
await teacher.evaluate(`document.getElementById("follow-sets").value = "uAdd=1.75"; document.getElementById("follow").click()`);
seen.uAddAfter = await waitFor(student, `(() => { const v = glimmerPage.value("uAdd"); return Math.abs(parseFloat(v) - 1.75) < 1e-6 ? v : ""; })()`,
                               "follow the teacher's push", 20);
// A script pushed: the student's page shows it, at the pushed value.
await teacher.evaluate(`document.getElementById("follow-sets").value = "script=second.glib;uAdd=0.25"; document.getElementById("follow").click()`);
seen.pushedScript = await waitFor(student, `(() => { const v = document.getElementById("verdict").textContent;
  return v === "second.glib: drawn" && Math.abs(parseFloat(glimmerPage.value("uAdd")) - 0.25) < 1e-6 ? v : ""; })()`,
                                  "show the pushed script", 20);
console.log(JSON.stringify(seen));
await teacher.close(null);
student.close(0);
