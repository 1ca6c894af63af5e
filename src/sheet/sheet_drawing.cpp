#include "sheet/sheet_drawing.h"

#include <algorithm>
#include <sstream>

#include "sheet/sheet_layout.h"
#include "plan/dependencies.h"

namespace glimmer {
namespace {

void blit(Image& sheet, const Image& cell, int x0, int y0) {
    for (int y = 0; y < cell.height && y0 + y < sheet.height; ++y)
        std::copy_n(&cell.u8[size_t(y) * size_t(cell.width) * 4], size_t(cell.width) * 4,
                    &sheet.u8[(size_t(y0 + y) * size_t(sheet.width) + size_t(x0)) * 4]);
}

}  // namespace

bool parseSheetAxis(const std::string& text, SheetAxis& a) {
    auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 >= text.size()) return false;
    a.name = text.substr(0, eq);
    std::stringstream ss(text.substr(eq + 1));
    for (std::string v; std::getline(ss, v, ',');)
        if (!v.empty()) a.values.push_back(v);
    return !a.values.empty();
}

bool checkSheetValues(const Plan& plan, const UniformValues& base, const SheetAxis& cols, const SheetAxis& rows,
                      Diagnostics& diags) {
    for (const SheetAxis* a : {&cols, &rows}) {
        if (a->name.empty()) continue;
        for (const auto& v : a->values) {
            UniformValues probe = base;
            if (!probe.applySet(plan, a->name + "=" + v, diags, "--vary") || diags.warningCount() > 0) return false;
        }
    }
    return true;
}

Image drawSheet(Renderer& renderer, const Plan& plan, const UniformValues& base, const SheetAxis& cols,
                const SheetAxis& rows, const std::string& title, const std::function<void(int, int)>& progress) {
    std::vector<std::string> rowValues;
    if (!rows.name.empty()) rowValues = rows.values;
    SheetLayout layout = layoutSheet(title, cols.name, cols.values, rows.name, rowValues, plan.width, plan.height);
    Image sheet = Image::rgba8(layout.width, layout.height);
    for (size_t i = 0; i < sheet.u8.size(); ++i) sheet.u8[i] = (i % 4 == 3) ? 255 : 24;
    drawSheetLabels(sheet, layout);

    const std::vector<std::string> one = {""};
    const std::vector<std::string>& rowsDrawn = rows.name.empty() ? one : rows.values;
    UniformValues drawn = base;
    bool first = true;
    int done = 0, total = int(cols.values.size() * rowsDrawn.size());
    for (size_t r = 0; r < rowsDrawn.size(); ++r) {
        for (size_t c = 0; c < cols.values.size(); ++c) {
            UniformValues v = base;
            Diagnostics d;
            v.applySet(plan, cols.name + "=" + cols.values[c], d, "--vary");
            if (!rows.name.empty()) v.applySet(plan, rows.name + "=" + rows.values[r], d, "--vary");
            Change change;
            change.everything = first;
            change.programs = v.programsDifferingFrom(drawn);
            std::vector<bool> only = passesToRun(plan, change);
            renderer.render(v, 0, nullptr, &only);
            drawn = v;
            first = false;
            auto [x, y] = layout.cellOrigin(int(c), int(r));
            blit(sheet, renderer.readScreen(), x, y);
            if (progress) progress(++done, total);
        }
    }
    return sheet;
}

}  // namespace glimmer
