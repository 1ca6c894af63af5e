#include "serve/class_server.h"

#include <httplib.h>

#include <filesystem>
#include <fmt/format.h>

#include "grade/grade_report.h"  // htmlEscape: one escaping for every page Glimmer writes
#include "serve/join_qr.h"
#include "serve/request_limits.h"
#include "serve/serve_assets.h"
#include "util/json.h"
#include "util/read_file.h"

namespace fs = std::filesystem;

namespace glimmer {
namespace {

// Bounds of what one request may carry (issue 41: every request bounded).
constexpr std::size_t kMaxBodyBytes = std::size_t(4) << 20;       // the server refuses larger before reading them
constexpr std::size_t kMaxSaveBytes = std::size_t(2) << 20;       // one save's files together
constexpr std::size_t kMaxFileBytes = std::size_t(1) << 20;       // one file of a save
constexpr std::size_t kMaxStatusBytes = 2000;                     // the page's verdict line
constexpr std::size_t kMaxThumbnailBytes = 96 * 1024;             // a 160-pixel PNG
constexpr std::size_t kMaxSetsBytes = 4000;                       // a follow-me push
constexpr std::size_t kMaxNameBytes = 60;                         // a name typed to join
constexpr std::size_t kMaxPageFiles = 500, kMaxPageBytes = std::size_t(96) << 20;

const char* kPageCsp = "script-src 'self' 'wasm-unsafe-eval'; object-src 'none'; base-uri 'none'; frame-ancestors 'none'";
// A feedback page is batch's own HTML: pictures as data: URLs and its style, never a script.
const char* kFeedbackCsp = "default-src 'none'; img-src data:; style-src 'unsafe-inline'; frame-ancestors 'none'";

std::string contentType(const std::string& path) {
    static const std::pair<const char*, const char*> kTypes[] = {
        {".html", "text/html; charset=utf-8"}, {".js", "text/javascript; charset=utf-8"},
        {".mjs", "text/javascript; charset=utf-8"}, {".css", "text/css; charset=utf-8"},
        {".wasm", "application/wasm"}, {".json", "application/json"}, {".png", "image/png"},
        {".svg", "image/svg+xml"}, {".ttf", "font/ttf"}, {".data", "application/octet-stream"},
        {".txt", "text/plain; charset=utf-8"}};
    for (const auto& [ext, type] : kTypes)
        if (path.ends_with(ext)) return type;
    return "application/octet-stream";
}

// Compares without stopping at the first difference (a token's prefix is not
// found by timing).
bool sameSecret(const std::string& a, const std::string& b) {
    if (a.size() != b.size() || a.empty()) return false;
    unsigned char d = 0;
    for (std::size_t i = 0; i < a.size(); ++i) d |= static_cast<unsigned char>(a[i] ^ b[i]);
    return d == 0;
}

std::string cookie(const httplib::Request& req, const std::string& name) {
    const std::string all = req.get_header_value("Cookie");
    std::size_t at = 0;
    while (at < all.size()) {
        std::size_t end = all.find(';', at);
        if (end == std::string::npos) end = all.size();
        std::string part = all.substr(at, end - at);
        while (!part.empty() && part[0] == ' ') part.erase(0, 1);
        if (part.starts_with(name + "=")) return part.substr(name.size() + 1);
        at = end + 1;
    }
    return "";
}

std::string setCookie(const std::string& name, const std::string& value) {
    return fmt::format("{}={}; Path=/; HttpOnly; SameSite=Lax; Max-Age=31536000", name, value);
}

void say(httplib::Response& res, int status, const std::string& message) {
    res.status = status;
    res.set_content(jsonLine(Json{{"error", message}}), "application/json");
}

// A small page of the server's own (joining, a refusal), escaped text only.
std::string plainPage(const std::string& title, const std::string& bodyHtml) {
    return fmt::format("<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>{}</title>"
                       "<meta name=\"viewport\" content=\"width=device-width\">"
                       "<style>body{{font:16px/1.5 system-ui,sans-serif;background:#1e1f22;color:#ddd;margin:2em auto;"
                       "max-width:36em;padding:0 1em}}input,button{{font:inherit}}a{{color:#8bf}}.bad{{color:#e88}}"
                       "</style></head><body>{}</body></html>",
                       htmlEscape(title), bodyHtml);
}

Json handInJson(const HandIn& h, bool hasFeedback) {
    return Json{{"id", h.id},       {"at", jsonNumber(h.at)}, {"state", h.state}, {"verdict", h.verdict},
                {"score", h.score}, {"notes", h.notes},       {"feedback", hasFeedback}};
}

}  // namespace

struct ClassServer::Impl {
    ClassStore& store;
    const LessonFolder& lesson;
    HandInGrader& grader;
    ServerSettings settings;
    httplib::Server http;
    std::map<std::string, std::string> pageFiles;  // "/glimmer-web.js" -> bytes
    RequestLimits byToken{20, 60};                  // a page saves every second or so, polls every two
    RequestLimits byAddress{20, 200};               // joining, links: a lab's machines share no address
    std::string teacherToken, classCode;
    int boundPort = 0;

