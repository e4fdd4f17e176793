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

namespace {

/// Adds cell k of `r`, of weight w, to the running sums.
struct Tally {
    const SweepResults& r;
    const DesignConstraints& c;
    double total = 0.0, acceptable = 0.0, standing = 0.0;

    void add(std::size_t k, double w) {
        const bool limited = c.max_rotation_ratio > 0.0 || c.max_force_ratio > 0.0;
        if (r.done[k] == cell_pending) throw std::invalid_argument("design criterion: cell " + std::to_string(k) + " is not computed");
        if (limited && r.done[k] == cell_inferred)
            throw std::invalid_argument("design criterion: a limit needs every cell computed, not inferred by refinement");
        total += w;
        if (r.outcome[k] != static_cast<std::uint8_t>(Outcome::safe)) return;
        standing += w;
        const bool rotation_ok = !(c.max_rotation_ratio > 0.0) || r.max_rotation[k] <= c.max_rotation_ratio;
        const bool force_ok = !(c.max_force_ratio > 0.0) || !(r.peak_force_ratio[k] > c.max_force_ratio);
        if (rotation_ok && force_ok) acceptable += w;
    }
    RegionScore score() const { return {acceptable / total, standing / total}; }
};

}  // namespace

RegionScore score_scenario(const SweepSpec& spec, const SweepResults& r, std::size_t scenario,
                           const DesignConstraints& c) {
    if (scenario >= spec.scenarios.size()) throw std::invalid_argument("score_scenario: no such scenario");
    if (r.size() != spec.cell_count()) throw std::invalid_argument("score_scenario: results do not match the sweep");
    const std::vector<double> wa = node_weights(spec.amplitude_ratio), wo = node_weights(spec.omega_ratio);
    const std::size_t first = scenario * spec.cells_per_scenario();
    Tally t{r, c};
    for (std::size_t i = 0; i < wa.size(); ++i)
        for (std::size_t j = 0; j < wo.size(); ++j) t.add(first + i * wo.size() + j, wa[i] * wo[j]);
    return t.score();
}

RegionScore score_cells(const SweepResults& r, std::size_t first, std::size_t count, const DesignConstraints& c) {
    if (count == 0 || first + count > r.size()) throw std::invalid_argument("score_cells: cells out of range");
    Tally t{r, c};
    for (std::size_t k = first; k < first + count; ++k) t.add(k, 1.0);
    return t.score();
}

std::vector<RegionScore> score_levels(const SweepResults& r, std::size_t first, std::size_t records, std::size_t levels,
                                      const DesignConstraints& c) {
    if (records == 0 || levels == 0 || first + records * levels > r.size()) throw std::invalid_argument("score_levels: cells out of range");
    std::vector<RegionScore> out;
    for (std::size_t l = 0; l < levels; ++l) {
        Tally t{r, c};
        for (std::size_t i = 0; i < records; ++i) t.add(first + i * levels + l, 1.0);
        out.push_back(t.score());
    }
    return out;
}

}  // namespace rocksweep
