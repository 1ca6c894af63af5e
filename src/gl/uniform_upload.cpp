#include "gl/uniform_upload.h"

#include <cmath>

#include <fmt/format.h>

namespace glimmer {
namespace {

enum class Base { Float, Int, Bool, Matrix, Other };

struct TypeInfo {
    Base base;
    int components;
};

TypeInfo typeInfo(GLenum type) {
    switch (type) {
    case GL_FLOAT: return {Base::Float, 1};
    case GL_FLOAT_VEC2: return {Base::Float, 2};
    case GL_FLOAT_VEC3: return {Base::Float, 3};
    case GL_FLOAT_VEC4: return {Base::Float, 4};
    case GL_INT: return {Base::Int, 1};
    case GL_INT_VEC2: return {Base::Int, 2};
    case GL_INT_VEC3: return {Base::Int, 3};
    case GL_INT_VEC4: return {Base::Int, 4};
    case GL_BOOL: return {Base::Bool, 1};
    case GL_BOOL_VEC2: return {Base::Bool, 2};
    case GL_BOOL_VEC3: return {Base::Bool, 3};
    case GL_BOOL_VEC4: return {Base::Bool, 4};
    case GL_FLOAT_MAT2: return {Base::Matrix, 4};
    case GL_FLOAT_MAT3: return {Base::Matrix, 9};
    case GL_FLOAT_MAT4: return {Base::Matrix, 16};
    default: return {isSamplerType(type) ? Base::Int : Base::Other, 1};
    }
}

const char* formName(UniformSetting::Form f) {
    switch (f) {
    case UniformSetting::Form::Range: return "a range";
    case UniformSetting::Form::Bool: return "a checkbox";
    case UniformSetting::Form::Color: return "a colour";
    case UniformSetting::Form::Array: return "an array";
    case UniformSetting::Form::Constant: return "a number";
    }
    return "a value";
}

}  // namespace

bool isSamplerType(GLenum type) {
    switch (type) {
    case GL_SAMPLER_1D: case GL_SAMPLER_2D: case GL_SAMPLER_3D: case GL_SAMPLER_CUBE:
    case GL_SAMPLER_2D_SHADOW: case GL_SAMPLER_2D_ARRAY: case GL_SAMPLER_2D_RECT:
    case GL_INT_SAMPLER_2D: case GL_UNSIGNED_INT_SAMPLER_2D: case GL_SAMPLER_BUFFER:
        return true;
    default: return false;
    }
}

std::vector<ActiveUniform> activeUniforms(const GlApi& gl, unsigned program) {
    std::vector<ActiveUniform> out;
    GLint count = 0;
    gl.GetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    for (GLint i = 0; i < count; ++i) {
        char name[256];
        GLsizei length = 0;
        ActiveUniform u;
        gl.GetActiveUniform(program, GLuint(i), sizeof name, &length, &u.size, &u.type, name);
        u.name.assign(name, size_t(length));
        if (u.name.compare(0, 3, "gl_") == 0) continue;  // the legacy built-in state
        if (u.name.size() > 3 && u.name.compare(u.name.size() - 3, 3, "[0]") == 0) u.name.resize(u.name.size() - 3);
        u.location = gl.GetUniformLocation(program, u.name.c_str());
        out.push_back(u);
    }
    return out;
}

void checkUniformSettings(const ProgramDecl& decl, const std::vector<ActiveUniform>& active,
                          const std::string& scriptFile, Diagnostics& diags) {
    for (const auto& s : decl.uniforms) {
        const ActiveUniform* a = nullptr;
        for (const auto& u : active)
            if (u.name == s.name) a = &u;
        if (!a) {
            diags.warning(scriptFile, s.loc, fmt::format("uniform '{}' is not used by the shaders of Program {} "
                                                         "(not declared, or removed by the compiler)", s.name, decl.name));
            continue;
        }
        TypeInfo t = typeInfo(a->type);
        size_t want = size_t(t.components) * size_t(a->size);
        bool scalar = t.components == 1 && a->size == 1;
        bool fits = true;
        switch (s.form) {
        case UniformSetting::Form::Range:
        case UniformSetting::Form::Bool:
        case UniformSetting::Form::Constant: fits = scalar; break;
        case UniformSetting::Form::Color: fits = t.base == Base::Float && (t.components == 3 || t.components == 4); break;
        case UniformSetting::Form::Array: fits = s.values.size() == want; break;
        }
        if (!fits)
            diags.warning(scriptFile, s.loc, fmt::format("uniform '{}' is given {} but its shader declares it with "
                                                         "{} value{}; the values are converted", s.name,
                                                         formName(s.form), want, want == 1 ? "" : "s"));
    }
}

void uploadUniform(const GlApi& gl, const ActiveUniform& u, const std::vector<double>& values) {
    if (u.location < 0) return;
    TypeInfo t = typeInfo(u.type);
    size_t n = size_t(t.components) * size_t(std::max(u.size, 1));
    std::vector<float> f(n, 0.f);
    std::vector<GLint> i(n, 0);
    for (size_t k = 0; k < n && k < values.size(); ++k) {
        f[k] = float(values[k]);
        i[k] = t.base == Base::Bool ? (values[k] != 0) : GLint(std::lround(values[k]));
    }
    GLsizei count = std::max(u.size, 1);
    switch (t.base) {
    case Base::Float:
        if (t.components == 1) gl.Uniform1fv(u.location, count, f.data());
        else if (t.components == 2) gl.Uniform2fv(u.location, count, f.data());
        else if (t.components == 3) gl.Uniform3fv(u.location, count, f.data());
        else gl.Uniform4fv(u.location, count, f.data());
        break;
    case Base::Int:
    case Base::Bool:
        if (t.components == 1) gl.Uniform1iv(u.location, count, i.data());
        else if (t.components == 2) gl.Uniform2iv(u.location, count, i.data());
        else if (t.components == 3) gl.Uniform3iv(u.location, count, i.data());
        else gl.Uniform4iv(u.location, count, i.data());
        break;
    case Base::Matrix:
        if (t.components == 4) gl.UniformMatrix2fv(u.location, count, GL_FALSE, f.data());
        else if (t.components == 9) gl.UniformMatrix3fv(u.location, count, GL_FALSE, f.data());
        else gl.UniformMatrix4fv(u.location, count, GL_FALSE, f.data());
        break;
    case Base::Other: break;
    }
}

}  // namespace glimmer
