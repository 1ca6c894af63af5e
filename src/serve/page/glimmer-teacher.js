// The teacher's page of `glimmer serve` (/teacher): every student in a grid,
// refreshed every two seconds from /api/class: their picture as last sent,
// their page's verdict line at their last save, their hand-ins and grade; a
// link to their work (read-only) and their feedback. "Push to the class"
// sends slider values (and script=PATH, the script to show) every student's
// page applies once (follow me).
"use strict";
(() => {
  const grid = document.getElementById("grid");
  const text = (tag, content, cls) => {
    const e = document.createElement(tag);
    e.textContent = content;
    if (cls) e.className = cls;
    return e;
  };
  const link = (href, label) => { const a = text("a", label); a.href = href; a.target = "_blank"; a.rel = "noopener"; return a; };
  const ago = (now, t) => !t ? "never saved" : now - t < 60 ? Math.round(now - t) + " s ago" : Math.round((now - t) / 60) + " min ago";
  document.getElementById("qr").src = "/api/qr.svg";
  const cards = new Map();
  const card = (s, now) => {
    let c = cards.get(s.id);
    if (!c) {
      c = document.createElement("div");
      c.className = "card";
      c.dataset.student = s.folder;
      cards.set(s.id, c);
      grid.appendChild(c);
    }
    c.replaceChildren();
    const img = s.thumbnail ? document.createElement("img") : text("div", "", "none");
    if (s.thumbnail) { img.src = "/api/thumbnail/" + s.id + "?v=" + s.versions + "-" + Math.floor(now / 15); img.alt = s.name; }
    c.append(img, text("div", s.name, "name"));
    c.append(text("div", s.versions + " versions, " + ago(now, s.lastSave)));
    c.append(text("div", s.status || "", "status" + (/error/.test(s.status) ? " bad" : "")));
    const h = s.last;
    const handIn = text("div", !h ? "not handed in" : h.state === "graded" ? `hand-in ${s.handins}: ${h.verdict}, ${h.score}` : `hand-in ${s.handins}: ${h.state}`,
                        h && h.state === "graded" ? (h.verdict === "pass" ? "ok" : "bad") : "");
    handIn.className += " handin";
    c.append(handIn);
    const links = document.createElement("div");
    links.append(link("/teacher/work/" + s.id, "work"));
    if (h && h.feedback) links.append(" · ", link("/api/feedback/" + h.id, "feedback"));
    links.append(" · ", link(s.link, "their link"));
    c.append(links);
    c.classList.toggle("stale", !s.lastSave || now - s.lastSave > 300);
  };
  const refresh = async () => {
    try {
      const r = await fetch("/api/class", { credentials: "same-origin" });
      if (!r.ok) return;
      const k = await r.json();
      const join = document.getElementById("join");
      join.replaceChildren(text("div", "Students join at"), text("code", k.address));
      if (k.code) join.append(text("div", "class code"), text("code", k.code));
      let graded = 0, handed = 0;
      for (const s of k.students) { card(s, k.now); if (s.last) { ++handed; if (s.last.state === "graded") ++graded; } }
      document.getElementById("counts").textContent = `${k.students.length} students, ${handed} handed in, ${graded} graded`;
      document.body.dataset.students = k.students.length;
    } catch {}
  };
  document.getElementById("follow").onclick = async () => {
    const sets = document.getElementById("follow-sets").value;
    const r = await fetch("/api/follow", { method: "POST", headers: { "Content-Type": "application/json" },
                                           body: JSON.stringify({ sets }), credentials: "same-origin" });
    document.getElementById("follow-said").textContent = r.ok ? "pushed: " + sets : "not pushed: " + r.status;
  };
  setInterval(refresh, 2000);
  refresh();
})();
