#include "rocksweep/records/suite_products.hpp"

#include <cmath>

namespace rocksweep {

namespace {

constexpr std::uint8_t not_converged = static_cast<std::uint8_t>(Outcome::not_converged);

/// The converged runs of one record on one block (`at`, level ignored), in increasing level.
std::vector<IdaPoint> ida_curve(const SuiteSpec& spec, const SweepResults& r, SuiteSpec::Coordinates at) {
    std::vector<IdaPoint> curve;
    for (std::size_t l = 0; l < spec.intensity.points; ++l) {
        at.level = l;
        const std::size_t i = spec.index(at);
        if (r.outcome[i] == not_converged) continue;
        curve.push_back({spec.intensity.at(l), r.max_rotation[i], r.outcome[i] != 0});
    }
    return curve;
}

}  // namespace

OverturningSpectrum overturning_spectrum(const SuiteSpec& spec, const SweepResults& r, std::size_t s) {
    const std::size_t blocks = spec.alphas_rad.size() * spec.radii_m.size(), n = spec.records.size() * blocks;
    OverturningSpectrum o;
    o.first_intensity.assign(n, NAN);
    o.first_pga_g.assign(n, NAN);
    o.below_intensity.assign(n, NAN);
    o.safe_above.assign(n, 0);
    const DamageState overturning{0.0, true};
    for (std::size_t rec = 0; rec < spec.records.size(); ++rec)
        for (std::size_t b = 0; b < blocks; ++b) {
            const SuiteSpec::Coordinates at{s, rec, b / spec.radii_m.size(), b % spec.radii_m.size(), 0};
            const std::vector<IdaPoint> curve = ida_curve(spec, r, at);
            if (curve.empty()) continue;
            const IdaCapacity c = ida_capacity(curve, overturning);
            if (!c.reached) continue;
            const std::size_t k = rec * blocks + b;
            o.first_intensity[k] = c.first_level;
            o.below_intensity[k] = c.below;
            o.safe_above[k] = c.safe_above ? 1 : 0;
            // The level is exact on the axis; the PGA the record had there follows from it.
            for (std::size_t l = 0; l < spec.intensity.points; ++l)
                if (spec.intensity.at(l) == c.first_level)
                    o.first_pga_g[k] = spec.scale_factor(rec, at.alpha, l, spec.floor_of(s)) * spec.records[rec].measures.pga_g;
        }
    return o;
}

SuiteFragility suite_fragility(const SuiteSpec& spec, const SweepResults& r, std::size_t s,
                               const std::vector<DamageState>& states) {
    const std::size_t blocks = spec.alphas_rad.size() * spec.radii_m.size(), levels = spec.intensity.points;
    SuiteFragility f;
    f.states = states;
    f.exceed.assign(states.size() * blocks * levels, 0);
    f.total.assign(states.size() * blocks * levels, 0);
    for (std::size_t d = 0; d < states.size(); ++d)
        for (std::size_t b = 0; b < blocks; ++b) {
            std::vector<Stripe> stripes;
            std::int32_t flagged = 0;
            for (std::size_t l = 0; l < levels; ++l) {
                Stripe st{spec.intensity.at(l), 0, 0};
                for (std::size_t rec = 0; rec < spec.records.size(); ++rec) {
                    const std::size_t i = spec.index({s, rec, b / spec.radii_m.size(), b % spec.radii_m.size(), l});
                    if (r.outcome[i] == not_converged) continue;
                    ++st.total;
                    flagged += r.sensitive.size() == r.size() && r.sensitive[i] ? 1 : 0;
                    st.exceed += reaches({st.intensity, r.max_rotation[i], r.outcome[i] != 0}, states[d]) ? 1 : 0;
                }
                const std::size_t k = (d * blocks + b) * levels + l;
                f.exceed[k] = st.exceed;
                f.total[k] = st.total;
                if (st.total > 0) stripes.push_back(st);
            }
            FragilityFit fit;
            if (stripes.empty()) {
                fit.status = FitStatus::none_reached;
                fit.curve = {INFINITY, NAN};
            } else {
                fit = fit_stripes(stripes);
            }
            f.fits.push_back(fit);
            f.sensitive.push_back(flagged);
        }
    return f;
}

}  // namespace rocksweep
