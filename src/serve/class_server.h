// `glimmer serve`'s HTTP side (Debian's cpp-httplib): the page and the
// lesson to the class, each student's saves and hand-ins into the store,
// the teacher's grid. No GL and no grading here: the store keeps, the
// grader grades, the page draws (in each student's browser).
//
// Who may read what (issue 41, item 5):
//   - a student is whoever holds their token: the cookie set by their link
//     (/join/TOKEN) or by joining with the class code; every /api/ call of
//     theirs reads and writes only their own work and feedback;
//   - the teacher holds the teacher token (/teacher/TOKEN sets its cookie);
//   - anyone may fetch the page's own files (the WebAssembly, the scripts):
//     they hold nothing of a student's; the solution is never served (it
//     lives outside the lesson folder: serve_command.cpp checks);
//   - cookies are HttpOnly, SameSite=Lax; a POST must carry JSON (a form on
//     another site cannot), and every body and rate is bounded.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "serve/class_store.h"
#include "serve/hand_in_grader.h"
#include "serve/lesson_folder.h"

namespace glimmer {

struct ServerSettings {
    std::string host = "0.0.0.0";
    int port = 8080;                 // 0: any free port (tests)
    std::string publicAddress;       // "http://192.168.1.20:8080": what students type (the join link, the QR)
    std::string pageDir;             // the page's files (index.html, glimmer-web.js, .wasm, editor/)
    bool rosterOnly = false;         // a roster was given: students join by their links only
    int threads = 256;               // the HTTP worker pool (each open connection holds one)
};

class ClassServer {
public:
    ClassServer(ClassStore& store, const LessonFolder& lesson, HandInGrader& grader, ServerSettings settings);
    ~ClassServer();
    // Reads the page's files and binds the port; false with `error`.
    bool bind(std::string& error);
    int port() const;
    void setPublicAddress(const std::string& address);
    void run();   // serves until stop()
    void stop();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace glimmer
