// A context that reports an error for ever, as a lost one may after a GPU
// reset (GL_CONTEXT_LOST from every glGetError): the renderer is still
// made, and loading a script ends with an error that says the context was
// lost, not a hang in a loop that waits for the error flag to clear.
#include <fstream>
#include <string_view>

#include <gtest/gtest.h>

#include "common/test_folder.h"
#include "gl/gl_api.h"
#include "render_harness.h"

using namespace glimmer;
using namespace glimmer::testing;

namespace {

constexpr GLenum kContextLost = 0x0507;
GLenum GLAPIENTRY lostForEver() { return kContextLost; }

std::string messages(const Diagnostics& diags) {
    std::string out;
    for (const auto& d : diags.all()) out += d.message + "\n";
    return out;
}

TEST(LostContext, LoadingEndsWithAnErrorNotAHang) {
    TestFolder dir("glimmer_lost_context_");
    std::ofstream(dir.path / "s.glib") << "Background 1 0 0\nClear\n";
    for (const auto& backend : testBackends()) {
        SCOPED_TRACE(backend);
        Diagnostics diags;
        LoadedScript loaded;
        ASSERT_TRUE(loadScript((dir.path / "s.glib").string(), {}, diags, loaded)) << messages(diags);
        BackendChoice choice;
        ASSERT_TRUE(parseBackend(backend, choice));
        std::string why;
        auto context = createContext(choice, why);
        ASSERT_TRUE(context) << why;
        auto renderer = Renderer::create(
            [&](const char* name) -> void* {
                if (std::string_view(name) == "glGetError") return reinterpret_cast<void*>(&lostForEver);
                return context->getProcAddress(name);
            },
            why);
        ASSERT_TRUE(renderer) << why;
        EXPECT_FALSE(loadAndUpload(*renderer, loaded, false, diags));
        EXPECT_EQ(messages(diags), "OpenGL error 0x0507 while loading the script\n");
        EXPECT_EQ(renderer->contextFailure(), "the GL context was lost (GL_CONTEXT_LOST)");
        renderer.reset();  // before its context
    }
}

}  // namespace
