// Boundary refinement as the sweep command asks for it: which planes, and the spec that records it.
#include "rocksweep/app/sweep_refinement.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "rocksweep/core/errors.hpp"

namespace rocksweep {

std::optional<RefinePlanes> refine_planes(const SweepSpec& spec, const SweepCommand& cmd) {
    const std::vector<std::string> names = spec.axis_names();
    std::vector<std::string> pair = cmd.refine_axes.empty() ? std::vector<std::string>{names[names.size() - 2], names.back()}
                                                            : cmd.refine_axes;
    const std::string shown = pair.size() == 2 ? pair[0] + " " + pair[1] : "";
    if (cmd.refine_stride == 0) {
        if (!cmd.refine_axes.empty()) throw InputError("refine-axes", shown, "only with --refine STRIDE");
        return std::nullopt;
    }
    std::size_t at[2];
    for (int k = 0; k < 2; ++k) {
        std::string name = pair[k];
        std::replace(name.begin(), name.end(), '-', '_');
        const auto it = std::find(names.begin(), names.end(), name);
        std::string all;
        for (const std::string& n : names) all += (all.empty() ? "" : ", ") + n;
        if (it == names.end()) throw InputError("refine-axes", shown, "two axes of the grid: " + all);
        at[k] = static_cast<std::size_t>(it - names.begin());
    }
    if (at[0] == at[1]) throw InputError("refine-axes", shown, "two different axes");
    return RefinePlanes(spec.axis_sizes(), std::min(at[0], at[1]), std::max(at[0], at[1]));
}

SweepSpec sweep_spec(const Options& opts, const SweepCommand& cmd) {
    SweepSpec spec = make_sweep_spec(opts);
    if (const std::optional<RefinePlanes> planes = refine_planes(spec, cmd)) {
        const std::vector<std::string> names = spec.axis_names();
        spec.refine_stride = cmd.refine_stride;
        spec.refine_axes = names[planes->row_axis()] + " " + names[planes->col_axis()];
    }
    return spec;
}

}  // namespace rocksweep
