#include "sheet/sheet_layout.h"

#include <algorithm>
#include <sstream>

#include "image/ttf_text.h"

namespace glimmer {
namespace {

// The largest size in [kMinLabelPx, kMaxLabelPx] at which every text fits
// `room` pixels; 0 when none does.
float fittingSize(const std::vector<std::string>& texts, int room) {
    for (float px = kMaxLabelPx; px >= kMinLabelPx; px -= 1.f) {
        bool all = true;
        for (const auto& t : texts) all &= labelWidth(t, px) <= room;
        if (all) return px;
    }
    return 0;
}

// Greedy wrap of `pieces` (joined by three spaces) into lines of at most
// `room` pixels; a piece too long for a line of its own breaks at its spaces.
std::vector<std::string> wrap(const std::vector<std::string>& pieces, float px, int room) {
    std::vector<std::string> lines;
    std::string line;
    auto add = [&](const std::string& word, const char* sep) {
        std::string tried = line.empty() ? word : line + sep + word;
        if (!line.empty() && labelWidth(tried, px) > room) {
            lines.push_back(line);
            line = word;
        } else {
            line = tried;
        }
    };
    for (const auto& p : pieces) {
        if (labelWidth(p, px) <= room) {
            add(p, "   ");
            continue;
        }
        bool firstWord = true;
        std::istringstream words(p);
        for (std::string w; words >> w; firstWord = false) add(w, firstWord ? "   " : " ");
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

// The widest of `texts` at `px`: no line can be narrower.
int widest(const std::vector<std::string>& texts, float px) {
    int w = 0;
    for (const auto& t : texts) w = std::max(w, labelWidth(t, px));
    return w;
}

// Column names for the legend: a, b, ..., z, aa, ab, ...
std::string letter(size_t i) {
    std::string s;
    for (size_t n = i + 1; n > 0; n = (n - 1) / 26) s.insert(s.begin(), char('a' + (n - 1) % 26));
    return s;
}

}  // namespace

SheetLayout layoutSheet(const std::string& title, const std::string& colName, const std::vector<std::string>& colValues,
                        const std::string& rowName, const std::vector<std::string>& rowValues, int cellW, int cellH) {
    SheetLayout L;
    L.cellW = cellW;
    L.cellH = cellH;
    const int gap = L.gap;
    const bool twoAxes = !rowName.empty();
    const int nCols = int(colValues.size()), nRows = twoAxes ? int(rowValues.size()) : 1;
    const int room = cellW - 2;

    // Column headers: "name = value", else the value, else a letter.
    std::vector<std::string> colFull, rowFull, colText, rowText;
    for (const auto& v : colValues) colFull.push_back(colName + " = " + v);
    for (const auto& v : rowValues) rowFull.push_back(rowName + " = " + v);
    std::vector<std::string> legend;
    float px = fittingSize(colFull, room);
    if (px > 0) {
        colText = colFull;
        rowText = rowFull;
    } else if ((px = fittingSize(colValues, room)) > 0) {
        colText = colValues;
        rowText = rowValues;
        legend.push_back("columns: " + colName);
        if (twoAxes) legend.push_back("rows: " + rowName);
    } else {
        px = kMinLabelPx;
        std::vector<std::string> pieces;
        for (int c = 0; c < nCols; ++c) {
            colText.push_back(letter(size_t(c)));
            pieces.push_back(colText.back() + ": " + colFull[size_t(c)]);
        }
        for (int r = 0; twoAxes && r < nRows; ++r) {
            rowText.push_back(std::to_string(r + 1));
            pieces.push_back(rowText.back() + ": " + rowFull[size_t(r)]);
        }
        legend = pieces;
    }
    L.labelPx = px;
    L.legend = !legend.empty();
    const int line = labelLineHeight(px);

    // Row headers sit left of their row, as wide as the widest needs (at
    // most a cell; longer ones shrink to fit, down to the minimum).
    int rowLabelW = 0;
    float rowPx = px;
    if (twoAxes) {
        for (const auto& t : rowText) rowLabelW = std::max(rowLabelW, labelWidth(t, rowPx));
        if (rowLabelW > cellW) {
            float fit = fittingSize(rowText, cellW);
            rowPx = fit > 0 ? std::min(fit, px) : kMinLabelPx;
            rowLabelW = 0;
            for (const auto& t : rowText) rowLabelW = std::max(rowLabelW, labelWidth(t, rowPx));
        }
        rowLabelW += gap;
    }
    L.width = gap + rowLabelW + nCols * (cellW + gap);

    // The title, wrapped to the sheet's width.
    const float titlePx = std::min(px + 2.f, kMaxLabelPx);
    std::vector<std::string> titlePieces;
    {
        size_t start = 0;
        for (;;) {
            size_t at = title.find("   ", start);
            titlePieces.push_back(title.substr(start, at == std::string::npos ? std::string::npos : at - start));
            if (at == std::string::npos) break;
            start = at + 3;
        }
    }
    // A sheet of narrow cells is widened to its longest "name = value",
    // rather than breaking one.
    L.width = std::max({L.width, widest(titlePieces, titlePx) + 2 * gap, widest(legend, px) + 2 * gap});
    int y = gap;
    for (const auto& t : wrap(titlePieces, titlePx, L.width - 2 * gap)) {
        L.texts.push_back({gap, y, t, titlePx});
        y += labelLineHeight(titlePx);
    }
    y += gap / 2;
    // Column headers, centred over their cell.
    L.gridX = gap + rowLabelW;
    for (int c = 0; c < nCols; ++c) {
        int w = labelWidth(colText[size_t(c)], px);
        L.texts.push_back({L.gridX + c * (cellW + gap) + std::max(0, (cellW - w) / 2), y, colText[size_t(c)], px});
    }
    y += line + gap / 2;
    L.gridY = y;
    for (int r = 0; twoAxes && r < nRows; ++r)
        L.texts.push_back({gap, L.gridY + r * (cellH + gap) + (cellH - labelLineHeight(rowPx)) / 2,
                           rowText[size_t(r)], rowPx});
    y = L.gridY + nRows * (cellH + gap);
    for (const auto& l : wrap(legend, px, L.width - 2 * gap)) {
        L.texts.push_back({gap, y, l, px});
        y += line;
    }
    if (!legend.empty()) y += gap;
    L.height = y;
    return L;
}

void drawSheetLabels(Image& sheet, const SheetLayout& layout) {
    for (const auto& t : layout.texts) drawLabel(sheet, t.x, t.y, t.text, t.px);
}

}  // namespace glimmer
