// The contact sheet's pictures: each cell the script drawn at one
// combination of the varied values, on one renderer, each cell re-running
// only the passes its change reaches (varying uAdd leaves the superblur as
// it is). `glimmer sheet` and the page's Save sheet both draw through here;
// where the labels go is sheet_layout.h.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "gl/renderer.h"
#include "image/image.h"
#include "plan/uniform_values.h"

namespace glimmer {

// One --vary: a uniform and its values, as the user wrote them.
struct SheetAxis {
    std::string name;
    std::vector<std::string> values;
};

// "NAME=V1,V2,..." -> an axis; false when it is not of that form.
bool parseSheetAxis(const std::string& text, SheetAxis& axis);

// Every value of both axes set on a copy of `base`: false, with the
// diagnostics (`option` names the source, "--vary"), when one cannot be.
// An axis with no name is the single row of a one-axis sheet.
bool checkSheetValues(const Plan& plan, const UniformValues& base, const SheetAxis& cols, const SheetAxis& rows,
                      Diagnostics& diags);

// The sheet: title, headers and cells. Draws on `renderer` (whose last
// picture it replaces); `progress(done, total)` after each cell.
Image drawSheet(Renderer& renderer, const Plan& plan, const UniformValues& base, const SheetAxis& cols,
                const SheetAxis& rows, const std::string& title,
                const std::function<void(int, int)>& progress = {});

}  // namespace glimmer
