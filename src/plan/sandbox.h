// --sandbox: a script may name only files inside its own folder or a folder
// given with -I, after every symlink is followed. Used by the planner in
// place of resolveFile when PlanOptions::sandbox is set.
#pragma once
#include <string>
#include <vector>

namespace glimmer {

enum class SandboxLookup { Found, NotFound, Outside };

// Looks for `name` in the script's folder, then each -I folder (not in the
// ../shaders and ../textures project folders resolveFile also tries).
// Found: `path` is the file's real path, a regular file inside a root.
// Outside: `why` says how it left the sandbox (an absolute name, a path or
// symlink leading out, not a regular file). `tried` lists the roots.
SandboxLookup resolveSandboxed(const std::string& scriptFile, const std::string& name,
                               const std::vector<std::string>& includeDirs, std::string& path,
                               std::vector<std::string>& tried, std::string& why);

}  // namespace glimmer
