#include "gl/uniform_upload.h"

#include "plan/limits.h"

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

const char* samplerTypeName(GLenum type) {
    switch (type) {
    case GL_SAMPLER_1D: return "sampler1D";
    case GL_SAMPLER_2D: return "sampler2D";
    case GL_SAMPLER_3D: return "sampler3D";
    case GL_SAMPLER_CUBE: return "samplerCube";
    case GL_SAMPLER_1D_SHADOW: return "sampler1DShadow";
    case GL_SAMPLER_2D_SHADOW: return "sampler2DShadow";
    case GL_SAMPLER_CUBE_SHADOW: return "samplerCubeShadow";
    case GL_SAMPLER_1D_ARRAY: return "sampler1DArray";
    case GL_SAMPLER_2D_ARRAY: return "sampler2DArray";
    case GL_SAMPLER_2D_ARRAY_SHADOW: return "sampler2DArrayShadow";
    case GL_SAMPLER_2D_RECT: return "sampler2DRect";
    case GL_SAMPLER_2D_RECT_SHADOW: return "sampler2DRectShadow";
    case GL_SAMPLER_BUFFER: return "samplerBuffer";
    case GL_SAMPLER_2D_MULTISAMPLE: return "sampler2DMS";
    case GL_INT_SAMPLER_2D: return "isampler2D";
    case GL_INT_SAMPLER_3D: return "isampler3D";
    case GL_INT_SAMPLER_CUBE: return "isamplerCube";
    case GL_UNSIGNED_INT_SAMPLER_2D: return "usampler2D";
    case GL_UNSIGNED_INT_SAMPLER_3D: return "usampler3D";
    case GL_UNSIGNED_INT_SAMPLER_CUBE: return "usamplerCube";
    default: return nullptr;
    }
}

bool samplerTextureKind(GLenum type, TextureDecl::Kind& out) {
    switch (type) {
    case GL_SAMPLER_2D: case GL_SAMPLER_2D_SHADOW: case GL_INT_SAMPLER_2D: case GL_UNSIGNED_INT_SAMPLER_2D:
        out = TextureDecl::Kind::Tex2D;
        return true;
    case GL_SAMPLER_3D: case GL_INT_SAMPLER_3D: case GL_UNSIGNED_INT_SAMPLER_3D:
        out = TextureDecl::Kind::Tex3D;
        return true;
    case GL_SAMPLER_CUBE: case GL_SAMPLER_CUBE_SHADOW: case GL_INT_SAMPLER_CUBE: case GL_UNSIGNED_INT_SAMPLER_CUBE:
        out = TextureDecl::Kind::Cube;
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

std::string uniformTypeName(GLenum type) {
    switch (type) {
    case GL_FLOAT: return "float";
    case GL_FLOAT_VEC2: return "vec2";
    case GL_FLOAT_VEC3: return "vec3";
    case GL_FLOAT_VEC4: return "vec4";
    case GL_INT: return "int";
    case GL_INT_VEC2: return "ivec2";
    case GL_INT_VEC3: return "ivec3";
    case GL_INT_VEC4: return "ivec4";
    case GL_UNSIGNED_INT: return "uint";
    case GL_UNSIGNED_INT_VEC2: return "uvec2";
    case GL_UNSIGNED_INT_VEC3: return "uvec3";
    case GL_UNSIGNED_INT_VEC4: return "uvec4";
    case GL_BOOL: return "bool";
    case GL_BOOL_VEC2: return "bvec2";
    case GL_BOOL_VEC3: return "bvec3";
    case GL_BOOL_VEC4: return "bvec4";
    case GL_FLOAT_MAT2: return "mat2";
    case GL_FLOAT_MAT3: return "mat3";
    case GL_FLOAT_MAT4: return "mat4";
    default: return isSamplerType(type) ? "sampler" : "another type";
    }
}

bool glibFormSets(GLenum type) { return !isSamplerType(type) && typeInfo(type).base != Base::Other; }

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
        std::string declared = uniformTypeName(a->type) + (a->size > 1 ? fmt::format("[{}]", a->size) : "");
        std::string prefix = fmt::format("uniform '{}' is given {} but its shader declares it {}", s.name,
                                         formName(s.form), declared);
        bool single = s.values.size() == 1;
        std::string how;
        if (t.base == Base::Other) {
            how = "it is not set";
        } else if (s.form == UniformSetting::Form::Bool && t.base != Base::Bool) {
            const char* v = s.values.at(0) != 0 ? "1" : "0";
            how = want == 1 ? fmt::format("{} is used", v) : fmt::format("every component is {}", v);
        } else if (s.form == UniformSetting::Form::Color) {
            if (t.base == Base::Float && (t.components == 3 || t.components == 4) && a->size == 1) continue;
            if (scalar) how = "its luminance (0.2126 r + 0.7152 g + 0.0722 b) is used";
            else how = "its components are used in order, missing ones 0";
        } else if (single && !scalar) {
            if (s.form == UniformSetting::Form::Array && want == 1) continue;
            how = t.base == Base::Matrix ? fmt::format("the value times the identity is used")
                                         : fmt::format("the value is copied to all {} components", want);
        } else if (s.form == UniformSetting::Form::Array && s.values.size() != want) {
            how = s.values.size() < want ? "the missing components are 0" : "the extra values are dropped";
        } else {
            continue;  // fits
        }
        diags.warning(scriptFile, s.loc, prefix + "; " + how);
    }
}

std::vector<double> convertUniform(UniformSetting::Form form, const ActiveUniform& u, const std::vector<double>& values) {
    TypeInfo t = typeInfo(u.type);
    size_t n = size_t(t.components) * size_t(std::max(u.size, 1));
    if (values.empty()) return values;
    if (form == UniformSetting::Form::Color && values.size() >= 3 && n == 1)
        return {0.2126 * values[0] + 0.7152 * values[1] + 0.0722 * values[2]};
    if (form == UniformSetting::Form::Bool) {
        double b = values[0] != 0 ? 1.0 : 0.0;
        return std::vector<double>(n, b);
    }
    if (values.size() == 1 && n > 1 && form != UniformSetting::Form::Color) {
        if (t.base == Base::Matrix) {
            int dim = t.components == 4 ? 2 : t.components == 9 ? 3 : 4;
            std::vector<double> m(n, 0.0);
            for (size_t e = 0; e < size_t(std::max(u.size, 1)); ++e)
                for (int k = 0; k < dim; ++k) m[e * size_t(t.components) + size_t(k * dim + k)] = values[0];
            return m;
        }
        return std::vector<double>(n, values[0]);
    }
    return values;
}

void uploadUniform(const GlApi& gl, const ActiveUniform& u, const std::vector<double>& values) {
    if (u.location < 0) return;
    TypeInfo t = typeInfo(u.type);
    size_t n = size_t(t.components) * size_t(std::max(u.size, 1));
    std::vector<float> f(n, 0.f);
    std::vector<GLint> i(n, 0);
    for (size_t k = 0; k < n && k < values.size(); ++k) {
        f[k] = clampToFloat(values[k]);
        i[k] = t.base == Base::Bool ? (values[k] != 0) : GLint(clampToInt(std::round(values[k])));
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