    Impl(ClassStore& s, const LessonFolder& l, HandInGrader& g, ServerSettings st)
        : store(s), lesson(l), grader(g), settings(std::move(st)) {}

    std::optional<Student> student(const httplib::Request& req) {
        const std::string token = cookie(req, "glimmer_student");
        if (token.size() != 32) return std::nullopt;
        return store.studentByToken(token);
    }
    bool teacher(const httplib::Request& req) { return sameSecret(cookie(req, "glimmer_teacher"), teacherToken); }

    bool readPage(std::string& error) {
        std::error_code ec;
        if (!fs::is_regular_file(fs::path(settings.pageDir) / "index.html", ec)) {
            error = fmt::format("{}: no index.html: not the page's folder (the web build's src/web, "
                                "or give --page)", settings.pageDir);
            return false;
        }
        std::size_t bytes = 0;
        fs::recursive_directory_iterator it(settings.pageDir, ec), end;
        for (; !ec && it != end; it.increment(ec)) {
            if (it->is_directory(ec) && it->path().filename() == "CMakeFiles") {
                it.disable_recursion_pending();
                continue;
            }
            if (it->is_symlink(ec) || !it->is_regular_file(ec)) continue;
            const std::string rel = fs::relative(it->path(), settings.pageDir, ec).generic_string();
            // And the bundled lesson's kept translations, which the page asks
            // for beside it (web/web_translations.cpp: its first picture
            // without glslang).
            static const char* kServed[] = {".html", ".js", ".wasm", ".css", ".data", ".ttf", "lesson-translations.txt"};
            if (std::none_of(std::begin(kServed), std::end(kServed), [&](const char* e) { return rel.ends_with(e); }))
                continue;
            std::string text, why;
            if (pageFiles.size() >= kMaxPageFiles || !readRegularFile(it->path().string(), kMaxPageBytes, text, why) ||
                (bytes += text.size()) > kMaxPageBytes) {
                error = fmt::format("{}: cannot read the page's files{}", settings.pageDir, why.empty() ? "" : ": " + why);
                return false;
            }
            pageFiles["/" + rel] = std::move(text);
        }
        return !ec;
    }

    // The page for a student: the lesson from /lesson.json (theirs), the
    // serve side (glimmer-serve.js) loaded before the page's own script.
    std::string studentPage(const Student& s) {
        std::string page = pageFiles["/index.html"];
        // The lesson's address names the student (the server reads only the cookie): the page keeps its
        // drafts and sliders per address, and two students on one lab machine must not share them.
        const std::string metas = fmt::format("<meta name=\"glimmer-lesson\" content=\"lesson.json?for={}\">\n"
                                              "<meta name=\"glimmer-serve\" content=\"{}\">\n",
                                              htmlEscape(s.folder), htmlEscape(s.name));
        if (const auto at = page.find("<title>"); at != std::string::npos) page.insert(at, metas);
        if (const auto at = page.find("<script src=\"glimmer-page.js\">"); at != std::string::npos)
            page.insert(at, "<script src=\"glimmer-serve.js\"></script>\n");
        return page;
    }

