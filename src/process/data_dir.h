// Where Glimmer's own files are (shaders/, scripts/, textures/): the blur
// kernels `tradeoff` runs are the files of scripts/bloom, read from here.
#pragma once
#include <string>

namespace glimmer {

// $GLIMMER_DATA_DIR when set; else share/glimmer beside the executable's
// folder (an installed glimmer); else the source tree it was built from.
// The first of these that holds scripts/bloom.
std::string dataDir();

}  // namespace glimmer
