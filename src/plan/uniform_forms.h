// Reads the name-value pairs of a Program line into UniformSettings.
#pragma once
#include <string>
#include <vector>

#include "plan/plan.h"

namespace glimmer {

// Pairs start at c.args[first]. Malformed pairs are reported and skipped;
// the rest of the line is still read.
std::vector<UniformSetting> parseUniformSettings(const Command& c, size_t first, const std::string& file,
                                                 Diagnostics& diags);

}  // namespace glimmer
