// Each subcommand's options on the command line (CLI11): add*Command wires
// one subcommand's flags to its options struct (app/subcommands.h). Not
// pipeline/options.cpp, which holds the parsing every front end shares.
#include <CLI/CLI.hpp>

#include "app/subcommands.h"
#include "view/viewer.h"

namespace glimmer {

CLI::Option* addBackendOption(CLI::App* sub, std::string& backend) {
    return sub->add_option("--backend", backend, "auto, osmesa, egl, egl-device, egl-surfaceless or egl-gles (OpenGL ES 3.0: WebGL 2's level)")
        ->check(CLI::IsMember({"auto", "osmesa", "egl", "egl-device", "egl-surfaceless", "egl-gles"}));
}

namespace {

// An option given with an empty value ("--watch ''") is a mistake, not the
// option left out (issue 37: both were silently ignored).
const CLI::Validator kNotEmpty(
    [](std::string& value) { return value.empty() ? std::string("an empty value; give one or leave the option out") : std::string(); },
    "", "not empty");

void addCommon(CLI::App* sub, CommonOptions& o) {
    sub->add_option("script", o.script, "the .glib script ('-': read it from standard input; the files it names "
                                        "resolve against the current folder)")->required();
    addBackendOption(sub, o.backend);
    sub->add_option("-I,--include", o.includeDirs, "another folder to find shaders and images in");
    sub->add_option("--set", o.sets, "NAME=VALUE for a range, checkbox, colour (R,G,B[,A]) or vector (X,Y,...) (repeatable)");
    sub->add_option("--size", o.size, "output size WxH (default: WindowSize, else 600x600)");
    sub->add_flag("--stand-ins", o.standIns, "a missing image, cube-map face, 3-D .tex or OBJ is a warning and a "
                                            "stand-in takes its place (a missing shader stays an error)");
    addSafetyOptions(sub, o);
}

}  // namespace

void addRenderCommand(CLI::App& app, RenderOptions& o) {
    CLI::App* sub = app.add_subcommand("render", "render a script headless to a PNG");
    addCommon(sub, o);
    sub->add_option("-o,--output", o.output, "the PNG to write ('-': standard output); with --frames, a frame "
                                             "pattern (frame_%04d.png) or an animated .webp");
    sub->add_option("--frames", o.frames, "render this many frames, Timer advancing 1/FPS seconds each");
    sub->add_option("--fps", o.fps, "frames per second of --frames");
    sub->add_option("--dump", o.dumps, "UNIT=FILE: also write the texture on that unit; .png, .hdr, .pfm or .exr "
                                       "(float targets keep their values in .hdr, .pfm and .exr) (repeatable)");
    sub->add_option("--png-level", o.pngLevel, "zlib level of the PNG, 0 (fastest, largest) to 9 (smallest, "
                                               "slowest); the pixels are the same at every level (default 3)");
    sub->add_option("--time", o.time, "seconds since start, for the Timer uniform");
    sub->add_flag("--timings", o.timings, "print start-up, compile, render and write times");
    sub->add_flag("--health", o.health, "report NaN, Inf, negative, above-65504 and clipped values per target");
    sub->add_flag("--strict", o.strict, "like --health, and exit 1 if any target holds NaN, Inf, negatives or "
                                        "values above 65504");
    sub->add_option("--watch", o.watch, "FILE:LINE:EXPR: write the value of a GLSL expression right after that line "
                                        "runs, over the whole pass, instead of the picture: -o .png shows it, .exr "
                                        "or .pfm holds the floats; prints its range and NaN/Inf counts")
        ->type_name("FILE:LINE:EXPR")
        ->check(kNotEmpty);
    sub->add_option("--watch-range", o.watchRange, "LO,HI: the values shown black to white (default: their own "
                                                   "minimum and maximum); outside it, marked")
        ->type_name("LO,HI")
        ->check(kNotEmpty);
}

void addCheckCommand(CLI::App& app, CheckOptions& o) {
    CLI::App* sub = app.add_subcommand("check", "parse, load, compile and link a script; draw nothing");
    addCommon(sub, o);
    sub->add_flag("--web", o.web, "instead, translate every shader to GLSL ES 3.00 for WebGL 2 (no OpenGL needed): "
                                  "will the script run in the browser?");
    sub->add_flag("--list-inputs", o.listInputs, "after a check without errors, print every file the script reads, "
                                                 "one a line (tools/web_lesson.py packs these)");
    sub->add_option("--watch", o.watch, "FILE:LINE:EXPR: also check that the expression can be watched there "
                                        "(in scope, a line inside a function, a type a watch shows)")
        ->type_name("FILE:LINE:EXPR")
        ->check(kNotEmpty);
}

void addViewCommand(CLI::App& app, ViewOptions& o) {
    CLI::App* sub = app.add_subcommand("view", "open a window with sliders; reload on every save");
    sub->add_option("script", o.script, "the .glib script")->required();
    sub->add_option("-I,--include", o.includeDirs, "another folder to find shaders and images in");
    sub->add_option("--set", o.sets, "NAME=VALUE for a range, checkbox, colour (R,G,B[,A]) or vector (X,Y,...) (repeatable)");
    sub->add_option("--size", o.size, "window size WxH (default: WindowSize, else 600x600)");
    sub->add_option("--exec", o.exec, "commands to run, separated by ';': set NAME VALUE, reload, save FILE.png, "
                                      "show UNIT|screen, values on|off, probe [on|off|X Y], split L R|off, watch FILE:LINE "
                                      "EXPR|off|range LO,HI, help, quit");
    sub->add_flag("!--no-stdin", o.readStdin, "do not read commands from standard input");
    sub->add_flag("--stand-ins,!--no-stand-ins", o.standIns, "replace missing images and models by stand-ins, with a "
                                                            "warning (the default in view); --no-stand-ins: an error");
    sub->add_flag("--sandbox", o.sandbox, "read only files inside the script's folder and -I folders");
    sub->add_option("--ui-scale", o.uiScale, "size of the panel's text and controls, 0.5 to 4 (default: the "
                                             "monitor's content scale, else 1)");
}

}  // namespace glimmer
