#include "view/viewer_core.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "gl/ui_texture.h"
#include "gl/window_frame.h"
#include "image/ttf_text.h"
#include "plan/dependencies.h"
#include "view/panel.h"

namespace glimmer {

double sliceBudgetMs() {
    const char* e = std::getenv("GLIMMER_SLICE_MS");
    if (!e || !*e) return kSliceMs;
    char* end = nullptr;
    double v = std::strtod(e, &end);
    if (end == e || *end || !(v >= 0) || v > 1e6) return kSliceMs;
    return v == 0 ? std::numeric_limits<double>::infinity() : v;
}

ViewerCore::ViewerCore(ViewerSource source, GetProcAddress getProc)
    : source_(std::move(source)), getProc_(std::move(getProc)) {}

ViewerCore::~ViewerCore() = default;

void ViewerCore::releaseGl() {
    drawing_.reset();
    s_.renderer.reset();
    valuesTexture_.reset();
    windowFrame_.reset();
    valuesId_ = 0;
    valuesUploaded_.clear();
}

bool ViewerCore::prepareAt(int w, int h, LoadedScript& next, std::unique_ptr<Renderer>& renderer,
                           Diagnostics& diags) {
    ScriptRequest request;
    request.script = source_.script;
    request.plan.includeDirs = source_.includeDirs;
    request.plan.standIns = source_.standIns;
    request.plan.sandbox = source_.sandbox;
    request.plan.width = w;
    request.plan.height = h;
    // Every target can be looked at in the pass inspector, so every pass
    // that draws into one runs, read by a later pass or not.
    for (int unit = 0; unit < 32; ++unit) request.plan.keepTargets.insert(unit);
    renderer = prepareScript(request, getProc_, diags, next);
    return renderer != nullptr;
}

bool ViewerCore::load(int w, int h, Diagnostics& diags, SourceTexts& sources, Plan* plan, const std::string& why) {
    LoadedScript next;
    std::unique_ptr<Renderer> renderer;
    ++loads_;
    prepareAt(w, h, next, renderer, diags);
    keepMessages(s_, diags, next.sources);
    if (source_.oneLineMessages)
        for (auto* list : {&s_.errors, &s_.warnings})
            for (auto& m : *list) m.text = m.text.substr(0, m.text.find('\n'));
    sources = next.sources;
    noteFiles(next.plan);
    if (plan) *plan = next.plan;
    if (!renderer) {
        if (s_.errors.empty()) s_.errors.push_back({"the script could not be loaded", source_.script});
        s_.failed = true;
        s_.status = why + " failed; keeping the last good picture";
        return false;
    }
    s_.status = why;
    adoptScript(s_, std::move(next), std::move(renderer), source_.sets, diags);
    drawing_.reset();  // its passes belong to the old plan
    firstFrame_ = true;
    // The targets' health (noteHealth) is read back half a second after a
    // load, not in its first frames: every float target read back at once
    // waited for the whole picture on the GPU before it was shown (issue
    // 39: 7 read-backs in the page's first frames in Chromium).
    lastHealth_ = Clock::now();
    std::string said;
    if (s_.watch) startWatchNow(said);  // the edited shader, watched again
    return true;
}

bool ViewerCore::draw(double budgetMs) {
    // A script's first picture is drawn whole: until it is, its targets and
    // screen hold nothing to show (a reload is one pause, not a drag).
    if (firstFrame_) {
        budgetMs = std::numeric_limits<double>::infinity();
        firstFrame_ = false;
    }
    if (!s_.renderer || !s_.good) return false;
    if (s_.watch) return drawWatchFrame();
    const Plan& plan = s_.good->plan;
    Change change = changeSinceDrawn(s_, false);
    // Time alone never replaces a frame under way: a heavy animated scene
    // would otherwise restart every window frame and never finish one.
    if (s_.time != s_.drawnTime && (!drawing_ || !change.programs.empty() || change.screen || change.everything))
        change = changeSinceDrawn(s_, true);
    s_.sceneMoved = false;
    std::vector<bool> only = passesToRun(plan, change);
    bool any = false;
    for (size_t p = 0; p < only.size(); ++p)
        if (only[p]) any = true, drawnPasses_.insert(int(p));
    if (any) {
        if (drawing_) {  // the stale work is dropped, never half kept; what it had not finished is redone
            std::vector<bool> left = drawing_->unfinished();
            for (size_t p = 0; p < only.size() && p < left.size(); ++p) only[p] = only[p] || left[p];
        }
        s_.renderer->setSceneTransform(sceneMatrix(s_));
        drawing_.emplace(s_.renderer->startFrame(*s_.values, s_.time, std::move(only)));
        drawingSince_ = Clock::now();
        slices_ = 0;
        s_.drawnWith = s_.values;
        s_.drawnTime = s_.time;
        s_.drawAll = false;
    }
    if (!drawing_) return false;
    ++slices_;
    if (!s_.renderer->renderSlice(*drawing_, budgetMs)) {
        s_.drawing = float(s_.renderer->progress(*drawing_));
        return false;
    }
    s_.drawing = -1;
    s_.lastTimings = drawing_->timings;
    s_.lastFrameMs = 0;
    for (const auto& t : s_.lastTimings) s_.lastFrameMs += t.ms;
    lastPictureMs_ = std::chrono::duration<double, std::milli>(Clock::now() - drawingSince_).count();
    lastPictureSlices_ = slices_;
    drawing_.reset();
    ++pictureVersion_;
    return true;
}

Image ViewerCore::finishedPicture() {
    if (!s_.renderer || !s_.good) return {};
    draw(std::numeric_limits<double>::infinity());
    if (s_.watch) return s_.renderer->readWatchPicture();
    return s_.shownTexture < 0 ? s_.renderer->readScreen() : s_.renderer->readTexture(s_.shownTexture);
}

Image ViewerCore::renderAtSize(int w, int h) {
    if (!s_.good || w < 1 || h < 1 || w > 16384 || h > 16384) return {};
    Diagnostics diags;
    LoadedScript ls;
    std::unique_ptr<Renderer> r;
    if (!prepareAt(w, h, ls, r, diags)) return {};
    UniformValues v(ls.plan);
    v.carryOver(s_.good->plan, *s_.values, ls.plan);
    r->setSceneTransform(sceneMatrix(s_));
    r->render(v, s_.time);
    return r->readScreen();
}

Image ViewerCore::savedPicture(bool hardcopy) {
    Image img = hardcopy ? renderAtSize(s_.hardcopy[0], s_.hardcopy[1]) : finishedPicture();
    if (!img.empty() && s_.showValues) layOver(img, valuesLayer(), kOverlayAt, kOverlayAt);
    return img;
}

const Image& ViewerCore::valuesLayer() {
    const float px = kPanelFontPx * uiScale_;
    std::string text = overlayText(s_);
    std::string key = fmt::format("{}|{}", px, text);
    if (key != valuesMadeFor_) {
        valuesLayer_ = text.empty() ? Image{} : labelLayer(text, px);
        valuesMadeFor_ = key;
    }
    return valuesLayer_;
}

void ViewerCore::drawValues() {
    if (!s_.showValues) return;
    const Image& layer = valuesLayer();
    if (layer.empty()) return;
    if (!valuesTexture_) {
        std::string why;
        valuesTexture_ = UiTexture::create(getProc_, why);
        if (!valuesTexture_) return;
    }
    if (valuesUploaded_ != valuesMadeFor_) {
        valuesId_ = valuesTexture_->upload(layer);
        valuesUploaded_ = valuesMadeFor_;
    }
    if (!valuesId_) return;
    // The picture's top left is the window's: the same offset as in a saved PNG.
    ImGui::GetForegroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(valuesId_)),
                                             ImVec2(kOverlayAt, kOverlayAt),
                                             ImVec2(float(kOverlayAt + layer.width), float(kOverlayAt + layer.height)));
}

