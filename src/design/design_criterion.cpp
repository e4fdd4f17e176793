#include "rocksweep/design/design_criterion.hpp"

#include <stdexcept>
#include <string>

#include "rocksweep/grid/refine.hpp"

namespace rocksweep {

std::vector<double> node_weights(const Axis& axis) {
    const std::vector<double> v = axis.values();
    std::vector<double> w(v.size(), 1.0);
    if (v.size() < 2) return w;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const double left = i > 0 ? v[i] - v[i - 1] : 0.0;
        const double right = i + 1 < v.size() ? v[i + 1] - v[i] : 0.0;
        w[i] = 0.5 * (left + right);
    }
    return w;
}

RegionScore score_scenario(const SweepSpec& spec, const SweepResults& r, std::size_t scenario,
                           const DesignConstraints& c) {
    if (scenario >= spec.scenarios.size()) throw std::invalid_argument("score_scenario: no such scenario");
    if (r.size() != spec.cell_count()) throw std::invalid_argument("score_scenario: results do not match the sweep");
    const bool limited = c.max_rotation_ratio > 0.0 || c.max_force_ratio > 0.0;
    const std::vector<double> wa = node_weights(spec.amplitude_ratio), wo = node_weights(spec.omega_ratio);
    const std::size_t first = scenario * spec.cells_per_scenario();
    double total = 0.0, acceptable = 0.0, standing = 0.0;
    for (std::size_t i = 0; i < wa.size(); ++i) {
        for (std::size_t j = 0; j < wo.size(); ++j) {
            const std::size_t k = first + i * wo.size() + j;
            if (r.done[k] == cell_pending)
                throw std::invalid_argument("score_scenario: cell " + std::to_string(k) + " is not computed");
            if (limited && r.done[k] == cell_inferred)
                throw std::invalid_argument("score_scenario: a limit needs every cell computed, not inferred by refinement");
            const double w = wa[i] * wo[j];
            total += w;
            if (r.outcome[k] != static_cast<std::uint8_t>(Outcome::safe)) continue;
            standing += w;
            const bool rotation_ok = !(c.max_rotation_ratio > 0.0) || r.max_rotation[k] <= c.max_rotation_ratio;
            const bool force_ok = !(c.max_force_ratio > 0.0) || !(r.peak_force_ratio[k] > c.max_force_ratio);
            if (rotation_ok && force_ok) acceptable += w;
        }
    }
    return {acceptable / total, standing / total};
}

}  // namespace rocksweep
