// Where everything on a contact sheet goes: a title line (the script and the
// values --set fixed), a header above each column and beside each row, and,
// when a header cannot fit its cell at a legible size, a legend below.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"

namespace glimmer {

struct SheetText {
    int x = 0, y = 0;
    std::string text;
    float px = 12;
};

struct SheetLayout {
    int width = 0, height = 0;
    int cellW = 0, cellH = 0;
    int gap = 8;
    int gridX = 0, gridY = 0;  // top-left of the first cell
    float labelPx = 12;        // the size the headers were set at
    bool legend = false;       // headers are short names explained below
    std::vector<SheetText> texts;
    std::pair<int, int> cellOrigin(int col, int row) const {
        return {gridX + col * (cellW + gap), gridY + row * (cellH + gap)};
    }
};

// The smallest label size a handout may use, in pixels; below it, headers
// become letters or values and a legend below says what they mean.
inline constexpr float kMinLabelPx = 9.f;
inline constexpr float kMaxLabelPx = 18.f;

// Headers read "name = value" when that fits the cell at kMinLabelPx or
// more (as large as fits, up to kMaxLabelPx); else the value alone, the
// name going to the legend; else a letter (columns) or number (rows), and
// the legend lists each. An empty rowName: one row, no row headers.
SheetLayout layoutSheet(const std::string& title, const std::string& colName, const std::vector<std::string>& colValues,
                        const std::string& rowName, const std::vector<std::string>& rowValues, int cellW, int cellH);

// Draws every text of the layout.
void drawSheetLabels(Image& sheet, const SheetLayout& layout);

}  // namespace glimmer
