#include "gl/builtin_feed.h"

#include <cstddef>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "geometry/mesh.h"
#include "gl/gl_api.h"

namespace glimmer {

void bindBuiltinAttributes(const GlApi& gl, unsigned program) {
    for (const CompatBuiltin& b : kCompatBuiltins)
        if (b.attribute) gl.BindAttribLocation(program, GLuint(b.location), std::string(b.name).c_str());
}

BuiltinFeed findBuiltinFeed(const GlApi& gl, unsigned program) {
    BuiltinFeed feed;
    for (size_t k = 0; k < kCompatBuiltins.size(); ++k) {
        const CompatBuiltin& b = kCompatBuiltins[k];
        std::string name(b.name);
        feed.location[k] = b.attribute ? gl.GetAttribLocation(program, name.c_str())
                                       : gl.GetUniformLocation(program, name.c_str());
        feed.any = feed.any || feed.location[k] >= 0;
    }
    return feed;
}

namespace {

int at(const BuiltinFeed& feed, CompatFeed f) { return feed.location[size_t(f)]; }

}  // namespace

void feedBuiltinUniforms(const GlApi& gl, const BuiltinFeed& feed, const BuiltinValues& v) {
    auto mat4 = [&](CompatFeed f, const glm::mat4& m) {
        if (int loc = at(feed, f); loc >= 0) gl.UniformMatrix4fv(loc, 1, GL_FALSE, glm::value_ptr(m));
    };
    mat4(CompatFeed::ModelViewProjection, v.projection * v.modelView);
    mat4(CompatFeed::ModelView, v.modelView);
    mat4(CompatFeed::Projection, v.projection);
    mat4(CompatFeed::ModelViewInverse, glm::inverse(v.modelView));
    mat4(CompatFeed::ProjectionInverse, glm::inverse(v.projection));
    mat4(CompatFeed::ModelViewProjectionInverse, glm::inverse(v.projection * v.modelView));
    if (int loc = at(feed, CompatFeed::Normal); loc >= 0) {
        // OpenGL's gl_NormalMatrix: the inverse transpose of the upper 3x3.
        glm::mat3 n = glm::transpose(glm::inverse(glm::mat3(v.modelView)));
        gl.UniformMatrix3fv(loc, 1, GL_FALSE, glm::value_ptr(n));
    }
    if (int loc = at(feed, CompatFeed::PointSize); loc >= 0) gl.Uniform1f(loc, v.pointSize);
}

void enableBuiltinAttributes(const GlApi& gl, const BuiltinFeed& feed, const BuiltinValues& v) {
    const GLsizei stride = sizeof(MeshVertex);
    auto array = [&](CompatFeed f, int size, size_t offset) {
        if (int loc = at(feed, f); loc >= 0) {
            // Fewer components than the attribute's vec4: OpenGL fills
            // (0, 0, 0, 1), as the fixed-function arrays did (w = 1, q = 1).
            gl.EnableVertexAttribArray(GLuint(loc));
            gl.VertexAttribPointer(GLuint(loc), size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offset));
        }
    };
    array(CompatFeed::Vertex, 3, offsetof(MeshVertex, position));
    array(CompatFeed::NormalAttrib, 3, offsetof(MeshVertex, normal));
    array(CompatFeed::MultiTexCoord0, 2, offsetof(MeshVertex, st));
    // The current colour: no array, one value for every vertex (glColor).
    if (int loc = at(feed, CompatFeed::Color); loc >= 0) gl.VertexAttrib4f(GLuint(loc), v.color.r, v.color.g, v.color.b, v.color.a);
}

void disableBuiltinAttributes(const GlApi& gl, const BuiltinFeed& feed) {
    for (CompatFeed f : {CompatFeed::Vertex, CompatFeed::NormalAttrib, CompatFeed::MultiTexCoord0})
        if (int loc = at(feed, f); loc >= 0) gl.DisableVertexAttribArray(GLuint(loc));
}

}  // namespace glimmer
