#include "app/help_text.h"

#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "pipeline/console.h"
#include "pipeline/options.h"

#ifndef GLIMMER_VERSION
#define GLIMMER_VERSION "unknown"
#endif

namespace glimmer {
namespace {

const char* const kFooter =
    "Shortcut: `glimmer SCRIPT.glib` is `glimmer view SCRIPT.glib`.\n"
    "`glimmer help COMMAND` (or `glimmer COMMAND --help`) shows a command's options and defaults.\n"
    "Exit codes: 0 success, 1 script or shader errors, 2 usage errors.";

std::vector<CLI::App*> commandsOf(CLI::App& app) {
    return app.get_subcommands([](CLI::App*) { return true; });
}

// roff needs its backslashes and leading dots and hyphens escaped.
std::string roff(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\\') out += "\\e";
        else if (c == '-') out += "\\-";
        else out += c;
    }
    if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out = "\\&" + out;
    return out;
}

std::string optionNames(const CLI::Option* o) {
    std::string names;
    for (const auto& s : o->get_snames()) names += (names.empty() ? "-" : ", -") + s;
    for (const auto& l : o->get_lnames()) names += (names.empty() ? "--" : ", --") + l;
    if (names.empty()) names = o->get_name();
    return names;
}

}  // namespace

void addGlobalOptions(CLI::App& app, GlobalOptions& o) {
    app.name("glimmer");
    app.set_version_flag("--version", std::string("glimmer ") + GLIMMER_VERSION, "print the version and exit");
    app.add_flag("-q,--quiet", o.quiet, "print errors only: no warnings, progress or 'wrote' lines");
    app.add_flag("-v,--verbose", o.verbose, "list every warning (by default, repeated glman-compatibility warnings "
                                            "of one kind are folded into one line)");
    // -q and -v also after the command: `glimmer render x.glib -q`.
    app.fallthrough();
    app.option_defaults()->always_capture_default();
    app.footer(kFooter);
    app.add_subcommand("help", "show this help, or a command's: glimmer help [COMMAND]");
}

std::optional<int> applyGlobalOptions(const GlobalOptions& o) {
    if (o.quiet && o.verbose) {
        std::cerr << "glimmer: error: -q and -v cannot be given together\n";
        return kExitUsage;
    }
    setVerbosity(o.quiet ? Verbosity::Quiet : o.verbose ? Verbosity::Verbose : Verbosity::Normal);
    return std::nullopt;
}

std::optional<int> runHelp(CLI::App& app, const std::vector<std::string>& args) {
    // An empty list says nothing as a default: show none.
    for (CLI::App* sub : commandsOf(app))
        for (CLI::Option* o : sub->get_options())
            if (o->get_default_str() == "[]") o->default_str("");
    if (args.size() == 2 && args[1] == "--man") {
        std::cout << manPage(app);
        return kExitOk;
    }
    if (args.size() < 2 || args[1] != "help") return std::nullopt;
    if (args.size() == 2) {
        std::cout << app.help();
        return kExitOk;
    }
    if (args.size() > 3) {
        std::cerr << "glimmer: error: help takes at most one COMMAND\n";
        return kExitUsage;
    }
    for (CLI::App* sub : commandsOf(app)) {
        if (sub->get_name() == args[2] && sub->get_name() != "help") {
            std::cout << sub->help(app.get_name());
            return kExitOk;
        }
    }
    std::string names;
    auto commands = commandsOf(app);
    for (CLI::App* sub : commands)
        if (sub->get_name() != "help") names += (names.empty() ? "'" : ", '") + sub->get_name() + "'";
    std::cerr << fmt::format("glimmer: error: help: unknown command '{}'; the commands are {}\n", args[2], names);
    return kExitUsage;
}

std::string manPage(CLI::App& app) {
    std::ostringstream m;
    m << ".TH GLIMMER 1 \"\" \"glimmer " << GLIMMER_VERSION << "\" \"User Commands\"\n";
    m << ".SH NAME\nglimmer \\- " << roff(app.get_description()) << "\n";
    m << ".SH SYNOPSIS\n";
    for (CLI::App* sub : commandsOf(app)) {
        if (sub->get_name() == "help") continue;
        m << ".B glimmer " << sub->get_name() << "\n";
        std::string positional;
        for (const CLI::Option* o : sub->get_options())
            if (!o->nonpositional()) positional += " " + o->get_name();
        m << "[\\fIOPTIONS\\fR]" << roff(positional) << "\n.br\n";
    }
    m << ".B glimmer\n.I SCRIPT.glib\n.br\n.B glimmer help\n.RI [ COMMAND ]\n";
    m << ".SH GLOBAL OPTIONS\n";
    for (const CLI::Option* o : app.get_options()) {
        m << ".TP\n.B " << roff(optionNames(o)) << "\n" << roff(o->get_description()) << "\n";
    }
    m << ".SH COMMANDS\n";
    for (CLI::App* sub : commandsOf(app)) {
        if (sub->get_name() == "help") continue;
        m << ".SS " << sub->get_name() << "\n" << roff(sub->get_description()) << ".\n";
        for (const CLI::Option* o : sub->get_options()) {
            if (o->get_lnames().size() == 1 && o->get_lnames()[0] == "help") continue;
            m << ".TP\n.B " << roff(optionNames(o));
            if (!o->get_type_name().empty() && o->get_type_size() != 0) m << " \\fI" << roff(o->get_type_name()) << "\\fR";
            m << "\n" << roff(o->get_description());
            std::string def = o->get_default_str();
            if (!def.empty() && def != "[]" && def != "0" && def != "false") m << " (default: " << roff(def) << ")";
            m << "\n";
        }
    }
    m << ".SH NOTES\n";
    std::istringstream footer(kFooter);
    for (std::string line; std::getline(footer, line);) m << roff(line) << "\n.br\n";
    m << ".SH SEE ALSO\nThe language: docs/glib.md; teaching with Glimmer: docs/teaching.md.\n";
    return m.str();
}

}  // namespace glimmer