    void routes();
    void studentRoutes();
    void teacherRoutes();
};

void ClassServer::Impl::routes() {
    // Before any handler: the rate of API calls, per token (or address).
    http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
        res.set_header("X-Content-Type-Options", "nosniff");
        res.set_header("Referrer-Policy", "no-referrer");
        const bool api = req.path.starts_with("/api/") || req.path.starts_with("/join") || req.path.starts_with("/teacher");
        if (!api) return httplib::Server::HandlerResponse::Unhandled;
        // A token counts only when it is one: made-up cookies are the address's, or a client could
        // dodge its limit with a new cookie a request.
        std::string key;
        if (teacher(req)) key = "teacher";
        else if (const auto s = student(req)) key = s->token;
        const bool ok = key.empty() ? byAddress.allow(req.remote_addr) : byToken.allow(key);
        if (ok) return httplib::Server::HandlerResponse::Unhandled;
        res.set_header("Retry-After", "1");
        say(res, 429, "too many requests: wait a moment");
        return httplib::Server::HandlerResponse::Handled;
    });
    http.Get("/glimmer-serve.js", [](const httplib::Request&, httplib::Response& res) {
        res.set_content(kServePageScript, "text/javascript; charset=utf-8");
    });
    http.Get("/glimmer-teacher.js", [](const httplib::Request&, httplib::Response& res) {
        res.set_content(kTeacherPageScript, "text/javascript; charset=utf-8");
    });
    http.Get("/", [this](const httplib::Request& req, httplib::Response& res) {
        const auto s = student(req);
        if (!s) {
            res.set_redirect("/join", 303);
            return;
        }
        res.set_header("Content-Security-Policy", kPageCsp);
        res.set_header("Cache-Control", "no-store");
        res.set_content(studentPage(*s), "text/html; charset=utf-8");
    });
    // Joining: a student's own link, or the class code and a name not taken.
    http.Get(R"(/join/([0-9a-f]{32}))", [this](const httplib::Request& req, httplib::Response& res) {
        const auto s = store.studentByToken(req.matches[1]);
        if (!s) {
            res.status = 404;
            res.set_content(plainPage("Not a link of this class",
                                      "<p class=bad>This link is not one of this class's. Ask your teacher for yours.</p>"),
                            "text/html; charset=utf-8");
            return;
        }
        res.set_header("Set-Cookie", setCookie("glimmer_student", s->token));
        res.set_redirect("/", 303);
    });
    http.Get("/join", [this](const httplib::Request&, httplib::Response& res) {
        res.set_header("Content-Security-Policy", "default-src 'none'; style-src 'unsafe-inline'; form-action 'self'");
        res.set_content(
            plainPage("Join the lab",
                      settings.rosterOnly
                          ? "<h1>Join the lab</h1><p>This class joins by each student's own link: ask your teacher for yours.</p>"
                          : "<h1>Join the lab</h1><form method=post action=/join><p><label>Class code "
                            "<input name=code autocomplete=off required maxlength=9></label></p><p><label>Your name "
                            "<input name=name required maxlength=60></label></p><p><button>Join</button></p></form>"),
            "text/html; charset=utf-8");
    });
    http.Post("/join", [this](const httplib::Request& req, httplib::Response& res) {
        auto refuse = [&](int status, const std::string& why) {
            res.status = status;
            res.set_content(plainPage("Cannot join", "<p class=bad>" + htmlEscape(why) + "</p><p><a href=/join>Back</a></p>"),
                            "text/html; charset=utf-8");
        };
        if (settings.rosterOnly) return refuse(403, "This class joins by each student's own link: ask your teacher for yours.");
        std::string code = req.get_param_value("code"), name = req.get_param_value("name");
        for (auto& c : code) c = char(std::toupper(static_cast<unsigned char>(c)));
        if (!sameSecret(code, classCode)) return refuse(403, "That is not this class's code.");
        while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
        while (!name.empty() && std::isspace(static_cast<unsigned char>(name.front()))) name.erase(0, 1);
        const bool printable = std::all_of(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) >= 32 && c != 127; });
        if (name.empty() || name.size() > kMaxNameBytes || !printable)
            return refuse(400, fmt::format("A name is 1 to {} characters.", kMaxNameBytes));
        // A name already in the class is theirs: joining by it again would hand over their work.
        if (store.studentNamed(name, false))
            return refuse(409, "That name is taken in this class. If it is yours, ask your teacher for your link.");
        const auto s = store.studentNamed(name, true);
        res.set_header("Set-Cookie", setCookie("glimmer_student", s->token));
        res.set_redirect("/", 303);
    });
    studentRoutes();
    teacherRoutes();
    // The page's own files: public, the same for everyone. Last: httplib takes the
    // first route that matches, and this one matches every plain path.
    http.Get(R"(/([A-Za-z0-9_./-]+))", [this](const httplib::Request& req, httplib::Response& res) {
        const auto it = pageFiles.find(req.path);
        if (it == pageFiles.end() || req.path == "/index.html") {
            res.status = 404;
            res.set_content(plainPage("Not here", "<p>Nothing here.</p>"), "text/html; charset=utf-8");
            return;
        }
        res.set_header("Cache-Control", "max-age=300");
        res.set_content(it->second, contentType(req.path));
    });
}

