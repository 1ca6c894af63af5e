// The seed bloom's files (bloom.glib, its four shaders, grid.bmp) copied
// side by side into a fresh folder of the test's own: what a student has
// open in `glimmer view`, free to edit without touching the repository.
#pragma once
#include <filesystem>
#include <string>

#include "common/test_folder.h"

namespace glimmer_viewer {

struct SeedProject {
    glimmer::testing::TestFolder folder;
    std::filesystem::path dir = folder.path;
    explicit SeedProject(const std::string& stem) : folder(stem) {
        const std::filesystem::path src(GLIMMER_SOURCE_DIR);
        std::filesystem::copy_file(src / "scripts/bloom.glib", dir / "bloom.glib");
        for (auto f : {"superblur.vert", "superblur.frag", "bloom.vert", "bloom.frag"})
            std::filesystem::copy_file(src / "shaders" / f, dir / f);
        std::filesystem::copy_file(src / "textures/grid.bmp", dir / "grid.bmp");
    }
};

}  // namespace glimmer_viewer
