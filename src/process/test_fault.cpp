#include "process/test_fault.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "gl/renderer.h"

namespace glimmer {

std::optional<TestFault> testFaultAsked() {
    const char* spec = std::getenv("GLIMMER_TEST_FAULT");
    if (!spec) return std::nullopt;
    const std::string text = spec;
    const size_t a = text.find(':'), b = a == std::string::npos ? a : text.find(':', a + 1);
    if (b == std::string::npos || b == a + 1) return std::nullopt;
    return TestFault{text.substr(0, a), text.substr(a + 1, b - a - 1), text.substr(b + 1)};
}

bool takesTestFault(const TestFault& f) {
    if (f.marker.empty()) return true;
    const int fd = ::open(f.marker.c_str(), O_CREAT | O_EXCL | O_WRONLY, 0600);
    if (fd < 0) return false;  // another drawing had it
    ::close(fd);
    return true;
}

namespace {

// A "reset", "zeros" or "broken" fault for `script`'s picture, if asked:
// `failure` set as contextFailure would, or `picture` zeroed.
void injectTestFault(const std::string& script, Image& picture, std::string& failure) {
    static bool broken = false;  // this process took a "broken" fault
    const std::optional<TestFault> f = testFaultAsked();
    if (!f || script.find(f->part) == std::string::npos || f->kind == "stuck") return;
    if (!(f->kind == "broken" && broken) && !takesTestFault(*f)) return;
    if (f->kind == "reset") failure = "the GPU was reset by another process while this script drew (GLIMMER_TEST_FAULT)";
    else if (f->kind == "zeros" || f->kind == "broken") std::fill(picture.u8.begin(), picture.u8.end(), std::uint8_t(0));
    broken = broken || f->kind == "broken";
}

}  // namespace

std::string pictureFailure(const Renderer& renderer, const std::string& script, Image& picture, std::string* refused) {
    std::string failure = renderer.contextFailure(refused);
    injectTestFault(script, picture, failure);
    return failure;
}

}  // namespace glimmer
