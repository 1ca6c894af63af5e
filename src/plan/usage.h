// Which textures, meshes and programs the passes that will run use: the only
// ones whose files are read and whose GL objects are made (a script's unused
// 4K image costs nothing). `everything` (for `check`) takes every one.
#pragma once
#include <vector>

#include "plan/plan.h"

namespace glimmer {

struct Usage {
    std::vector<bool> textures, meshes, programs;  // per Plan::textures, ::meshes, ::programs
};

Usage resourcesUsed(const Plan& plan, bool everything);

}  // namespace glimmer