void ClassServer::Impl::studentRoutes() {
    http.Get("/lesson.json", [this](const httplib::Request& req, httplib::Response& res) {
        const auto s = student(req);
        if (!s) return say(res, 403, "not signed in: open your link again");
        res.set_header("Cache-Control", "no-store");
        res.set_content(lessonJson(lesson, store.filesAt(s->id), lesson.name + " (" + s->folder + ")"), "application/json");
    });
    // A save: {"files": {path: text}, "status": "..."}; the version after it.
    http.Post("/api/save", [this](const httplib::Request& req, httplib::Response& res) {
        const auto s = student(req);
        if (!s) return say(res, 403, "not signed in: open your link again");
        if (req.get_header_value("Content-Type").rfind("application/json", 0) != 0)
            return say(res, 415, "a save is JSON");
        if (req.body.size() > kMaxSaveBytes) return say(res, 413, "a save holds at most 2 MiB");
        Json body = Json::parse(req.body, nullptr, false);
        if (body.is_discarded() || !body.is_object() || !body.contains("files") || !body["files"].is_object())
            return say(res, 400, "a save is {\"files\": {\"path\": \"text\"}}");
        FileTexts files;
        for (const auto& [path, text] : body["files"].items()) {
            if (!text.is_string()) return say(res, 400, "a file's text is a string");
            if (!lesson.editable(path)) return say(res, 400, fmt::format("{} is not a file of the lesson", path));
            if (text.get_ref<const std::string&>().size() > kMaxFileBytes) return say(res, 413, path + " is larger than 1 MiB");
            files[path] = text.get<std::string>();
        }
        std::string status = body.value("status", "");
        if (status.size() > kMaxStatusBytes) status.resize(kMaxStatusBytes);
        const std::int64_t version = store.save(s->id, files, status);
        res.set_content(jsonLine(Json{{"version", version}}), "application/json");
    });
    http.Post("/api/handin", [this](const httplib::Request& req, httplib::Response& res) {
        const auto s = student(req);
        if (!s) return say(res, 403, "not signed in: open your link again");
        if (req.get_header_value("Content-Type").rfind("application/json", 0) != 0)
            return say(res, 415, "a hand-in is asked with JSON");
        const std::int64_t id = store.handIn(s->id);
        grader.wake();
        res.set_content(jsonLine(Json{{"handin", id}}), "application/json");
    });
    http.Get("/api/me", [this](const httplib::Request& req, httplib::Response& res) {
        const auto s = student(req);
        if (!s) return say(res, 403, "not signed in: open your link again");
        Json handins = Json::array();
        for (const HandIn& h : store.handIns(s->id)) handins.push_back(handInJson(h, !grader.feedbackFile(h.id).empty()));
        const auto [followId, sets] = store.lastFollow();
        res.set_header("Cache-Control", "no-store");
        res.set_content(jsonLine(Json{{"name", s->name},
                                      {"version", store.latestVersion(s->id)},
                                      {"handins", handins},
                                      {"follow", Json{{"id", followId}, {"sets", sets}}}}),
                        "application/json");
    });
    http.Get(R"(/api/feedback/(\d{1,18}))", [this](const httplib::Request& req, httplib::Response& res) {
        const auto h = store.handInById(std::stoll(req.matches[1]));
        const auto s = student(req);
        // The owner, or the teacher; anyone else is told nothing about whether it exists.
        if (!h || !(teacher(req) || (s && s->id == h->student))) return say(res, 404, "no such feedback");
        std::string page, why;
        const std::string file = grader.feedbackFile(h->id);
        if (file.empty() || !readRegularFile(file, std::size_t(64) << 20, page, why)) return say(res, 404, "no feedback yet");
        res.set_header("Content-Security-Policy", kFeedbackCsp);
        res.set_content(page, "text/html; charset=utf-8");
    });
    http.Post("/api/thumbnail", [this](const httplib::Request& req, httplib::Response& res) {
        const auto s = student(req);
        if (!s) return say(res, 403, "not signed in: open your link again");
        if (req.get_header_value("Content-Type") != "image/png") return say(res, 415, "a thumbnail is a PNG");
        static const std::string kSignature = "\x89PNG\r\n\x1a\n";
        if (req.body.size() > kMaxThumbnailBytes || !req.body.starts_with(kSignature))
            return say(res, 400, "a thumbnail is a PNG of at most 96 KiB");
        store.setThumbnail(s->id, req.body);
        res.set_content("{}", "application/json");
    });
}

