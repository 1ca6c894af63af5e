// A contact sheet as asked for, built once for `glimmer sheet --vary ...`
// and the page's Save sheet (issue 38: each built it in its own words):
// one or two axes, every value checked against the script before anything
// is drawn, and the title line.
#pragma once
#include <string>
#include <vector>

#include "lang/diagnostics.h"
#include "plan/uniform_values.h"
#include "sheet/sheet_drawing.h"

namespace glimmer {

struct SheetRequest {
    SheetAxis cols, rows;  // rows has no name for a sheet of one row
    std::string title;
};

// `vary`: each NAME=V1,V2,... (columns, then rows). False when the request
// cannot be drawn: a usage error in `usage` (exit 2; "" otherwise) or the
// values' diagnostics in `diags`. The title is `scriptName` followed by
// every uniform that is not at the script's own value (what --set or the
// panel changed) and not varied, "   NAME = V1,V2".
bool makeSheetRequest(const std::vector<std::string>& vary, const std::string& scriptName, const Plan& plan,
                      const UniformValues& values, SheetRequest& out, std::string& usage, Diagnostics& diags);

}  // namespace glimmer
