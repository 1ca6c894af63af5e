// The table of compatibility built-ins and their stand-ins
// (shader/compat_builtins.h) is a contract between the translation and the
// renderer: names the renderer looks up must be unique and recognisable,
// and attributes must not share a location (two arrays on one location
// would silently draw one of them).
#include <cctype>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "shader/compat_builtins.h"

using namespace glimmer;

namespace {

TEST(CompatBuiltins, NamesAndBuiltinsAreUnique) {
    std::set<std::string_view> names, builtins;
    for (const CompatBuiltin& b : kCompatBuiltins) {
        EXPECT_TRUE(names.insert(b.name).second) << "stand-in named twice: " << b.name;
        EXPECT_TRUE(builtins.insert(b.builtin).second) << "built-in listed twice: " << b.builtin;
    }
}

TEST(CompatBuiltins, EveryBuiltinStartsGlAndEveryNameGlimmer) {
    for (const CompatBuiltin& b : kCompatBuiltins) {
        EXPECT_EQ(b.builtin.substr(0, 3), "gl_") << b.builtin;
        EXPECT_EQ(b.name.substr(0, 8), "glimmer_") << b.name;
        EXPECT_GT(b.name.size(), 8u) << "a stand-in needs more than the prefix";
        // The stand-in must be a plain identifier (it is declared and looked up).
        for (char c : b.name) EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '_') << b.name;
    }
}

TEST(CompatBuiltins, AttributeLocationsAreDistinctAndUniformsHaveNone) {
    std::set<int> locations;
    for (const CompatBuiltin& b : kCompatBuiltins) {
        if (b.attribute) {
            EXPECT_GE(b.location, 0) << b.name;
            // OpenGL ES 3.0 guarantees 16 vertex attributes (GL_MAX_VERTEX_ATTRIBS).
            EXPECT_LT(b.location, 16) << b.name;
            EXPECT_TRUE(locations.insert(b.location).second) << "location " << b.location << " used twice (" << b.name << ")";
        } else {
            EXPECT_EQ(b.location, -1) << b.name << ": a uniform has no attribute location";
        }
    }
    EXPECT_FALSE(locations.empty());
}

TEST(CompatBuiltins, EachFeedFindsItsOwnRow) {
    for (size_t k = 0; k < kCompatBuiltins.size(); ++k)
        EXPECT_EQ(&compatBuiltin(kCompatBuiltins[k].feed), &kCompatBuiltins[k]) << "row " << k << " is out of order";
}

TEST(CompatBuiltins, TypesAreOnesTheFeedUploads) {
    // gl/builtin_feed.cpp uploads mat4, mat3 and float uniforms and vec3/vec4 arrays.
    const std::set<std::string_view> uniformTypes{"mat4", "mat3", "float"}, attributeTypes{"vec4", "vec3"};
    for (const CompatBuiltin& b : kCompatBuiltins)
        EXPECT_TRUE((b.attribute ? attributeTypes : uniformTypes).count(b.glslType)) << b.name << " is " << b.glslType;
}

}  // namespace
