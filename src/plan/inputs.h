// Every file a plan reads, once each, in the order the script names them:
// the script, each texture (each face of a cube map), each shader stage,
// each model. The output guard compares outputs against them; `check
// --list-inputs` prints them, for the lesson packer (tools/web_lesson.py),
// which packs exactly what each script reads.
#pragma once
#include <string>
#include <vector>

#include "plan/plan.h"

namespace glimmer {

struct PlanInput {
    std::string path;   // resolved, openable
    std::string shown;  // as the script wrote it
};

std::vector<PlanInput> inputsOf(const Plan& plan);

}  // namespace glimmer
