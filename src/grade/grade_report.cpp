#include "grade/grade_report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include <fmt/format.h>

namespace glimmer {
namespace {

int rank(const std::string& verdict) {
    static const std::map<std::string, int> order{{"error", 0}, {"wrong", 1}, {"look", 2}, {"pass", 3}};
    auto it = order.find(verdict);
    return it == order.end() ? 0 : it->second;
}

std::string dB(double v) { return std::isinf(v) ? "identical" : fmt::format("{:.1f} dB", v); }

// A cell a spreadsheet would run as a formula starts with '=', '+', '-' or
// '@', or with a tab or a carriage return before one (OWASP's CSV injection
// list; issue 29): it gets a "'" first, which makes it text.
// Spreadsheets also trim leading spaces and read the full-width forms
// (U+FF1D = and its kin) as the ASCII ones (issue 37).
bool startsLikeAFormula(const std::string& text) {
    if (text.empty()) return false;
    if (text[0] == '\t' || text[0] == '\r') return true;
    const size_t at = text.find_first_not_of(' ');
    if (at == std::string::npos) return false;
    const char c = text[at];
    if (c == '=' || c == '+' || c == '-' || c == '@') return true;
    for (const char* wide : {"\xef\xbc\x9d", "\xef\xbc\x8b", "\xef\xbc\x8d", "\xef\xbc\xa0"})  // = + - @
        if (text.compare(at, 3, wide) == 0) return true;
    return false;
}

std::string csvCell(std::string text) {
    // Control bytes from a folder name or a comment (ESC, NUL) as \xNN text:
    // the CSV is read in terminals and by scripts too.
    std::string clean;
    for (char ch : text) {
        const unsigned char c = static_cast<unsigned char>(ch);
        if ((c < 0x20 && c != '\n' && c != '\r' && c != '\t') || c == 0x7f) clean += fmt::format("\\x{:02x}", c);
        else clean += ch;
    }
    text = std::move(clean);
    if (startsLikeAFormula(text)) text = "'" + text;
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

}  // namespace

std::string htmlEscape(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&#39;"; break;
        default: out += c;
        }
    }
    return out;
}

void sortForReview(std::vector<GradeRow>& rows) {
    std::stable_sort(rows.begin(), rows.end(), [](const GradeRow& a, const GradeRow& b) {
        if (rank(a.verdict) != rank(b.verdict)) return rank(a.verdict) < rank(b.verdict);
        if (a.score != b.score) return a.score < b.score;
        return a.student < b.student;
    });
}

std::string hrefOf(const std::string& path) {
    std::string out;
    for (unsigned char c : path) {
        if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') out += char(c);
        else out += fmt::format("%{:02X}", c);
    }
    return out;
}

std::string reportRowHtml(const GradeRow& r, const RowPictures& p) {
    auto img = [](const std::string& url, const std::string& alt, const std::string& href = "") {
        if (url.empty()) return fmt::format("<div class=none>no {}</div>", alt);
        std::string tag = fmt::format("<img src=\"{}\" alt=\"{}\" title=\"{}\">", url, alt, alt);
        return href.empty() ? tag : fmt::format("<a href=\"{}\">{}</a>", htmlEscape(hrefOf(href)), tag);  // full size on click
    };
    std::string measures = r.verdict == "error"
                               ? std::string("&nbsp;")
                               : fmt::format("SSIM {:.3f} · PSNR {}<br>worst at {}{}", r.ssim, htmlEscape(dB(r.psnr)),
                                             htmlEscape(r.worstSetting),
                                             r.bySetting.empty() ? "" : "<br>SSIM by setting: " + htmlEscape(r.bySetting));
    // An error says which (issue 29: one red ERROR stood for a refused zip, an
    // unreadable one, a time-out and a shader that does not compile alike).
    const std::string label = r.verdict == "error" && !r.notes.empty() ? "error: " + r.notes : r.verdict;
    const std::string score = r.computedScore >= 0 ? fmt::format("{} <small>(set by hand; computed {})</small>", r.score,
                                                                 r.computedScore)
                                                   : std::to_string(r.score);
    std::string extra;
    if (!r.comment.empty()) extra += "<p class=comment>Teacher: " + htmlEscape(r.comment) + "</p>";
    if (!p.feedbackHref.empty())
        extra += fmt::format("<p><a href=\"{}\">feedback page</a> (every setting, full size, to hand back)</p>",
                             htmlEscape(hrefOf(p.feedbackHref)));
    return fmt::format(
        "<tr class=\"{0}\" id=\"s-{1}\"><td class=who><b>{1}</b><br><span class=v>{10}</span> <span class=score>{2}</span><br>"
        "<small>{3:.2f} s</small><br><small class=path>{11}</small></td>\n<td class=pics>{4}{5}{6}</td>\n"
        "<td class=why><small>{7}</small>{12}{8}{9}</td></tr>\n",
        htmlEscape(r.verdict), htmlEscape(r.student), score, r.seconds, img(p.student, "student", p.studentHref),
        img(p.solution, "solution", p.solutionHref), img(p.difference, "difference x4"), measures,
        r.notes.empty() ? "" : "<p>" + htmlEscape(r.notes) + "</p>",
        r.diagnostics.empty() ? "" : "<pre>" + htmlEscape(r.diagnostics) + "</pre>", htmlEscape(label),
        htmlEscape(r.submission), extra);
}

