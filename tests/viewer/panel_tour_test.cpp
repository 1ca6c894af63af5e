// The panel tour in the window (issue 39): every control of the panel, as
// tests/data/panel_tour.txt lists them, clicked, dragged or typed into with
// xdotool on the virtual X server, each found where `where NAME` says it is
// now, and its effect read back with `panel` (the picture's hash among it).
// The page takes the same tour in three browser engines
// (tools/page-engine.mjs --tour, tests/web/panel_tour.sh): one table, the
// same answers from the same core.
#include <chrono>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "common/test_folder.h"
#include "image/image.h"
#include "viewer_process.h"
#include "x11_driver.h"

namespace fs = std::filesystem;
using namespace glimmer_viewer;
using namespace std::chrono_literals;

namespace {

struct Step {
    int line = 0;
    std::string control, action, text;
    double at = 0.5;  // where along the control's width
    std::vector<std::string> expect;
};
struct Section {
    std::string script;
    std::vector<Step> steps;
};

std::string trim(std::string s) {
    s.erase(0, s.find_first_not_of(" \t"));
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.pop_back();
    return s;
}

std::vector<Section> readTour(const fs::path& path) {
    std::ifstream in(path);
    std::vector<Section> tour;
    std::string raw;
    for (int n = 1; std::getline(in, raw); ++n) {
        std::string line = trim(raw);
        if (line.empty() || line[0] == '#') continue;
        if (line.rfind("script ", 0) == 0) {
            tour.push_back({trim(line.substr(7)), {}});
            continue;
        }
        std::vector<std::string> parts;
        for (size_t at = 0;;) {
            size_t bar = line.find(" | ", at);
            parts.push_back(trim(line.substr(at, bar == std::string::npos ? std::string::npos : bar - at)));
            if (bar == std::string::npos) break;
            at = bar + 3;
        }
        if (parts.size() != 3 || tour.empty()) throw std::runtime_error(fmt::format("panel_tour.txt:{}: not a step", n));
        Step s;
        s.line = n;
        s.control = parts[0];
        std::string verb = parts[1].substr(0, parts[1].find(' '));
        s.text = parts[1].find(' ') == std::string::npos ? "" : trim(parts[1].substr(parts[1].find(' ') + 1));
        if (size_t atSign = verb.find('@'); atSign != std::string::npos) {
            s.at = std::stod(verb.substr(atSign + 1));
            verb.erase(atSign);
        }
        s.action = verb;
        std::istringstream words(parts[2]);
        for (std::string w; words >> w;) s.expect.push_back(w);
        tour.back().steps.push_back(s);
    }
    return tour;
}

// `panel`'s words as a map (the first of a repeated name).
std::map<std::string, std::string> parseState(const std::string& line) {
    std::map<std::string, std::string> out;
    std::istringstream words(line);
    for (std::string w; words >> w;)
        if (size_t eq = w.find('='); eq != std::string::npos) out.emplace(w.substr(0, eq), w.substr(eq + 1));
    return out;
}

std::set<fs::path> pngsIn(const fs::path& dir) {
    std::set<fs::path> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".png") out.insert(e.path());
    return out;
}

// A saved PNG's size, "WxH" ("?" when it does not load).
std::string pngSize(const fs::path& p) {
    glimmer::Image img;
    std::string why;
    return glimmer::loadImage(p.string(), img, why) ? fmt::format("{}x{}", img.width, img.height) : "?";
}

class WindowTour {
public:
    WindowTour(ViewerProcess& v, XViewer x, fs::path dir) : v_(v), x_(std::move(x)), dir_(std::move(dir)) {}

    // Sends `command` and waits for the viewer's next line that starts with
    // one of `answers` (after "glimmer view: "); "" on timeout.
    std::string ask(const std::string& command, const std::vector<std::string>& answers) {
        const size_t from = v_.log().size();
        v_.send(command);
        for (auto end = std::chrono::steady_clock::now() + 10s; std::chrono::steady_clock::now() < end;) {
            std::istringstream lines(v_.log().substr(from));
            for (std::string l; std::getline(lines, l);)
                for (const auto& a : answers)
                    if (l.rfind("glimmer view: " + a, 0) == 0) return l.substr(14);
            std::this_thread::sleep_for(50ms);
        }
        return "";
    }
    std::map<std::string, std::string> state() { return parseState(ask("panel", {"panel "})); }
    // A state whose picture hash is of a frame after this call.
    std::map<std::string, std::string> freshState() {
        state();
        std::this_thread::sleep_for(400ms);
        return state();
    }
    bool where(const std::string& name, double& x, double& y, double& w, double& h) {
        std::string said = ask("where " + name, {"where " + name + " at ", "where: no control"});
        std::istringstream in(said.rfind("where: ", 0) == 0 ? "" : said.substr(said.rfind(" at ") + 4));
        return bool(in >> x >> y >> w >> h);
    }
    void x(const std::string& args) { xdotool(x_, args); }

