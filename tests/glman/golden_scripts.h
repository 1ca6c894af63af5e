// The classroom-style scripts of tests/data/glman whose pictures are stored
// in tests/data/glman/expected: compared by Golden.MatchesTheStoredPicture
// (golden_test.cpp), rewritten only by tools/update-golden.sh
// (update_golden/update_golden.cpp).
#pragma once

namespace glimmer::glmantest {

inline constexpr const char* kGoldenScripts[] = {
    "quad_texture", "sphere_ortho", "teapot",       "cone_cylinder_disk", "wire_shapes", "objadj",
    "triangles_linesadj", "glbegin", "tessellation", "clouds",           "quadbox",     "skybox",
    "cubemap_axes", "texture3d",    "noise",        "noise2_stats",       "flat_smooth", "uniform_forms",
    "all_commands"};

}  // namespace glimmer::glmantest