const Image& ViewerCore::probeImage() {
    if (probeVersion_ != pictureVersion_ || probeTexture_ != s_.shownTexture) {
        probeImage_ = s_.shownTexture < 0 ? s_.renderer->readScreen() : s_.renderer->readTextureFloat(s_.shownTexture);
        probeVersion_ = pictureVersion_;
        probeTexture_ = s_.shownTexture;
    }
    return probeImage_;
}

std::string ViewerCore::probeTextAt(int ix, int iy) {
    if (s_.watch) {  // the watch's own floats, every component, not the picture's bytes
        const WatchStats& w = watchFrame_.stats;
        if (!watchFrame_.drawn || ix < 0 || iy < 0 || ix >= w.width || iy >= w.height) return "";
        WatchProbe& p = watchProbe_;
        if (p.x != ix || p.y != iy || p.version != pictureVersion_)
            p = {ix, iy, pictureVersion_, watchValueAt(*s_.renderer, ix, iy)};
        return fmt::format("({}, {}) of the watch: {} = {}", ix, iy, s_.watch->spec.expression, p.text);
    }
    const Image& img = probeImage();
    if (img.empty() || ix < 0 || iy < 0 || ix >= img.width || iy >= img.height) return "";
    size_t i = (size_t(iy) * size_t(img.width) + size_t(ix)) * 4;
    float v[4];
    for (int c = 0; c < 4; ++c) v[c] = img.type == Image::Type::F32 ? img.f32[i + size_t(c)] : img.u8[i + size_t(c)] / 255.f;
    return fmt::format("({}, {}) of {}: r {:.4g}  g {:.4g}  b {:.4g}  a {:.4g}", ix, iy,
                       s_.shownTexture < 0 ? std::string("screen") : fmt::format("texture {}", s_.shownTexture), v[0],
                       v[1], v[2], v[3]);
}

