#include "view/view_commands.h"

#include <cmath>
#include <sstream>

#include "util/numbers.h"

namespace glimmer {

namespace {

bool toNumber(const std::string& s, double& v) {
    if (s == "true") return v = 1, true;
    if (s == "false") return v = 0, true;
    auto [end, ec] = parseDouble(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && end == s.data() + s.size();
}

// A texture unit (0 to 31) or "screen" (-1).
bool toUnit(const std::string& s, int& unit) {
    if (s == "screen") return unit = -1, true;
    double u = -1;
    if (!toNumber(s, u) || u < 0 || u > 31 || u != int(u)) return false;
    unit = int(u);
    return true;
}

bool toOnOff(const std::string& s, bool& on) {
    if (s != "on" && s != "off") return false;
    on = s == "on";
    return true;
}

}  // namespace

std::vector<std::string> splitCommands(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    for (std::string part; std::getline(ss, part, ';');) out.push_back(part);
    return out;
}

std::optional<ViewCommand> parseViewCommand(const std::string& line, std::string& error) {
    error.clear();
    std::istringstream in(line);
    std::string word;
    if (!(in >> word) || word[0] == '#') return std::nullopt;
    ViewCommand c;
    if (word == "watch") {
        // The rest of the line as written: an expression may hold spaces.
        std::string rest;
        std::getline(in, rest);
        rest.erase(0, rest.find_first_not_of(" \t"));
        while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t' || rest.back() == '\r')) rest.pop_back();
        c.kind = ViewCommand::Kind::Watch;
        if (rest.rfind("range ", 0) == 0) c.name = "range", rest.erase(0, 6);
        c.text = rest;
        if (rest.empty()) {
            error = "usage: watch FILE:LINE EXPRESSION, watch off, or watch range LO,HI|auto";
            return std::nullopt;
        }
        return c;
    }
    if (word == "where") {  // the rest of the line: a control's name may hold spaces ("Fix range")
        std::string rest;
        std::getline(in, rest);
        rest.erase(0, rest.find_first_not_of(" \t"));
        while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t' || rest.back() == '\r')) rest.pop_back();
        if (rest.empty()) {
            error = "usage: where CONTROL (a slider's uniform, Watch, Watch button, Stop, Fix range, Own range, Probe)";
            return std::nullopt;
        }
        c.kind = ViewCommand::Kind::Where;
        c.name = rest;
        return c;
    }
    std::vector<std::string> args;
    for (std::string a; in >> a;) args.push_back(a);
    auto want = [&](size_t n, const char* usage) {
        if (args.size() == n) return true;
        error = std::string("usage: ") + usage;
        return false;
    };
    if (word == "set") {
        if (!want(2, "set NAME VALUE")) return std::nullopt;
        c.kind = ViewCommand::Kind::Set;
        c.name = args[0];
        c.text = args[1];
        // A colour or a vector: numbers separated by commas.
        std::stringstream parts(args[1] + ",");
        bool firstPart = true;
        for (std::string part; std::getline(parts, part, ',');) {
            double v = 0;
            if (!toNumber(part, v)) {
                error = "set " + args[0] + ": '" + args[1] + "' is not a number (or numbers separated by commas)";
                return std::nullopt;
            }
            if (firstPart) c.value = v;
            firstPart = false;
        }
    } else if (word == "reload") {
        if (!want(0, "reload")) return std::nullopt;
        c.kind = ViewCommand::Kind::Reload;
    } else if (word == "save") {
        if (!want(1, "save FILE.png")) return std::nullopt;
        c.kind = ViewCommand::Kind::Save;
        c.name = args[0];
    } else if (word == "show") {
        if (!want(1, "show TARGET_UNIT|screen")) return std::nullopt;
        c.kind = ViewCommand::Kind::Show;
        if (!toUnit(args[0], c.unit)) {
            error = "show: '" + args[0] + "' is not a texture unit (0 to 31) or 'screen'";
            return std::nullopt;
        }
    } else if (word == "values") {
        if (!want(1, "values on|off") || !toOnOff(args[0], c.on)) {
            error = "usage: values on|off";
            return std::nullopt;
        }
        c.kind = ViewCommand::Kind::Values;
    } else if (word == "probe") {
        c.kind = ViewCommand::Kind::Probe;
        c.report = args.empty() || args.size() == 2;
        double x = -1, y = -1;
        bool ok = args.empty() || (args.size() == 1 && toOnOff(args[0], c.on)) ||
                  (args.size() == 2 && toNumber(args[0], x) && toNumber(args[1], y) && x >= 0 && y >= 0 &&
                   x < 16384 && y < 16384 && x == std::floor(x) && y == std::floor(y));
        if (!ok) {
            error = "usage: probe [on|off], or probe X Y (a pixel of the picture, top left 0 0)";
            return std::nullopt;
        }
        c.x = int(x), c.y = int(y);
    } else if (word == "split") {
        c.kind = ViewCommand::Kind::Split;
        if (args.size() == 1 && toOnOff(args[0], c.on) && !c.on) return c;
        if (args.size() != 2) {
            error = "usage: split LEFT_UNIT|screen RIGHT_UNIT|screen, or split off";
            return std::nullopt;
        }
        for (int i = 0; i < 2; ++i)
            if (!toUnit(args[size_t(i)], i == 0 ? c.unit : c.right)) {
                error = "split: '" + args[size_t(i)] + "' is not a texture unit (0 to 31) or 'screen'";
                return std::nullopt;
            }
    } else if (word == "scale") {
        if (!want(1, "scale 0.5..4")) return std::nullopt;
        c.kind = ViewCommand::Kind::Scale;
        if (!toNumber(args[0], c.value) || !(c.value >= 0.5 && c.value <= 4)) {
            error = "scale: '" + args[0] + "' is not a number from 0.5 to 4";
            return std::nullopt;
        }
    } else if (word == "help") {
        if (!want(0, "help")) return std::nullopt;
        c.kind = ViewCommand::Kind::Help;
    } else if (word == "panel") {
        if (!want(0, "panel")) return std::nullopt;
        c.kind = ViewCommand::Kind::Panel;
    } else if (word == "frames") {
        if (!want(0, "frames")) return std::nullopt;
        c.kind = ViewCommand::Kind::Frames;
    } else if (word == "quit") {
        if (!want(0, "quit")) return std::nullopt;
        c.kind = ViewCommand::Kind::Quit;
    } else {
        error = "unknown command '" + word + "' (set, reload, save, show, values, probe, split, watch, where, panel, scale, help, frames, quit)";
        return std::nullopt;
    }
    return c;
}

}  // namespace glimmer
