// Helpers for the plan tests: a throw-away project folder (scripts/,
// shaders/, textures/) holding dummy files, a parse-and-plan in one call, and
// compact renderings of diagnostics and matrices.
#pragma once
#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "lang/diagnostics.h"
#include "lang/parser.h"
#include "plan/plan.h"

namespace glimmer::test {

namespace fs = std::filesystem;

// A project folder under the system temp folder, removed when done.
class TempProject {
public:
    TempProject() {
        static std::atomic<int> counter{0};
        root_ = fs::temp_directory_path() /
                ("glimmer_plan_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::remove_all(root_);
        fs::create_directories(root_ / "scripts");
        fs::create_directories(root_ / "shaders");
        fs::create_directories(root_ / "textures");
        // The plan only finds files; it never opens them, so any content will do.
        touch("shaders/a.vert");
        touch("shaders/a.frag");
        touch("shaders/b.frag");
        touch("textures/img.bmp");
        touch("textures/other.bmp");
        touch("scripts/model.obj");
    }
    ~TempProject() {
        std::error_code ec;
        fs::remove_all(root_, ec);
    }
    TempProject(const TempProject&) = delete;
    TempProject& operator=(const TempProject&) = delete;

    void touch(const std::string& rel) {
        fs::create_directories((root_ / rel).parent_path());
        std::ofstream(root_ / rel) << "dummy\n";
    }
    fs::path root() const { return root_; }
    std::string script() const { return (root_ / "scripts" / "t.glib").string(); }
    std::string path(const std::string& rel) const { return (root_ / rel).lexically_normal().string(); }

private:
    fs::path root_;
};

struct Planned {
    Script script;
    Diagnostics diags;
    Plan plan;
};

inline Planned plan(const std::string& file, const std::string& text, const PlanOptions& options = {}) {
    Planned p;
    p.script = parseScript(file, text, p.diags);
    p.plan = buildPlan(p.script, options, p.diags);
    return p;
}

// "line:col: severity: message"
inline std::vector<std::string> messages(const Diagnostics& d) {
    std::vector<std::string> out;
    for (const Diagnostic& x : d.all())
        out.push_back(std::to_string(x.loc.line) + ":" + std::to_string(x.loc.col) + ": " +
                      severityName(x.severity) + ": " + x.message);
    return out;
}

// Only the messages of the given severity, without location.
inline std::vector<std::string> texts(const Diagnostics& d, Severity s) {
    std::vector<std::string> out;
    for (const Diagnostic& x : d.all())
        if (x.severity == s) out.push_back(x.message);
    return out;
}
inline std::vector<std::string> errors(const Diagnostics& d) { return texts(d, Severity::Error); }
inline std::vector<std::string> warnings(const Diagnostics& d) { return texts(d, Severity::Warning); }

inline ::testing::AssertionResult matNear(const glm::mat4& actual, const glm::mat4& expected, float eps = 1e-5f) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (std::abs(actual[c][r] - expected[c][r]) > eps) {
                std::string s = "matrices differ at [" + std::to_string(c) + "][" + std::to_string(r) +
                                "]: " + std::to_string(actual[c][r]) + " vs " + std::to_string(expected[c][r]) +
                                "\nactual:  ";
                for (int i = 0; i < 4; ++i)
                    for (int j = 0; j < 4; ++j) s += std::to_string(actual[i][j]) + " ";
                s += "\nexpected: ";
                for (int i = 0; i < 4; ++i)
                    for (int j = 0; j < 4; ++j) s += std::to_string(expected[i][j]) + " ";
                return ::testing::AssertionFailure() << s;
            }
    return ::testing::AssertionSuccess();
}

// The draw steps of a pass, in order.
inline std::vector<const Draw*> draws(const Pass& p) {
    std::vector<const Draw*> out;
    for (const Step& s : p.steps)
        if (s.kind == Step::Kind::Draw) out.push_back(&s.draw);
    return out;
}

}  // namespace glimmer::test