void ClassServer::Impl::teacherRoutes() {
    http.Get(R"(/teacher/([0-9a-f]{32}))", [this](const httplib::Request& req, httplib::Response& res) {
        if (!sameSecret(req.matches[1], teacherToken)) {
            res.status = 404;
            res.set_content(plainPage("Not here", "<p>Nothing here.</p>"), "text/html; charset=utf-8");
            return;
        }
        res.set_header("Set-Cookie", setCookie("glimmer_teacher", teacherToken));
        res.set_redirect("/teacher", 303);
    });
    http.Get("/teacher", [this](const httplib::Request& req, httplib::Response& res) {
        if (!teacher(req)) {
            res.status = 403;
            res.set_content(plainPage("Teacher only", "<p>Open the teacher's link glimmer serve printed.</p>"),
                            "text/html; charset=utf-8");
            return;
        }
        res.set_header("Content-Security-Policy", "default-src 'none'; script-src 'self'; style-src 'unsafe-inline'; "
                                                  "img-src 'self' data:; connect-src 'self'; frame-ancestors 'none'");
        res.set_header("Cache-Control", "no-store");
        res.set_content(kTeacherPage, "text/html; charset=utf-8");
    });
    http.Get("/api/class", [this](const httplib::Request& req, httplib::Response& res) {
        if (!teacher(req)) return say(res, 403, "teacher only");
        Json students = Json::array();
        for (const StudentSummary& s : store.summaries()) {
            Json row = {{"id", s.student.id},          {"name", s.student.name},
                        {"folder", s.student.folder},  {"link", settings.publicAddress + "/join/" + s.student.token},
                        {"versions", s.versions},       {"lastSave", jsonNumber(s.lastSave)},
                        {"status", s.status},           {"handins", s.handIns},
                        {"thumbnail", s.hasThumbnail}};
            if (s.lastHandIn) row["last"] = handInJson(*s.lastHandIn, !grader.feedbackFile(s.lastHandIn->id).empty());
            students.push_back(row);
        }
        const auto [followId, sets] = store.lastFollow();
        res.set_header("Cache-Control", "no-store");
        res.set_content(jsonLine(Json{{"address", settings.publicAddress + "/join"},
                                      {"code", settings.rosterOnly ? "" : classCode},
                                      {"now", jsonNumber(nowSeconds())},
                                      {"follow", sets},
                                      {"followId", followId},
                                      {"students", students}}),
                        "application/json");
    });
    http.Get(R"(/api/thumbnail/(\d{1,18}))", [this](const httplib::Request& req, httplib::Response& res) {
        if (!teacher(req)) return say(res, 403, "teacher only");
        const std::string png = store.thumbnail(std::stoll(req.matches[1]));
        if (png.empty()) return say(res, 404, "no picture yet");
        res.set_header("Cache-Control", "no-store");
        res.set_content(png, "image/png");
    });
    // One student's work, read-only: the files they changed, as text.
    http.Get(R"(/teacher/work/(\d{1,18}))", [this](const httplib::Request& req, httplib::Response& res) {
        if (!teacher(req)) return say(res, 403, "teacher only");
        const auto s = store.studentById(std::stoll(req.matches[1]));
        if (!s) return say(res, 404, "no such student");
        std::string body = fmt::format("<h1>{}</h1><p>The files {} changed (version {}); the rest are the lesson's.</p>",
                                       htmlEscape(s->name), htmlEscape(s->name), store.latestVersion(s->id));
        for (const auto& [path, text] : store.filesAt(s->id))
            body += fmt::format("<h2>{}</h2><pre style=\"background:#111;padding:.6em;overflow:auto\">{}</pre>",
                                htmlEscape(path), htmlEscape(text));
        res.set_header("Content-Security-Policy", "default-src 'none'; style-src 'unsafe-inline'");
        res.set_content(plainPage(s->name, body), "text/html; charset=utf-8");
    });
    http.Post("/api/follow", [this](const httplib::Request& req, httplib::Response& res) {
        if (!teacher(req)) return say(res, 403, "teacher only");
        if (req.get_header_value("Content-Type").rfind("application/json", 0) != 0) return say(res, 415, "JSON only");
        Json body = Json::parse(req.body, nullptr, false);
        if (body.is_discarded() || !body.is_object() || !body.contains("sets") || !body["sets"].is_string() ||
            body["sets"].get_ref<const std::string&>().size() > kMaxSetsBytes)
            return say(res, 400, "a push is {\"sets\": \"uAdd=2;uHalfSize=5\"}");
        res.set_content(jsonLine(Json{{"id", store.follow(body["sets"].get<std::string>())}}), "application/json");
    });
    http.Get("/api/qr.svg", [this](const httplib::Request& req, httplib::Response& res) {
        if (!teacher(req)) return say(res, 403, "teacher only");
        res.set_content(qrSvg(settings.publicAddress + "/join"), "image/svg+xml");
    });
    // The export: the graded folder batch --reference wrote.
    http.Get(R"(/teacher/export/(grades\.csv|report\.html|grades\.jsonl))", [this](const httplib::Request& req,
                                                                                 httplib::Response& res) {
        if (!teacher(req)) return say(res, 403, "teacher only");
        std::string text, why;
        if (!readRegularFile((fs::path(grader.gradedDir()) / req.matches[1].str()).string(), std::size_t(1) << 30, text, why))
            return say(res, 404, "nothing graded yet");
        if (req.matches[1].str().ends_with(".html")) res.set_header("Content-Security-Policy", kFeedbackCsp);
        res.set_content(text, contentType(req.matches[1].str()) == "application/octet-stream"
                                  ? "text/plain; charset=utf-8" : contentType(req.matches[1].str()));
    });
}

