#include "plan/uniform_values.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "util/numbers.h"

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

bool UniformValues::applySet(const Plan& plan, const std::string& assignment, Diagnostics& diags,
                             const std::string& option) {
    auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) {
        diags.error(option, {}, fmt::format("'{}' is not of the form name=value", assignment));
        return false;
    }
    std::string name = assignment.substr(0, eq), text = assignment.substr(eq + 1);
    // One number (or true/false), or several separated by commas: a colour
    // "1,0,0,1" or a vector.
    std::vector<double> numbers;
    size_t start = 0;
    for (;;) {
        size_t comma = text.find(',', start);
        std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        std::string lowered = part;
        for (auto& ch : lowered) ch = char(std::tolower(static_cast<unsigned char>(ch)));
        double value = 0;
        if (lowered == "true" || lowered == "false") {
            value = lowered == "true" ? 1 : 0;
        } else {
            auto [end, ec] = parseDouble(part.data(), part.data() + part.size(), value);
            if (ec != std::errc() || end != part.data() + part.size() || !std::isfinite(value)) {
                diags.error(option, {}, fmt::format("'{}' in {} {} is not a number", part, option, assignment));
                return false;
            }
        }
        numbers.push_back(value);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    const double value = numbers[0];
    bool found = false, ok = true;
    for (size_t p = 0; p < plan.programs.size(); ++p) {
        for (const auto& u : plan.programs[p].uniforms) {
            if (u.name != name) continue;
            found = true;
            auto wrongCount = [&](const std::string& wants) {
                diags.error(plan.scriptFile, u.loc,
                            fmt::format("{} {}: uniform '{}' of Program {} {}", option, assignment, name,
                                        plan.programs[p].name, wants));
                ok = false;
            };
            if (u.form == UniformSetting::Form::Range) {
                if (numbers.size() != 1) {
                    wrongCount("is a range and takes one number");
                    continue;
                }
                if (value < u.min || value > u.max) {
                    diags.error(plan.scriptFile, u.loc,
                                fmt::format("{} {}={} is outside the range <{} {}> of uniform '{}' in Program {}",
                                            option, name, text, u.min, u.max, name, plan.programs[p].name));
                    ok = false;
                    continue;
                }
                values_[{int(p), name}] = {value};
            } else if (u.form == UniformSetting::Form::Bool) {
                if (numbers.size() != 1) {
                    wrongCount("is a checkbox and takes one value");
                    continue;
                }
                values_[{int(p), name}] = {value != 0 ? 1.0 : 0.0};
            } else if (u.form == UniformSetting::Form::Color) {
                if (numbers.size() != 3 && numbers.size() != 4) {
                    wrongCount("is a colour and takes R,G,B or R,G,B,A");
                    continue;
                }
                std::vector<double> rgba = numbers;
                if (rgba.size() == 3) rgba.push_back(u.values.size() > 3 ? u.values[3] : 1.0);
                values_[{int(p), name}] = rgba;
            } else if (u.form == UniformSetting::Form::Array) {
                if (numbers.size() != u.values.size()) {
                    wrongCount(fmt::format("is a vector of {} and takes {} numbers separated by commas",
                                           u.values.size(), u.values.size()));
                    continue;
                }
                values_[{int(p), name}] = numbers;
            } else {
                diags.error(plan.scriptFile, u.loc,
                            fmt::format("{} {}: uniform '{}' of Program {} is a constant (a texture unit or a fixed "
                                        "number), not a range, checkbox, colour or vector",
                                        option, name, name, plan.programs[p].name));
                ok = false;
            }
        }
    }
    if (!found) {
        diags.error(option, {}, fmt::format("no Program sets a uniform named '{}'", name));
        return false;
    }
    return ok;
}

}  // namespace glimmer
