#include "gl/unset_uniforms.h"

#include <fmt/format.h>

#include "shader/uniform_declaration.h"

namespace glimmer {
namespace {

bool builtIn(const std::string& name) {
    return name == "Timer" || name == "Noise2" || name == "Noise3" || name.rfind("glimmer_", 0) == 0 ||
           name.find('.') != std::string::npos;
}

// What a student could add to the Program line for a uniform of this type,
// in GLIB's own forms; empty where no form fits (matrices).
std::string example(const std::string& name, const std::string& type) {
    if (type == "float") return fmt::format("{} <0. 1. 1.>", name);
    if (type == "int") return fmt::format("{} <0 1 10>", name);
    if (type == "bool") return fmt::format("{} <true>", name);
    if (type == "vec3" || type == "vec4") return fmt::format("{} {{1. 1. 1.}}", name);
    if (type == "vec2") return fmt::format("{} [1. 1.]", name);
    if (type == "ivec2") return fmt::format("{} [1 1]", name);
    if (type == "ivec3") return fmt::format("{} [1 1 1]", name);
    if (type == "ivec4") return fmt::format("{} [1 1 1 1]", name);
    return {};
}

}  // namespace

std::vector<UnsetUniform> unsetUniforms(const ProgramDecl& decl, const std::vector<ActiveUniform>& active,
                                        const std::set<std::string>& initialized) {
    std::vector<UnsetUniform> out;
    for (const auto& u : active) {
        if (isSamplerType(u.type) || builtIn(u.name) || initialized.count(u.name)) continue;
        bool set = false;
        for (const auto& s : decl.uniforms) set = set || s.name == u.name;
        if (set) continue;
        std::string type = uniformTypeName(u.type);
        out.push_back({u.name, type, int(u.size), u.size > 1 ? std::string() : example(u.name, type), glibFormSets(u.type)});
    }
    return out;
}

void warnUnsetUniforms(const ProgramDecl& decl, const std::vector<ActiveUniform>& active,
                       const std::set<std::string>& initialized,
                       const std::vector<std::optional<std::string>>& texts, const std::string& scriptFile,
                       Diagnostics& diags) {
    for (const auto& u : unsetUniforms(decl, active, initialized)) {
        // Where its shader declares it: the first stage that does.
        std::string where;
        for (size_t k = 0; k < decl.stages.size() && where.empty(); ++k)
            if (k < texts.size() && texts[k])
                if (int line = uniformDeclarationLine(*texts[k], u.name); line > 0)
                    where = fmt::format(" ({}:{})", decl.stages[k].shown, line);
        std::string type = u.type + (u.size > 1 ? fmt::format("[{}]", u.size) : "");
        const bool scalar = u.size == 1 && (type == "float" || type == "int" || type == "uint");
        std::string value = type == "bool" ? "false" : scalar ? "0" : "all 0";
        const std::string& add = u.example;
        std::string advice;
        if (!u.settable) {
            // No Program line can set it: the advice is the shader's.
            const bool unsignedInt = u.type == "uint" || u.type.rfind("uvec", 0) == 0;
            advice = fmt::format("no GLIB form sets a {}: give it a value where the shader declares it{}", u.type,
                                 unsignedInt ? fmt::format(", or declare it {}", u.type == "uint" ? "int" : "i" + u.type.substr(1))
                                             : "");
        } else {
            advice = fmt::format("give it a value{} on this Program line{}", scalar ? " or a slider" : "",
                                 add.empty() || u.size > 1 ? std::string() : fmt::format(", e.g. '{}'", add));
        }
        diags.warning(scriptFile, decl.loc,
                      fmt::format("Program {} reads uniform {} {}{} but the script never sets it, so it stays {}; {}",
                                  decl.name, type, u.name, where, value, advice));
    }
}

}  // namespace glimmer
