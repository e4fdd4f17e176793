#include "rocksweep/records/suite_products.hpp"

#include <cmath>
#include <stdexcept>

namespace rocksweep {

namespace {

constexpr std::uint8_t not_converged = static_cast<std::uint8_t>(Outcome::not_converged);

/// The converged runs of one record on one block, in increasing level: `at` is the entry of
/// its lowest level in `r`.
std::vector<IdaPoint> ida_curve(const SuiteSpec& spec, const SweepResults& r, std::size_t at) {
    std::vector<IdaPoint> curve;
    for (std::size_t l = 0; l < spec.intensity.points; ++l) {
        const std::size_t i = at + l;
        if (r.outcome[i] == not_converged) continue;
        curve.push_back({spec.intensity.at(l), r.max_rotation[i], r.outcome[i] != 0});
    }
    return curve;
}

std::size_t blocks_of(const SuiteSpec& spec) { return spec.alphas_rad.size() * spec.radii_m.size(); }

}  // namespace

SuiteProducts::SuiteProducts(const SuiteSpec& spec, std::size_t scenario, std::vector<DamageState> states)
    : spec_(spec), scenario_(scenario) {
    const std::size_t blocks = blocks_of(spec), n = spec.records.size() * blocks;
    overturning_.first_intensity.assign(n, NAN);
    overturning_.first_pga_g.assign(n, NAN);
    overturning_.below_intensity.assign(n, NAN);
    overturning_.safe_above.assign(n, 0);
    counts_.exceed.assign(states.size() * blocks * spec.intensity.points, 0);
    counts_.total.assign(counts_.exceed.size(), 0);
    counts_.sensitive.assign(states.size() * blocks, 0);
    counts_.states = std::move(states);
}

void SuiteProducts::add(const SweepResults& r, std::size_t offset, std::size_t first_record, std::size_t records) {
    const SuiteSpec& spec = spec_;
    const std::size_t blocks = blocks_of(spec), levels = spec.intensity.points, states = counts_.states.size();
    const DamageState overturning{0.0, true};
    const bool flags = r.sensitive.size() == r.size();
    for (std::size_t j = 0; j < records; ++j)
        for (std::size_t b = 0; b < blocks; ++b) {
            const std::size_t rec = first_record + j, alpha = b / spec.radii_m.size(), at = offset + (j * blocks + b) * levels;
            // The stripes: per state and level, the converged runs and those reaching the state.
            for (std::size_t l = 0; l < levels; ++l) {
                const std::size_t i = at + l;
                if (r.outcome[i] == not_converged) continue;
                const IdaPoint point{spec.intensity.at(l), r.max_rotation[i], r.outcome[i] != 0};
                for (std::size_t d = 0; d < states; ++d) {
                    const std::size_t k = (d * blocks + b) * levels + l;
                    ++counts_.total[k];
                    counts_.exceed[k] += reaches(point, counts_.states[d]) ? 1 : 0;
                    counts_.sensitive[d * blocks + b] += flags && r.sensitive[i] ? 1 : 0;
                }
            }
            // The overturning spectrum: where this record's IDA curve first overturns the block.
            const std::vector<IdaPoint> curve = ida_curve(spec, r, at);
            if (curve.empty()) continue;
            const IdaCapacity c = ida_capacity(curve, overturning);
            if (!c.reached) continue;
            const std::size_t k = rec * blocks + b;
            OverturningSpectrum& o = overturning_;
            o.first_intensity[k] = c.first_level;
            o.below_intensity[k] = c.below;
            o.safe_above[k] = c.safe_above ? 1 : 0;
            // The level is exact on the axis; the PGA the record had there follows from it.
            for (std::size_t l = 0; l < levels; ++l)
                if (spec.intensity.at(l) == c.first_level)
                    o.first_pga_g[k] = spec.scale_factor(rec, alpha, l, spec.floor_of(scenario_)) * spec.records[rec].measures.pga_g;
        }
}

std::vector<Stripe> SuiteProducts::stripes(std::size_t d, std::size_t b) const {
    const std::size_t blocks = blocks_of(spec_), levels = spec_.intensity.points;
    std::vector<Stripe> out;
    for (std::size_t l = 0; l < levels; ++l) {
        const std::size_t k = (d * blocks + b) * levels + l;
        if (counts_.total[k] > 0) out.push_back({spec_.intensity.at(l), counts_.exceed[k], counts_.total[k]});
    }
    return out;
}

void SuiteProducts::fit() {
    const std::size_t blocks = blocks_of(spec_);
    std::vector<double> levels;
    for (std::size_t l = 0; l < spec_.intensity.points; ++l) levels.push_back(spec_.intensity.at(l));
    fits_.clear();
    clusters_.clear();
    for (std::size_t d = 0; d < counts_.states.size(); ++d)
        for (std::size_t b = 0; b < blocks; ++b) {
            const std::vector<Stripe> st = stripes(d, b);
            FragilityFit fit;
            if (st.empty()) {
                fit.status = FitStatus::none_reached;
                fit.curve = {INFINITY, NAN};
            } else {
                fit = fit_stripes(st);
            }
            fits_.push_back(fit);
            clusters_.emplace_back(fit, levels);
        }
}

void SuiteProducts::add_errors(const SweepResults& r, std::size_t offset, std::size_t records) {
    if (clusters_.empty()) throw std::logic_error("SuiteProducts::add_errors before fit()");
    const std::size_t blocks = blocks_of(spec_), levels = spec_.intensity.points, states = counts_.states.size();
    std::vector<std::int8_t> outcome(levels);
    for (std::size_t j = 0; j < records; ++j)
        for (std::size_t b = 0; b < blocks; ++b) {
            const std::size_t at = offset + (j * blocks + b) * levels;
            for (std::size_t d = 0; d < states; ++d) {
                for (std::size_t l = 0; l < levels; ++l) {
                    const std::size_t i = at + l;
                    outcome[l] = r.outcome[i] == not_converged ? -1
                                 : reaches({spec_.intensity.at(l), r.max_rotation[i], r.outcome[i] != 0}, counts_.states[d])
                                     ? 1
                                     : 0;
                }
                clusters_[d * blocks + b].add(outcome);
            }
        }
}

SuiteFragility SuiteProducts::fragility() const {
    if (clusters_.empty()) throw std::logic_error("SuiteProducts::fragility before fit()");
    const std::size_t blocks = blocks_of(spec_);
    SuiteFragility f = counts_;
    for (std::size_t d = 0; d < f.states.size(); ++d)
        for (std::size_t b = 0; b < blocks; ++b) {
            const std::size_t k = d * blocks + b;
            const StripeClusters& c = clusters_[k];
            f.fits.push_back(c.records() > 0 ? c.corrected(stripes(d, b)) : fits_[k]);
        }
    return f;
}

OverturningSpectrum overturning_spectrum(const SuiteSpec& spec, const SweepResults& r, std::size_t s) {
    SuiteProducts p(spec, s, {});
    p.add(r, s * spec.cells_per_scenario(), 0, spec.records.size());
    return p.overturning();
}

SuiteFragility suite_fragility(const SuiteSpec& spec, const SweepResults& r, std::size_t s,
                               const std::vector<DamageState>& states) {
    SuiteProducts p(spec, s, states);
    const std::size_t offset = s * spec.cells_per_scenario();
    p.add(r, offset, 0, spec.records.size());
    p.fit();
    p.add_errors(r, offset, spec.records.size());
    return p.fragility();
}

}  // namespace rocksweep