const std::string& ViewerCore::probe(double x, double y, int pw, int ph, bool tooltip) {
    s_.probeText.clear();
    if (!s_.probe || !s_.renderer || s_.compare || pw < 1 || ph < 1) return s_.probeText;
    int width = watchFrame_.stats.width, height = watchFrame_.stats.height;
    if (!s_.watch) {
        const Image& img = probeImage();
        width = img.width, height = img.height;
    }
    if (width < 1 || height < 1) return s_.probeText;
    double scale = std::min(double(pw) / width, double(ph) / height);
    double ox = (pw - width * scale) / 2, oy = (ph - height * scale) / 2;
    s_.probeText = probeTextAt(int(std::floor((x - ox) / scale)), int(std::floor((y - oy) / scale)));
    if (tooltip && !s_.probeText.empty()) {
        ImGui::BeginTooltip();
        ImGui::TextUnformatted(s_.probeText.c_str());
        ImGui::EndTooltip();
    }
    return s_.probeText;
}

void ViewerCore::noteFrame() {
    auto now = Clock::now();
    double ms = std::chrono::duration<double, std::milli>(now - lastUiFrame_).count();
    if (ms < 1000 && frameIntervals_.size() < 1000000) frameIntervals_.push_back(ms);
    lastUiFrame_ = now;
}

std::string ViewerCore::frameStats() {
    std::vector<double> d;
    d.swap(frameIntervals_);
    std::sort(d.begin(), d.end());
    auto at = [&](double q) { return d.empty() ? 0.0 : d[std::min(d.size() - 1, size_t(q * double(d.size())))]; };
    return fmt::format("frames: {} drawn, median {:.1f} ms, p95 {:.1f} ms, max {:.1f} ms; "
                       "last picture {:.1f} ms after its last change ({:.1f} ms drawing, {} slice{}){}\n",
                       d.size(), at(0.5), at(0.95), d.empty() ? 0.0 : d.back(), lastPictureMs_, s_.lastFrameMs,
                       lastPictureSlices_, lastPictureSlices_ == 1 ? "" : "s",
                       drawing_ ? "; a picture is being drawn" : "");
}

bool ViewerCore::textureOnUnit(const char* command, int unit, int& texture, std::string& said) const {
    if (unit < 0) return texture = -1, true;
    if (s_.good && s_.good->plan.finalUnits.count(unit)) return texture = s_.good->plan.finalUnits.at(unit), true;
    said = fmt::format("{}: no texture on unit {}", command, unit);
    return false;
}

bool ViewerCore::apply(const ViewCommand& c, std::string& said) {
    said.clear();
    switch (c.kind) {
    case ViewCommand::Kind::Set: {
        Diagnostics d;
        set(c.name + "=" + c.text, d);
        for (const auto& diag : d.all()) said += std::string(severityName(diag.severity)) + ": " + diag.message + "\n";
        if (!said.empty()) said.pop_back();
        return true;
    }
    case ViewCommand::Kind::Show: textureOnUnit("show", c.unit, s_.shownTexture, said); return true;
    case ViewCommand::Kind::Values: s_.showValues = c.on; return true;
    case ViewCommand::Kind::Probe:
        if (c.x >= 0) {  // a pixel of the finished picture, wherever the pointer is
            if (!s_.renderer || !s_.good) {
                said = "probe: nothing is shown yet";
                return true;
            }
            draw(std::numeric_limits<double>::infinity());
            said = probeTextAt(c.x, c.y);
            said = said.empty() ? fmt::format("probe: ({}, {}) is outside the picture", c.x, c.y) : "probe " + said;
        } else if (!c.report) s_.probe = c.on;
        else if (!s_.probe) said = "probe: off (probe on turns it on)";
        else if (s_.probeText.empty()) said = "probe: the pointer is not over the picture";
        else said = "probe " + s_.probeText;
        return true;
    case ViewCommand::Kind::Watch: applyWatch(c, said); return true;
    case ViewCommand::Kind::Where: {  // for a test or a script that clicks the panel as a person would
        auto it = s_.controlRects.find(c.name);
        said = it == s_.controlRects.end()
                   ? fmt::format("where: no control '{}' in the panel now", c.name)
                   : fmt::format("where {} at {:g} {:g} {:g} {:g}", c.name, it->second[0], it->second[1], it->second[2],
                                 it->second[3]);
        return true;
    }
    case ViewCommand::Kind::Panel:
        // The picture's hash is the last frame's that was asked for; the next frame hashes again.
        said = panelState(s_, watchRange_, loads_) + fmt::format(" picture={:016x}", pictureHash_);
        pictureHashWanted_ = true;
        return true;
    case ViewCommand::Kind::Split:
        if (c.on && textureOnUnit("split", c.unit, s_.compareLeft, said) &&
            textureOnUnit("split", c.right, s_.compareRight, said))
            s_.compare = true;
        else if (!c.on) s_.compare = false;
        return true;
    default: return false;
    }
}

