#include "lang/parser.h"

#include <optional>

#include "lang/lexer.h"
#include "util/numbers.h"

namespace glimmer {

namespace {

std::string formatNumber(double v) { return formatDouble(v); }

std::string quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

class Parser {
public:
    Parser(const std::string& file, Diagnostics& diags, std::uint64_t maxBytes)
        : file_(file), diags_(diags), maxBytes_(maxBytes) {}

    Script run(std::string_view text) {
        Script script;
        script.file = file_;
        // Index into script.commands of the Program that uniform lines written
        // without `\` still belong to; reset by any line that is not one.
        std::optional<size_t> attachTo;

        LexBudget budget;
        budget.maxBytes = maxBytes_;
        std::vector<LogicalLine> lines = lexScript(text, &budget);
        script.bytes = budget.used;
        if (budget.over()) {
            diags_.error(file_, budget.overAt, overMemoryBudget(budget.used, maxBytes_));
            return script;
        }
        if (text.substr(0, 3) == "\xEF\xBB\xBF")  // read as nothing by the lexer; said, as for shaders
            diags_.note(file_, {1, 1}, "a UTF-8 byte-order mark starts this file (an editor put it there); read as "
                                       "nothing");
        for (const LogicalLine& line : lines) {
            const Token& first = line.tokens.front();
            if (first.kind != Token::Kind::Word) {
                diags_.warning(file_, first.loc,
                               "expected a command word, found " + quoted(first.text) + "; line ignored");
                attachTo.reset();
                continue;
            }

            std::optional<CommandKind> kind = lookupCommand(first.text);
            if (!kind && attachTo) {
                attachUniformLine(script.commands[*attachTo], line);
                continue;
            }
            attachTo.reset();
            if (!kind) {
                diags_.warning(file_, first.loc, "unknown command " + quoted(first.text) + "; line ignored");
                continue;
            }

            Command cmd;
            cmd.kind = *kind;
            cmd.spelled = first.text;
            cmd.loc = first.loc;
            if (cmd.kind == CommandKind::MessageBox) {
                messageText(line, cmd);
            } else {
                std::string dropped = "command " + quoted(first.text) + " ignored";
                if (!parseArgs(line.tokens, 1, cmd.args, dropped)) continue;
            }
            script.commands.push_back(std::move(cmd));
            if (*kind == CommandKind::Program) attachTo = script.commands.size() - 1;
        }
        return script;
    }

private:
    // glman reads a Program's uniforms only from its own logical line; the
    // classroom scripts put them on the next lines anyway and expect them to work.
    void attachUniformLine(Command& program, const LogicalLine& line) {
        const Token& first = line.tokens.front();
        std::string programName = "Program";
        if (!program.args.empty() && program.args.front().kind == Arg::Kind::Word)
            programName += " " + quoted(program.args.front().text);
        diags_.warning(file_, first.loc,
                       "uniform " + quoted(first.text) + " is on a line of its own; taken as part of " +
                           programName + " (line " + std::to_string(program.loc.line) +
                           "); glman needs a '\\' at the end of the previous line");
        std::vector<Arg> args;
        if (parseArgs(line.tokens, 0, args, "line ignored"))
            program.args.insert(program.args.end(), args.begin(), args.end());
    }

    // MessageBox text is free prose: brackets, commas and stray dots in it are
    // not GLIB syntax, so it is taken verbatim as one Word.
    void messageText(const LogicalLine& line, Command& cmd) {
        const Token& word = line.tokens.front();
        std::string text;
        SourceLoc loc;
        for (const Segment& seg : line.segments) {
            size_t from = 0;
            if (seg.line == word.loc.line) from = static_cast<size_t>(word.loc.col - seg.col) + word.text.size();
            if (seg.line < word.loc.line || from >= seg.text.size()) continue;
            size_t b = seg.text.find_first_not_of(" \t\r\v\f", from);
            if (b == std::string::npos) continue;
            size_t e = seg.text.find_last_not_of(" \t\r\v\f");
            if (text.empty()) loc = {seg.line, seg.col + static_cast<int>(b)};
            else text += ' ';
            text += seg.text.substr(b, e + 1 - b);
        }
        if (text.empty()) return;
        Arg a;
        a.kind = Arg::Kind::Word;
        a.loc = loc;
        a.text = std::move(text);
        cmd.args.push_back(std::move(a));
    }

    // Returns false, after an error, when the tokens do not form arguments;
    // `dropped` says what is thrown away because of it.
    bool parseArgs(const std::vector<Token>& toks, size_t i, std::vector<Arg>& out, const std::string& dropped) {
        while (i < toks.size()) {
            const Token& t = toks[i];
            if (t.kind == Token::Kind::Close) {
                diags_.error(file_, t.loc, "unexpected " + quoted(t.text) + " outside a group; " + dropped);
                return false;
            }
            if (t.kind != Token::Kind::Open) {
                std::optional<Arg> a = scalar(t, dropped);
                if (!a) return false;
                out.push_back(std::move(*a));
                ++i;
                continue;
            }

            Arg group;
            group.kind = t.text == "<" ? Arg::Kind::Range : t.text == "{" ? Arg::Kind::Color : Arg::Kind::Array;
            group.loc = t.loc;
            const std::string close(1, closingBracket(t.text[0]));
            size_t j = i + 1;
            for (;; ++j) {
                if (j == toks.size()) {
                    diags_.error(file_, t.loc,
                                 quoted(t.text) + " is never closed (missing " + quoted(close) + "); " + dropped);
                    return false;
                }
                const Token& u = toks[j];
                if (u.kind == Token::Kind::Open) {
                    diags_.error(file_, u.loc,
                                 quoted(u.text) + " inside " + quoted(t.text + "..." + close) +
                                     "; groups do not nest; " + dropped);
                    return false;
                }
                if (u.kind == Token::Kind::Close) {
                    if (u.text == close) break;
                    diags_.error(file_, u.loc,
                                 quoted(u.text) + " cannot close " + quoted(t.text) + " (expected " + quoted(close) +
                                     "); " + dropped);
                    return false;
                }
                std::optional<Arg> a = scalar(u, dropped);
                if (!a) return false;
                group.items.push_back(std::move(*a));
            }
            out.push_back(std::move(group));
            i = j + 1;
        }
        return true;
    }

    std::optional<Arg> scalar(const Token& t, const std::string& dropped) {
        Arg a;
        a.loc = t.loc;
        a.text = t.text;
        if (t.kind == Token::Kind::Word) {
            a.kind = Arg::Kind::Word;
            return a;
        }
        a.kind = Arg::Kind::Number;
        a.number = t.number;
        switch (t.issue) {
            case Token::NumberIssue::None: break;
            case Token::NumberIssue::Malformed:
                diags_.warning(file_, t.loc,
                               "malformed number " + quoted(t.text) + " read as " + formatNumber(t.number));
                break;
            case Token::NumberIssue::DecimalComma:
                diags_.warning(file_, t.loc,
                               "decimal comma in " + quoted(t.text) + " read as " + formatNumber(t.number) +
                                   "; GLIB separates values with commas, so write decimals with a point");
                break;
            case Token::NumberIssue::OutOfRange:
                diags_.error(file_, t.loc, "number " + quoted(t.text) + " is out of range; " + dropped);
                return std::nullopt;
        }
        return a;
    }

    const std::string& file_;
    Diagnostics& diags_;
    std::uint64_t maxBytes_ = 0;
};

}  // namespace

Script parseScript(const std::string& file, const std::string& text, Diagnostics& diags, std::uint64_t maxBytes) {
    return Parser(file, diags, maxBytes).run(text);
}

}  // namespace glimmer
