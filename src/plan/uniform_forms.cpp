#include "plan/uniform_forms.h"

#include <fmt/format.h>

namespace glimmer {
namespace {

std::string itemsText(const Arg& a) {
    std::string s;
    for (const auto& i : a.items) s += (s.empty() ? "" : " ") + i.text;
    return s;
}

bool allNumbers(const Arg& group, const std::string& name, const std::string& file, Diagnostics& diags) {
    for (const auto& i : group.items) {
        if (i.kind != Arg::Kind::Number) {
            diags.error(file, i.loc, fmt::format("uniform '{}': '{}' is not a number", name, i.text));
            return false;
        }
    }
    return true;
}

// `<...>` is a slider when it holds three numbers and a checkbox when it
// holds one truth value.
bool readRange(const Arg& a, UniformSetting& u, const std::string& file, Diagnostics& diags) {
    if (a.items.size() == 1) {
        const Arg& v = a.items[0];
        std::string word = v.text;
        for (auto& ch : word) ch = char(std::tolower(static_cast<unsigned char>(ch)));
        if (v.kind == Arg::Kind::Word && (word == "true" || word == "false")) {
            u.form = UniformSetting::Form::Bool;
            u.values = {word == "true" ? 1.0 : 0.0};
            return true;
        }
        if (v.kind == Arg::Kind::Number && (v.number == 0 || v.number == 1)) {
            u.form = UniformSetting::Form::Bool;
            u.values = {v.number};
            return true;
        }
        diags.error(file, a.loc, fmt::format("uniform '{}': <{}> is neither a range <min current max> "
                                             "nor a checkbox <true>/<false>", u.name, v.text));
        return false;
    }
    if (a.items.size() != 3) {
        std::string hint = a.items.size() == 4 ? "; commas separate values, so write decimals with a point" : "";
        diags.error(file, a.loc, fmt::format("uniform '{}': a range needs 3 values <min current max>, got {} <{}>{}",
                                             u.name, a.items.size(), itemsText(a), hint));
        return false;
    }
    if (!allNumbers(a, u.name, file, diags)) return false;
    double lo = a.items[0].number, cur = a.items[1].number, hi = a.items[2].number;
    if (!(lo <= cur && cur <= hi)) {
        diags.error(file, a.loc, fmt::format("uniform '{}': range <{}> needs min <= current <= max", u.name,
                                             itemsText(a)));
        return false;
    }
    u.form = UniformSetting::Form::Range;
    u.min = lo;
    u.max = hi;
    u.values = {cur};
    return true;
}

}  // namespace

std::vector<UniformSetting> parseUniformSettings(const Command& c, size_t first, const std::string& file,
                                                 Diagnostics& diags) {
    std::vector<UniformSetting> out;
    for (size_t i = first; i < c.args.size(); ++i) {
        const Arg& nameArg = c.args[i];
        if (nameArg.kind != Arg::Kind::Word) {
            diags.error(file, nameArg.loc, fmt::format("expected a uniform name, found '{}'",
                                                       nameArg.isGroup() ? itemsText(nameArg) : nameArg.text));
            continue;
        }
        UniformSetting u;
        u.name = nameArg.text;
        u.loc = nameArg.loc;
        if (i + 1 >= c.args.size() || c.args[i + 1].kind == Arg::Kind::Word) {
            diags.error(file, nameArg.loc, fmt::format("uniform '{}' has no value", u.name));
            continue;
        }
        const Arg& v = c.args[++i];
        bool ok = true;
        switch (v.kind) {
        case Arg::Kind::Range: ok = readRange(v, u, file, diags); break;
        case Arg::Kind::Color:
            ok = allNumbers(v, u.name, file, diags);
            if (ok && (v.items.size() < 3 || v.items.size() > 4)) {
                diags.error(file, v.loc, fmt::format("uniform '{}': a colour needs {{r g b}} or {{r g b a}}, got {} values",
                                                     u.name, v.items.size()));
                ok = false;
            }
            if (ok) {
                u.form = UniformSetting::Form::Color;
                for (const auto& it : v.items) u.values.push_back(it.number);
                if (u.values.size() == 3) u.values.push_back(1.0);
            }
            break;
        case Arg::Kind::Array:
            ok = allNumbers(v, u.name, file, diags);
            if (ok) {
                u.form = UniformSetting::Form::Array;
                for (const auto& it : v.items) u.values.push_back(it.number);
            }
            break;
        case Arg::Kind::Number:
            u.form = UniformSetting::Form::Constant;
            u.values = {v.number};
            break;
        case Arg::Kind::Word: break;  // handled above
        }
        if (ok) out.push_back(std::move(u));
    }
    return out;
}

}  // namespace glimmer