std::set<int> ViewerCore::takeDrawnPasses() {
    std::set<int> out;
    out.swap(drawnPasses_);
    return out;
}

void ViewerCore::applyWatch(const ViewCommand& c, std::string& said) {
    if (c.name == "range") {
        WatchRange range;
        std::string why;
        if (c.text == "auto") watchRange_.reset();
        else if (parseWatchRange(c.text, range, why)) watchRange_ = range;
        else {
            said = "watch range: '" + c.text + "' is not LO,HI with LO less than HI (for example 0,1), or auto";
            return;
        }
        if (s_.watch) s_.watch->range = watchRange_;
        watchStale_ = true;
        draw(std::numeric_limits<double>::infinity());
        said = s_.watch ? "watch " + s_.watchSummary : "watch range set; it applies to the next watch";
        return;
    }
    if (c.text == "off") {
        s_.watch.reset();
        s_.watchSummary.clear();
        if (s_.renderer) s_.renderer->dropWatch();
        s_.drawAll = true;  // the watched pass drew into the watch's targets, not its own
        said = "watch: off";
        return;
    }
    s_.watchSpec = c.text;
    startWatchNow(said);
}

bool ViewerCore::startWatchNow(std::string& said) {
    WatchSpec spec;
    std::string why;
    s_.watch.reset();
    s_.watchError.clear();
    if (!parseWatchSpec(s_.watchSpec, spec, why)) {
        s_.watchError = said = "watch: " + why;
        s_.drawAll = true;
        return false;
    }
    if (!s_.renderer || !s_.good) {
        s_.watchError = said = "watch: no script is shown";
        return false;
    }
    Diagnostics diags;
    Watch watch;
    if (!startWatch(spec, s_.good->plan, *s_.renderer, diags, watch)) {
        for (const auto& d : diags.all()) s_.watchError += formatDiagnostic(d, s_.good->sources);
        while (!s_.watchError.empty() && s_.watchError.back() == '\n') s_.watchError.pop_back();
        said = s_.watchError;
        s_.drawAll = true;
        return false;
    }
    watch.range = watchRange_;
    s_.watch = std::move(watch);
    drawing_.reset();  // a frame of the picture under way is dropped: the watch is shown now
    watchStale_ = true;
    draw(std::numeric_limits<double>::infinity());
    said = "watch " + watchTitle(*s_.watch, s_.good->plan) + ": " + s_.watchSummary;
    return true;
}

bool ViewerCore::drawWatchFrame() {
    Change change = changeSinceDrawn(s_, true);
    if (!watchStale_ && !change.everything && change.programs.empty() && !change.screen) return false;
    s_.renderer->setSceneTransform(sceneMatrix(s_));
    // Of the passes that feed the watched one, only those the change reaches
    // (a uAdd slider does not draw the blur again); all of them when the
    // watch is new, as a frame dropped for it may have left them half drawn.
    std::vector<bool> feeding = s_.watch->feeding;
    if (!watchStale_ && !change.everything) {
        const std::vector<bool> reached = passesToRun(s_.good->plan, change);
        for (size_t p = 0; p < feeding.size(); ++p) feeding[p] = feeding[p] && p < reached.size() && reached[p];
    }
    const auto start = Clock::now();
    watchFrame_ = drawWatch(*s_.renderer, *s_.watch, *s_.values, s_.time, &feeding);
    s_.watchSummary = watchFrame_.drawn ? watchSummary(watchFrame_.stats)
                                        : "the driver cannot draw into a float target (RGBA32F)";
    s_.drawnWith = s_.values;
    s_.drawnTime = s_.time;
    s_.sceneMoved = false;
    s_.drawAll = false;
    watchStale_ = false;
    lastPictureMs_ = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    lastPictureSlices_ = 1;
    s_.lastFrameMs = lastPictureMs_;  // the panel's frame line: what the watch took, drawn whole
    s_.lastTimings.clear();
    ++pictureVersion_;
    return true;
}

}  // namespace glimmer
