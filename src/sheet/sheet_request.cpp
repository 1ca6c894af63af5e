#include "sheet/sheet_request.h"

#include <set>

#include <fmt/format.h>

namespace glimmer {

bool makeSheetRequest(const std::vector<std::string>& vary, const std::string& scriptName, const Plan& plan,
                      const UniformValues& values, SheetRequest& out, std::string& usage, Diagnostics& diags) {
    usage.clear();
    std::vector<SheetAxis> axes;
    for (const std::string& text : vary) {
        SheetAxis a;
        const size_t start = text.find_first_not_of(' ');  // the page's "a; b" leaves a space
        if (!parseSheetAxis(start == std::string::npos ? text : text.substr(start), a)) {
            usage = fmt::format("--vary '{}' is not NAME=V1,V2,...", text);
            return false;
        }
        axes.push_back(a);
    }
    if (axes.empty()) {
        usage = "a sheet varies one or two uniforms: --vary NAME=V1,V2,... (columns), a second for rows";
        return false;
    }
    if (axes.size() > 2) {
        usage = "--vary can be given at most twice (columns, then rows)";
        return false;
    }
    out.cols = axes[0];
    out.rows = axes.size() > 1 ? axes[1] : SheetAxis{};
    if (!checkSheetValues(plan, values, out.cols, out.rows, diags)) return false;

    out.title = scriptName;
    const UniformValues own(plan);  // the script's own values
    std::set<std::string> named = {out.cols.name, out.rows.name};
    for (size_t p = 0; p < plan.programs.size(); ++p)
        for (const auto& u : plan.programs[p].uniforms) {
            if (u.form == UniformSetting::Form::Constant || !named.insert(u.name).second) continue;
            const std::vector<double>& now = values.get(int(p), u.name);
            if (now == own.get(int(p), u.name)) {
                named.erase(u.name);  // another Program's uniform of this name may differ
                continue;
            }
            std::string text;
            for (double x : now) text += (text.empty() ? "" : ",") + fmt::format("{:g}", x);
            out.title += "   " + u.name + " = " + text;
        }
    return true;
}

}  // namespace glimmer
