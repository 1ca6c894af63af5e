// A context that reports an error for ever, as a lost one may after a GPU
// reset (GL_CONTEXT_LOST from every glGetError): the renderer is still
// made, and loading a script ends with an error that says the context was
// lost, not a hang in a loop that waits for the error flag to clear.
// Each wait for the flag is bounded, and the bound is counted here: a wait
// that ran until an int wrapped (2^31 calls) ends with the same message,
// but a driver's glGetError on a lost context may take microseconds, so
// that is minutes of a frozen window.
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
long errorQueries = 0;
GLenum GLAPIENTRY lostForEver() {
    ++errorQueries;
    return kContextLost;
}

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
        Rig rig = makeWrappedRig(backend, [](std::string_view name, void* driver) {
            return name == "glGetError" ? reinterpret_cast<void*>(&lostForEver) : driver;
        });
        ASSERT_TRUE(rig.renderer) << rig.error;
        Renderer& renderer = *rig.renderer;
        errorQueries = 0;
        EXPECT_FALSE(loadAndUpload(renderer, loaded, false, diags));
        // Every wait gives up after at most 64 queries; loading has a few.
        EXPECT_LT(errorQueries, 1000) << "glGetError asked " << errorQueries << " times while loading";
        EXPECT_EQ(messages(diags), "OpenGL error 0x0507 while loading the script\n");
        EXPECT_EQ(renderer.contextFailure(), "the GL context was lost (GL_CONTEXT_LOST)");
    }
}

}  // namespace
