// The values uniforms have now: the script's, then --set, then sliders.
// Kept apart from the plan so a reload or a slider move touches only this.
#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

#include "plan/plan.h"

namespace glimmer {

struct UniformKey {
    int program;
    std::string name;
    bool operator<(const UniformKey& o) const { return std::tie(program, name) < std::tie(o.program, o.name); }
};

class UniformValues {
public:
    explicit UniformValues(const Plan& plan);

    const std::vector<double>& get(int program, const std::string& name) const;
    const std::map<UniformKey, std::vector<double>>& all() const { return values_; }

    // "name=value": sets every uniform of that name: a Range or a Bool from
    // one value, a Color from "r,g,b[,a]", an Array from as many numbers,
    // comma-separated. A value outside a range is an error naming the range;
    // an unknown name is an error too. `option` is the command-line option the
    // assignment came from, for messages ("--set", "--vary").
    // Returns false on error.
    bool applySet(const Plan& plan, const std::string& assignment, Diagnostics& diags,
                  const std::string& option = "--set");

    void set(int program, const std::string& name, std::vector<double> v) { values_[{program, name}] = std::move(v); }

    // After a reload: every uniform of `now` whose Program name, uniform name
    // and form are the same as in `before` keeps the value it had (a range
    // value clamped into the new range); the rest start from the script.
    void carryOver(const Plan& before, const UniformValues& old, const Plan& now);

    // The programs whose values differ from `other` (same plan).
    std::set<int> programsDifferingFrom(const UniformValues& other) const;

private:
    std::map<UniformKey, std::vector<double>> values_;
};

}  // namespace glimmer
