// Risk-based design: the suite's per-level fractions of unacceptable runs over a site's hazard.
#include "rocksweep/app/design_risk.hpp"

#include <cmath>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/risk/hazard_file.hpp"
#include "rocksweep/risk/risk_integral.hpp"
#include "rocksweep/risk/suite_risk.hpp"

namespace rocksweep {

DesignRisk read_design_hazard(const std::string& path, int site, double exposure_years, const SuiteSpec& spec) {
    HazardFile file = read_hazard_file("hazard", path, site);
    SuiteFragilityTable measure;
    measure.measure = to_string(spec.measure);
    if (spec.measure == IntensityMeasure::sa_g) measure.period_s = spec.sa.period_s, measure.damping = spec.sa.damping;
    if (spec.measure == IntensityMeasure::sa_g && file.curve.measure() == HazardMeasure::sa &&
        std::abs(spec.sa.damping - hazard_sa_damping) > 1e-9)
        throw InputError("sa-damping", format_short(spec.sa.damping),
                         "0.05 with an SA(T) hazard curve (--hazard " + path + "): such curves are 5 %-damped");
    check_same_measure(file.curve, path, measure);
    return DesignRisk{std::move(file.curve), path, exposure_years};
}

DesignScore risk_score(const DesignRisk& risk, const std::vector<double>& levels, const std::vector<RegionScore>& per_level) {
    std::vector<double> bad, fallen;
    for (const RegionScore& s : per_level) {
        bad.push_back(1.0 - s.acceptable);
        fallen.push_back(1.0 - s.standing);
    }
    // The empirical fractions, not a lognormal fit: defined for every anchorage the search
    // tries (a fit can fail), and the same counts the suite design scores without a hazard.
    const double rate = annual_rate(risk.curve, levels, bad).rate, standing_rate = annual_rate(risk.curve, levels, fallen).rate;
    const double t = risk.exposure_years;
    return {{std::exp(-rate * t), std::exp(-standing_rate * t)}, rate, standing_rate};
}

}  // namespace rocksweep
