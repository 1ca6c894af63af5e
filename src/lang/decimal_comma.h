// Decimal commas: a student whose locale writes 0,01 types `< 0,01 0.1 1.0 >`.
// Commas separate values in GLIB, so that group has four items, and a slider
// needs three. This reads such a comma as a decimal point, but only where
// nothing else makes sense:
//   - inside a group whose items are otherwise separated by blanks, a chunk
//     written without blanks as digits,digits (`0,01`, `-1,5`) is one number;
//   - and only when the group, read that way, has the size its kind needs
//     (< > 1 or 3, { } 3 or 4, [ ] 2 to 4) while read with the comma as a
//     separator it does not.
// `<0,3,3>`, `{1,0,0}`, `<0, 3, 3>`, `1,5` outside a group and a chunk with
// two commas (`1,000,000`) keep their commas as separators.
#pragma once
#include "lang/lexer.h"

namespace glimmer {

// Joins the tokens of `line` that form a decimal-comma number into one Number
// token with NumberIssue::DecimalComma (its text as written, e.g. "0,01").
void readDecimalCommas(LogicalLine& line);

}  // namespace glimmer