std::string reportHtml(const ReportHeader& h, const std::vector<GradeRow>& rows, const std::vector<std::string>& rowHtml) {
    std::map<std::string, int> counts;
    for (const auto& r : rows) ++counts[r.verdict];
    std::string settings;
    for (const auto& s : h.settings) settings += (settings.empty() ? "" : " · ") + htmlEscape(s);
    std::string out;
    out += "<!DOCTYPE html>\n<html lang=en><head><meta charset=utf-8><title>Grades: " + htmlEscape(h.solution) +
           "</title>\n<style>\n"
           // A name is isolated from the text around it: a right-to-left
           // override (U+202E) in a folder name no longer turns the row
           // around (issue 37).
           ".who b,.glance a,.path,h1{unicode-bidi:isolate}\n"
           "body{font:14px/1.35 system-ui,sans-serif;margin:16px;color:#222}\n"
           "h1{font-size:20px;margin:0 0 4px}\n.how{color:#555;margin:0 0 10px}\n"
           ".counts span{display:inline-block;padding:2px 8px;margin-right:6px;border-radius:3px}\n"
           "table{border-collapse:collapse;width:100%}\ntd{border-top:1px solid #ddd;padding:6px;vertical-align:top}\n"
           "td.who{width:150px}\ntd.pics{width:312px;white-space:nowrap}\n"
           "td.pics img,.none{width:96px;height:96px;margin-right:4px;image-rendering:pixelated;border:1px solid #ccc;"
           "display:inline-block;vertical-align:top;object-fit:contain;background:#eee}\n"
           ".none{font-size:11px;color:#888;text-align:center;line-height:96px}\n"
           "pre{margin:4px 0 0;font-size:12px;background:#f6f6f6;padding:4px;max-height:9em;overflow:auto;white-space:pre-wrap}\n"
           "td.why p{margin:2px 0}\n.comment{background:#eef;padding:2px 4px}\n.path{color:#777;word-break:break-all}\n.v{font-weight:bold;text-transform:uppercase;font-size:12px}\n"
           ".score{font-size:18px}\n"
           "tr.error .v,.counts .error{color:#fff;background:#b00}\ntr.wrong .v,.counts .wrong{color:#fff;background:#d60}\n"
           "tr.look .v,.counts .look{background:#fd4}\ntr.pass .v,.counts .pass{color:#fff;background:#282}\n"
           "tr .v{padding:0 4px;border-radius:3px}\n"
           ".glance{line-height:1.9;margin:0 0 10px}\n.glance a{display:inline-block;min-width:84px;padding:0 4px;"
           "margin:0 2px 2px 0;font-size:12px;text-decoration:none;color:inherit;border-radius:3px;background:#eee}\n"
           ".glance a.error{color:#fff;background:#b00}\n.glance a.wrong{color:#fff;background:#d60}\n"
           ".glance a.look{background:#fd4}\n.glance a.pass{background:#cec}\n"
           "</style></head><body>\n";
    out += "<h1>Grades against " + htmlEscape(h.solution) + "</h1>\n";
    out += fmt::format("<p class=how>{} submissions{} · compared at {} setting{}: {} · {} · sandbox {}</p>\n",
                       rows.size(),
                       h.expected > int(rows.size()) ? fmt::format(" of {} (the rest still running)", h.expected) : "",
                       h.settings.size(), h.settings.size() == 1 ? "" : "s", settings, htmlEscape(h.thresholds),
                       h.sandbox ? "on" : "<b>off</b>");
    out += "<p class=counts>";
    for (const char* v : {"error", "wrong", "look", "pass"})
        out += fmt::format("<span class={0}>{1} {0}</span>", v, counts[v]);
    out += "<small>pictures: the student's, the solution's, their difference x4, at the worst setting; a click "
           "shows one full size; each row links to the student's feedback page</small></p>\n";
    // At a glance: every student as a chip in the table's order, a link to its row.
    out += "<p class=glance>";
    for (const auto& r : rows)
        out += fmt::format("<a class={} href=\"#s-{}\">{} {}</a>", htmlEscape(r.verdict), htmlEscape(r.student),
                           htmlEscape(r.student), r.score);
    out += "</p>\n<table>\n";
    for (const auto& row : rowHtml) out += row;
    out += "</table>\n</body></html>\n";
    return out;
}

