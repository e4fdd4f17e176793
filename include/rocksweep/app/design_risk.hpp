#pragma once
/// Risk-based design (`design --suite ... --hazard CURVE`, docs/risk.md): each anchorage is
/// scored by the annual rate at which the block becomes unacceptable (overturns, or exceeds the
/// rotation or object-force limit) at a site, the suite's per-level fractions integrated over
/// the site's hazard curve, instead of by the share of the suite's runs it survives.
#include <optional>
#include <string>
#include <vector>

#include "rocksweep/design/design_criterion.hpp"
#include "rocksweep/records/suite_sweep.hpp"
#include "rocksweep/risk/hazard_curve.hpp"

namespace rocksweep {

struct DesignRisk {
    HazardCurve curve;
    std::string path;
    double exposure_years = 50;
};

/// A design evaluation: the criterion (RegionScore) and, when a hazard curve scores it, the
/// annual rates it came from. The criterion is then the probability of no unacceptable event
/// in the exposure time, exp(-rate t) (and the same for overturning alone as `standing`), so
/// that larger stays better and minimising the rate is maximising it.
struct DesignScore {
    RegionScore score;
    double rate = 0.0;           ///< unacceptable state [1/yr]; NaN without a hazard curve
    double standing_rate = 0.0;  ///< overturning alone [1/yr]; NaN without a hazard curve
};

/// Reads `path` (OpenQuake row `site`) and checks its measure against the suite's. Throws
/// InputError naming --hazard.
DesignRisk read_design_hazard(const std::string& path, int site, double exposure_years, const SuiteSpec& spec);

/// Scores the block of one scenario from the suite's per-level shares (score_levels).
DesignScore risk_score(const DesignRisk& risk, const std::vector<double>& levels, const std::vector<RegionScore>& per_level);

}  // namespace rocksweep
