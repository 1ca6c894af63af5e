#include "plan/uniform_values.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace glimmer {

UniformValues::UniformValues(const Plan& plan) {
    for (size_t p = 0; p < plan.programs.size(); ++p)
        for (const auto& u : plan.programs[p].uniforms) values_[{int(p), u.name}] = u.values;
}

const std::vector<double>& UniformValues::get(int program, const std::string& name) const {
    static const std::vector<double> none;
    auto it = values_.find({program, name});
    return it == values_.end() ? none : it->second;
}

void UniformValues::carryOver(const Plan& before, const UniformValues& old, const Plan& now) {
    for (size_t p = 0; p < now.programs.size(); ++p) {
        for (const auto& u : now.programs[p].uniforms) {
            for (size_t q = 0; q < before.programs.size(); ++q) {
                if (before.programs[q].name != now.programs[p].name) continue;
                for (const auto& was : before.programs[q].uniforms) {
                    if (was.name != u.name || was.form != u.form) continue;
                    std::vector<double> v = old.get(int(q), u.name);
                    if (v.size() != u.values.size()) continue;
                    if (u.form == UniformSetting::Form::Range) v[0] = std::clamp(v[0], u.min, u.max);
                    values_[{int(p), u.name}] = v;
                }
            }
        }
    }
}

std::set<int> UniformValues::programsDifferingFrom(const UniformValues& other) const {
    std::set<int> out;
    for (const auto& [key, v] : values_)
        if (other.get(key.program, key.name) != v) out.insert(key.program);
    for (const auto& [key, v] : other.values_)
        if (get(key.program, key.name) != v) out.insert(key.program);
    return out;
}

bool UniformValues::applySet(const Plan& plan, const std::string& assignment, Diagnostics& diags) {
    auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) {
        diags.error("--set", {}, fmt::format("'{}' is not of the form name=value", assignment));
        return false;
    }
    std::string name = assignment.substr(0, eq), text = assignment.substr(eq + 1);
    double value = 0;
    std::string lowered = text;
    for (auto& ch : lowered) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    if (lowered == "true" || lowered == "false") {
        value = lowered == "true" ? 1 : 0;
    } else {
        auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
            diags.error("--set", {}, fmt::format("'{}' in --set {} is not a number", text, assignment));
            return false;
        }
    }
    bool found = false, ok = true;
    for (size_t p = 0; p < plan.programs.size(); ++p) {
        for (const auto& u : plan.programs[p].uniforms) {
            if (u.name != name) continue;
            found = true;
            if (u.form == UniformSetting::Form::Range) {
                if (value < u.min || value > u.max) {
                    diags.error(plan.scriptFile, u.loc,
                                fmt::format("--set {}={} is outside the range <{} {}> of uniform '{}' in Program {}",
                                            name, text, u.min, u.max, name, plan.programs[p].name));
                    ok = false;
                    continue;
                }
                values_[{int(p), name}] = {value};
            } else if (u.form == UniformSetting::Form::Bool) {
                values_[{int(p), name}] = {value != 0 ? 1.0 : 0.0};
            } else {
                diags.error(plan.scriptFile, u.loc,
                            fmt::format("--set {}: uniform '{}' of Program {} is not a range or a checkbox",
                                        name, name, plan.programs[p].name));
                ok = false;
            }
        }
    }
    if (!found) diags.warning("--set", {}, fmt::format("no Program sets a uniform named '{}'", name));
    return ok;
}

}  // namespace glimmer