std::string feedbackHtml(const GradeRow& r, const std::string& solutionName, const std::vector<SettingPictures>& settings) {
    auto img = [](const std::string& url, const std::string& alt) {
        return url.empty() ? fmt::format("<div class=none>no {}</div>", alt)
                           : fmt::format("<figure><img src=\"{}\" alt=\"{}\"><figcaption>{}</figcaption></figure>", url,
                                         alt, alt);
    };
    const std::string label = r.verdict == "error" && !r.notes.empty() ? "error: " + r.notes : r.verdict;
    std::string out = "<!DOCTYPE html>\n<html lang=en><head><meta charset=utf-8><title>Feedback: \u2068" + htmlEscape(r.student) + "\u2069" +
                      "</title>\n<style>\nh1{unicode-bidi:isolate}\nbody{font:15px/1.4 system-ui,sans-serif;margin:16px;color:#222;max-width:1100px}\n"
                      "h1{font-size:20px;margin:0 0 6px}\nfigure{display:inline-block;margin:0 8px 8px 0;vertical-align:top}\n"
                      "figure img{max-width:340px;image-rendering:pixelated;border:1px solid #ccc;display:block}\n"
                      "figcaption{font-size:12px;color:#555}\n.none{display:inline-block;width:200px;color:#888}\n"
                      "pre{background:#f6f6f6;padding:6px;white-space:pre-wrap}\n.comment{background:#eef;padding:6px}\n"
                      ".v{font-weight:bold;text-transform:uppercase}\nh2{font-size:16px;margin:14px 0 4px}\n"
                      "</style></head><body>\n";
    // The name isolated (a title takes no markup: U+2068 FIRST STRONG
    // ISOLATE ... U+2069), so a U+202E in it turns nothing around it (issue 37).
    out += "<h1><bdi>" + htmlEscape(r.student) + "</bdi>: graded against " + htmlEscape(solutionName) + "</h1>\n";
    out += fmt::format("<p><span class=v>{}</span> · score {}{}</p>\n", htmlEscape(label), r.score,
                       r.computedScore >= 0 ? fmt::format(" (set by your teacher; computed {})", r.computedScore) : "");
    if (!r.comment.empty()) out += "<p class=comment>Your teacher: " + htmlEscape(r.comment) + "</p>\n";
    if (!r.notes.empty()) out += "<p>" + htmlEscape(r.notes) + "</p>\n";
    if (r.verdict != "error")
        out += fmt::format("<p>SSIM {:.3f} · PSNR {} at the setting that differs most ({}). SSIM by setting: {}</p>\n",
                           r.ssim, htmlEscape(dB(r.psnr)), htmlEscape(r.worstSetting), htmlEscape(r.bySetting));
    if (!r.diagnostics.empty()) out += "<h2>What Glimmer said</h2>\n<pre>" + htmlEscape(r.diagnostics) + "</pre>\n";
    if (!settings.empty())
        out += "<h2>Every setting: yours, the solution's, their difference x4</h2>\n";
    for (const auto& s : settings) {
        out += "<h3>" + htmlEscape(s.label) + "</h3>\n<div>";
        out += img(s.student, "yours") + img(s.solution, "the solution") + img(s.difference, "difference x4");
        out += "</div>\n";
    }
    out += "</body></html>\n";
    return out;
}

std::string gradesCsv(std::vector<GradeRow> rows) {
    std::sort(rows.begin(), rows.end(), [](const GradeRow& a, const GradeRow& b) { return a.student < b.student; });
    std::string out = "student,score,verdict,ssim,psnr_db,seconds,notes,first_diagnostic,submission,computed_score,comment\n";
    for (const auto& r : rows)
        out += fmt::format("{},{},{},{},{},{:.2f},{},{},{},{},{}\n", csvCell(r.student), r.score, r.verdict,
                           r.verdict == "error" ? "" : fmt::format("{:.4f}", r.ssim),
                           r.verdict == "error" ? "" : std::isinf(r.psnr) ? "inf" : fmt::format("{:.2f}", r.psnr),
                           r.seconds, csvCell(r.notes), csvCell(firstLine(r.diagnostics)), csvCell(r.submission),
                           r.computedScore >= 0 ? std::to_string(r.computedScore) : "", csvCell(r.comment));
    return out;
}

}  // namespace glimmer
