// glimmer serve LESSON_DIR --solution SOLUTION.glib [--roster roster.csv]
// [--port N]: the lab from one command (issue 41). Checks what it is given,
// prints where students join (and the QR code) and the teacher's link, then
// serves until Ctrl-C. The work is in src/serve: the store, the grader, the
// HTTP side.
#include <ifaddrs.h>
#include <netinet/in.h>
#include <arpa/inet.h>
#include <signal.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>
#include <thread>

#include "app/subcommands.h"
#include "lang/diagnostics.h"
#include "pipeline/console.h"
#include "pipeline/load_script.h"
#include "process/data_dir.h"
#include "serve/class_server.h"
#include "serve/join_qr.h"
#include "serve/roster.h"
#include "util/read_file.h"
#include "util/write_file.h"

namespace fs = std::filesystem;

namespace glimmer {
namespace {

// This machine's first address other than loopback: what students on the
// lab's network type (the teacher gives --public when it is another).
std::string outwardAddress() {
    ifaddrs* all = nullptr;
    std::string found = "127.0.0.1";
    if (getifaddrs(&all) != 0) return found;
    for (ifaddrs* a = all; a; a = a->ifa_next) {
        if (!a->ifa_addr || a->ifa_addr->sa_family != AF_INET) continue;
        char text[INET_ADDRSTRLEN] = {};
        inet_ntop(AF_INET, &reinterpret_cast<sockaddr_in*>(a->ifa_addr)->sin_addr, text, sizeof text);
        if (std::string(text).rfind("127.", 0) != 0) {
            found = text;
            break;
        }
    }
    freeifaddrs(all);
    return found;
}

// The page's build: --page, $GLIMMER_PAGE, or beside Glimmer's data (an
// install's share/glimmer/web, a source tree's build-web or build/web).
std::string findPage(const std::string& given) {
    if (!given.empty()) return given;
    if (const char* env = std::getenv("GLIMMER_PAGE")) return env;
    const fs::path data = dataDir();
    for (const fs::path& p : {data / "web", data / "build-web" / "src" / "web", data / "build" / "web" / "src" / "web"}) {
        std::error_code ec;
        if (fs::is_regular_file(p / "index.html", ec) && fs::is_regular_file(p / "glimmer-web.wasm", ec)) return p.string();
    }
    return "";
}

bool inside(const fs::path& file, const fs::path& dir) {
    std::error_code ec;
    const fs::path f = fs::weakly_canonical(file, ec), d = fs::weakly_canonical(dir, ec);
    const auto [end, _] = std::mismatch(d.begin(), d.end(), f.begin(), f.end());
    return end == d.end();
}

}  // namespace

void addServeCommand(CLI::App& app, ServeOptions& o) {
    auto* sub = app.add_subcommand("serve", "the lab from one command: the page and lesson served to the class, each "
                                            "student's work kept, hand-ins graded as they arrive");
    sub->add_option("lesson", o.lessonDir, "the lesson's folder: its scripts, shaders and textures, as students get them")
        ->required();
    sub->add_option("--solution", o.solution, "the solution script hand-ins are graded against (outside the lesson "
                                              "folder: it is never served)")->required();
    sub->add_option("--roster", o.roster, "the class list (a name a line): each student gets their own link "
                                          "(STATE/links.csv); without it students join with the class code");
    sub->add_option("--port", o.port, "the port to listen on (default 8080; 0: any free one)");
    sub->add_option("--host", o.host, "the address to listen on (default 0.0.0.0: every interface)");
    sub->add_option("--public", o.publicAddress, "the address students type, when it is not this machine's own "
                                                 "(behind a department's web server: https://lab.example.edu)");
    sub->add_option("--state", o.stateDir, "where the class is kept: the database, hand-ins, grading (default "
                                           "./glimmer-serve-state)");
    sub->add_option("--page", o.pageDir, "the page's build (index.html, glimmer-web.js, glimmer-web.wasm); default: "
                                         "$GLIMMER_PAGE, or found beside Glimmer's data");
    sub->add_option("--jobs", o.jobs, "grading workers (batch --jobs; default 2)");
    sub->add_option("--overrides", o.overrides, "the teacher's scores and comments, as for batch --reference");
}

int runServe(const ServeOptions& o) {
    auto fail = [](const std::string& what) {
        std::cerr << "glimmer: error: serve: " << sanitizeForTerminal(what, false) << "\n";
        return kExitUsage;
    };
    LessonFolder lesson;
    std::string why;
    if (!readLessonFolder(o.lessonDir, lesson, why)) return fail(why);
    if (std::string e; !checkRegularFile(o.solution, e)) return fail(fmt::format("--solution {}: {}", o.solution, e));
    if (inside(o.solution, o.lessonDir))
        return fail(fmt::format("--solution {} is inside the lesson folder {}, which is served to every student: keep "
                                "the solution outside it", o.solution, o.lessonDir));
    {  // the solution must plan, or every hand-in would fail to grade
        Diagnostics diags;
        LoadedScript solution;
        if (!loadScript(o.solution, PlanOptions{}, diags, solution) || diags.errorCount() > 0) {
            printDiagnostics(diags, solution.sources, std::cerr);
            return fail(fmt::format("--solution {}: the solution has errors", o.solution));
        }
    }
    const std::string page = findPage(o.pageDir);
    if (page.empty())
        return fail("no page to serve: build it (emcmake cmake -S . -B build-web && cmake --build build-web) and give "
                    "--page build-web/src/web");
    std::vector<std::string> roster;
    if (!o.roster.empty()) {
        std::string text;
        if (!readRegularFile(o.roster, 1 << 20, text, why)) return fail(fmt::format("--roster {}: {}", o.roster, why));
        if (!parseRoster(text, o.roster, roster, why)) {
            for (std::size_t at = 0; at < why.size();) {  // line by line: the message, the source line, the caret
                const std::size_t end = std::min(why.find('\n', at), why.size());
                std::cerr << sanitizeForTerminal(why.substr(at, end - at), false) << "\n";
                at = end + 1;
            }
            return kExitUsage;
        }
    }
    std::error_code ec;
    fs::create_directories(o.stateDir, ec);
    if (ec) return fail(fmt::format("--state {}: cannot make it: {}", o.stateDir, ec.message()));
    ClassStore store;
    if (!store.open((fs::path(o.stateDir) / "class.sqlite").string(), why)) return fail(o.stateDir + ": " + why);

    // Ctrl-C and SIGTERM end the server in order: blocked here, waited for by one thread.
    sigset_t stopSignals;
    sigemptyset(&stopSignals);
    sigaddset(&stopSignals, SIGINT);
    sigaddset(&stopSignals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stopSignals, nullptr);
    signal(SIGPIPE, SIG_IGN);

    GraderSettings gs;
    gs.glimmer = fs::read_symlink("/proc/self/exe", ec).string();
    gs.solution = fs::absolute(o.solution).string();
    gs.stateDir = fs::absolute(o.stateDir).string();
    gs.batchArgs = {"--jobs", std::to_string(std::max(1, o.jobs))};
    if (!o.overrides.empty()) gs.batchArgs.insert(gs.batchArgs.end(), {"--overrides", fs::absolute(o.overrides).string()});
    HandInGrader grader(store, lesson, gs);
    ServerSettings ss;
    ss.host = o.host;
    ss.port = o.port;
    ss.pageDir = page;
    ss.rosterOnly = !roster.empty();
    ClassServer server(store, lesson, grader, ss);
    if (!server.bind(why)) return fail(why);
    const std::string address = !o.publicAddress.empty() ? o.publicAddress
                                                         : fmt::format("http://{}:{}", outwardAddress(), server.port());
    // The address is known only once bound (port 0): the server reads it from here.
    server.setPublicAddress(address);

    std::string links = "name,link\n";
    for (const std::string& name : roster) {
        const auto s = store.studentNamed(name, true);
        std::string quoted = name;
        for (std::size_t at = 0; (at = quoted.find('"', at)) != std::string::npos; at += 2) quoted.insert(at, "\"");
        links += fmt::format("\"{}\",{}/join/{}\n", quoted, address, s->token);
    }
    const std::string linksFile = (fs::path(o.stateDir) / "links.csv").string();
    if (!roster.empty() && !writeBytesReplacing(linksFile, links.data(), links.size(), why)) return fail(why);

    std::cout << qrForTerminal(address + "/join");
    std::cout << fmt::format("glimmer serve: {} ({} scripts) on {} (port {})\n", lesson.name, lesson.scripts.size(),
                             address, server.port());
    if (roster.empty())
        std::cout << fmt::format("  students: open {}/join, class code {}\n", address, store.classCode());
    else
        std::cout << fmt::format("  students: each their own link, {} of them in {}\n", roster.size(), linksFile);
    std::cout << fmt::format("  teacher:  {}/teacher/{}\n", address, store.teacherToken());
    std::cout << fmt::format("  kept in:  {} (Ctrl-C stops; starting again continues the class)\n", o.stateDir);
    std::cout.flush();

    grader.start();
    std::thread waiter([&] {
        int sig = 0;
        sigwait(&stopSignals, &sig);
        server.stop();
    });
    server.run();
    std::cout << "glimmer serve: stopping: grading cut off now is graded again at the next start\n";
    grader.stop();
    pthread_kill(waiter.native_handle(), SIGTERM);  // when run() ended another way, the waiter is still waiting
    waiter.join();
    return kExitOk;
}

}  // namespace glimmer
