// A script's shader stage (plan/plan.h) as the translator names it
// (shader/web_translate.h): the one mapping, for the two places that hand
// a Program's stages to the translator, `check --web` (pipeline/web_check)
// and the renderer on OpenGL ES (gl/shader_build). Header-only, so the
// translator library itself stays free of the plan.
#pragma once
#include "plan/plan.h"
#include "shader/web_translate.h"

namespace glimmer {

inline WebStage webStage(ShaderStage::Kind kind) {
    switch (kind) {
    case ShaderStage::Kind::Vertex: return WebStage::Vertex;
    case ShaderStage::Kind::Fragment: return WebStage::Fragment;
    case ShaderStage::Kind::Geometry: return WebStage::Geometry;
    case ShaderStage::Kind::TessControl: return WebStage::TessControl;
    case ShaderStage::Kind::TessEvaluation: return WebStage::TessEvaluation;
    }
    return WebStage::Vertex;
}

}  // namespace glimmer
