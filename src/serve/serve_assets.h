// The files of `glimmer serve`'s own pages, built into the program (from
// src/serve/page/ by src/serve/CMakeLists.txt): the server needs nothing
// beside itself but the page's build and the lesson.
#pragma once

namespace glimmer {

extern const char* const kServePageScript;    // page/glimmer-serve.js: the student's page's serve side
extern const char* const kTeacherPage;        // page/teacher.html
extern const char* const kTeacherPageScript;  // page/glimmer-teacher.js

}  // namespace glimmer
