// The page's presentation mode, for a projector: made by glimmer-page.js
// once the canvas and the viewer's command (glimmerPage.command's) exist.
// `isLive()`: whether a script is on show (nothing to fit otherwise).
"use strict";
const presentationMode = (canvas, viewCommand, isLive) => {
  // Presentation mode (the Present button, ?present): the picture and its
  // panel at a larger `scale` (the window's command, web_view.cpp), as large
  // as the window's height allows, for a projector; the editor and most of
  // the toolbar hidden (index.html's body.present). Its factor is on top of
  // devicePixelRatio's; refitted when the window is resized.
  const presentButton = document.getElementById("present");
  let presentFactor = 1;
  const dprScale = () => Math.min(4, Math.max(0.5, window.devicePixelRatio || 1));
  const fitPresentation = () => {
    if (!document.body.classList.contains("present") || !isLive()) return;
    const box = canvas.getBoundingClientRect();
    if (!box.width || !box.height) return;
    // The canvas's size at factor 1, then the largest factor that fits.
    const baseW = box.width / presentFactor, baseH = box.height / presentFactor;
    const fits = Math.min((window.innerHeight - box.top - 8) / baseH, (document.documentElement.clientWidth - 32) / baseW,
                          4 / dprScale());
    const factor = Math.max(1, Math.floor(fits * 20) / 20);
    if (Math.abs(factor - presentFactor) < 0.01) return;
    presentFactor = factor;
    viewCommand("scale " + Math.min(4, dprScale() * factor).toFixed(3).replace(/\.?0+$/, ""));
  };
  const present = (on) => {
    document.body.classList.toggle("present", on);
    presentButton.textContent = on ? "Leave presentation" : "Present";
    if (!on && presentFactor !== 1) { presentFactor = 1; viewCommand("scale " + dprScale()); }
    // Fitted now, and again once the panel has settled at its new size.
    if (on) { fitPresentation(); setTimeout(fitPresentation, 300); setTimeout(fitPresentation, 900); }
  };
  presentButton.onclick = () => present(!document.body.classList.contains("present"));
  window.addEventListener("resize", () => fitPresentation());
  document.addEventListener("keydown", (e) => {
    if (e.key === "Escape" && document.body.classList.contains("present") && e.target !== canvas) present(false);
  });
  return { present, factor: () => presentFactor };
};