ClassServer::ClassServer(ClassStore& store, const LessonFolder& lesson, HandInGrader& grader, ServerSettings settings)
    : impl_(std::make_unique<Impl>(store, lesson, grader, std::move(settings))) {}

ClassServer::~ClassServer() = default;

bool ClassServer::bind(std::string& error) {
    Impl& m = *impl_;
    if (!m.readPage(error)) return false;
    m.teacherToken = m.store.teacherToken();
    m.classCode = m.store.classCode();
    const int threads = m.settings.threads;
    m.http.new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
    m.http.set_payload_max_length(kMaxBodyBytes);
    m.http.set_keep_alive_timeout(2);
    m.http.set_read_timeout(10);
    m.http.set_write_timeout(30);
    m.routes();
    if (m.settings.port == 0) {
        m.boundPort = m.http.bind_to_any_port(m.settings.host);
    } else if (m.http.bind_to_port(m.settings.host, m.settings.port)) {
        m.boundPort = m.settings.port;
    }
    if (m.boundPort <= 0) {
        error = fmt::format("cannot listen on {}:{} (in use, or not this machine's address)", m.settings.host,
                            m.settings.port);
        return false;
    }
    return true;
}

int ClassServer::port() const { return impl_->boundPort; }
void ClassServer::setPublicAddress(const std::string& address) { impl_->settings.publicAddress = address; }
void ClassServer::run() { impl_->http.listen_after_bind(); }
void ClassServer::stop() { impl_->http.stop(); }

}  // namespace glimmer