    // The step's action; "" or why it could not be done.
    std::string act(const Step& s) {
        double cx = 0, cy = 0, w = 0, h = 0;
        bool found = false;
        for (int attempt = 0; attempt < 20 && !found; ++attempt) {  // the first frames' panel may not be drawn yet
            found = where(s.control, cx, cy, w, h);
            if (!found) std::this_thread::sleep_for(250ms);
        }
        if (!found) return "no control '" + s.control + "' in the panel";
        const int px = int(cx + s.at * w), py = int(cy + h / 2);
        const std::string at = fmt::format("mousemove --window {} {} {} sleep 0.2 ", x_.window, px, py);
        if (s.action == "click") x(at + "click 1 sleep 0.3");
        else if (s.action == "rclick") x(at + "click 3 sleep 0.3");
        else if (s.action == "drag") {
            const int dx = std::stoi(s.text);
            std::string moves;
            for (int k = 1; k <= 8; ++k) moves += fmt::format("mousemove --window {} {} {} sleep 0.05 ", x_.window, px + dx * k / 8, py);
            x(at + "mousedown 1 sleep 0.2 " + moves + "sleep 0.2 mouseup 1 sleep 0.3");
        } else if (s.action == "type" || s.action == "write") {
            // Into the field, what it holds selected (Ctrl+A) so the text typed
            // replaces it. Each key held for a few frames: ImGui 1.86 reads
            // keys as held or not at each frame, and a press and release
            // between two frames of a slow picture would be lost.
            x(at + "click 1 sleep 0.3 keydown ctrl sleep 0.1 keydown a sleep 0.3 keyup a sleep 0.1 keyup ctrl sleep 0.2");
            x(fmt::format("type --delay 30 '{}'", s.text));
            if (s.action == "type") x("sleep 0.2 keydown Return sleep 0.3 keyup Return");
            std::this_thread::sleep_for(300ms);
        } else return "unknown action '" + s.action + "'";
        return "";
    }

    // Why `expect` does not hold after the step ("" when it does).
    std::string check(const std::string& e, const std::map<std::string, std::string>& before,
                      const std::map<std::string, std::string>& after, const std::set<fs::path>& pngsBefore) {
        auto value = [&](const std::map<std::string, std::string>& m, const std::string& k) {
            auto it = m.find(k);
            return it == m.end() ? std::string("(none)") : it->second;
        };
        if (e.rfind("shown:", 0) == 0 || e.rfind("gone:", 0) == 0) {
            const bool want = e[0] == 's';
            std::string name = e.substr(e.find(':') + 1);
            for (size_t at; (at = name.find("%20")) != std::string::npos;) name.replace(at, 3, " ");
            double a, b, c, d;
            return where(name, a, b, c, d) == want ? "" : (want ? "no control " : "still a control ") + name;
        }
        if (e.rfind("saved", 0) == 0) {
            std::set<fs::path> now = pngsIn(dir_);
            for (const auto& p : now)
                if (!pngsBefore.count(p)) {
                    if (e.size() > 6 && pngSize(p) != e.substr(6)) return "saved " + p.filename().string() + " at " + pngSize(p);
                    return "";
                }
            return "no new PNG";
        }
        if (e.back() == '^') {
            const std::string k = e.substr(0, e.size() - 1);
            return value(before, k) != value(after, k) ? "" : k + " still " + value(after, k);
        }
        for (const char* op : {"~", "="}) {
            size_t at = e.find(op);
            if (at == std::string::npos) continue;
            const std::string k = e.substr(0, at), want = e.substr(at + 1), got = value(after, k);
            if (*op == '~') return got.find(want) != std::string::npos ? "" : k + "=" + got;
            if (size_t pm = want.find("+-"); pm != std::string::npos) {
                try {
                    return std::abs(std::stod(got) - std::stod(want.substr(0, pm))) <= std::stod(want.substr(pm + 2)) ? "" : k + "=" + got;
                } catch (...) {
                    return k + "=" + got;
                }
            }
            return got == want ? "" : k + "=" + got;
        }
        return "cannot read the expectation '" + e + "'";
    }

private:
    ViewerProcess& v_;
    XViewer x_;
    fs::path dir_;
};

TEST(PanelTour, EveryControlOfThePanelClickedInTheWindowDoesWhatTheTableSays) {
    const auto tour = readTour(fs::path(GLIMMER_SOURCE_DIR) / "tests/data/panel_tour.txt");
    ASSERT_FALSE(tour.empty());
    size_t steps = 0;
    for (const auto& section : tour) {
        glimmer::testing::TestFolder dir("glimmer_panel_tour_");  // Save PNG writes here
        ViewerProcess v({(fs::path(GLIMMER_SOURCE_DIR) / section.script).string()}, dir.path);
        ASSERT_TRUE(v.waitForLog("glimmer view: ui scale")) << v.log();
        auto x = findViewer(dir.path);
        ASSERT_TRUE(x) << v.log();
        WindowTour t(v, *x, dir.path);
        for (const Step& s : section.steps) {
            SCOPED_TRACE(fmt::format("panel_tour.txt:{}: {} | {} {}", s.line, s.control, s.action, s.text));
            const auto before = t.freshState();
            const auto pngs = pngsIn(dir.path);
            ASSERT_EQ(t.act(s), "");
            // The effect may take a few frames (a picture drawn in slices).
            std::vector<std::string> failed;
            for (auto end = std::chrono::steady_clock::now() + 10s;;) {
                std::this_thread::sleep_for(300ms);
                const auto after = t.state();
                failed.clear();
                for (const auto& e : s.expect)
                    if (std::string why = t.check(e, before, after, pngs); !why.empty()) failed.push_back(e + ": " + why);
                if (failed.empty() || std::chrono::steady_clock::now() > end) break;
            }
            for (const auto& f : failed) ADD_FAILURE() << f;
            if (!failed.empty()) {  // what the viewer said about it, less the tour's own questions
                std::istringstream lines(v.log());
                std::string said;
                for (std::string l; std::getline(lines, l);)
                    if (l.rfind("glimmer view: panel ", 0) != 0 && l.rfind("glimmer view: where ", 0) != 0) said += l + "\n";
                ADD_FAILURE() << "the viewer's last lines:\n" << said.substr(said.size() > 1500 ? said.size() - 1500 : 0);
            }
            ++steps;
        }
        EXPECT_EQ(v.quit(), 0) << v.log();
    }
    EXPECT_GE(steps, 50u);
}

}  // namespace
