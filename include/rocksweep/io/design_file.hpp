#pragma once
/// The design file: the criterion against the constant stiffness K and against K_min/K_max,
/// the recommended values, the hazard region and the limits used. Layout: docs/design.md.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rocksweep/design/design_criterion.hpp"
#include "rocksweep/design/design_search.hpp"
#include "rocksweep/io/spectra_file.hpp"
#include "rocksweep/grid/sweep.hpp"

namespace rocksweep {

/// One design variable's curve, ascending in the variable.
struct DesignCurve {
    std::vector<double> variable;            ///< K [N/m], or K_min / K_max
    std::vector<double> theta_f_ratio;       ///< theta_f / alpha of each constant K (empty for K_min / K_max)
    std::vector<double> acceptable;          ///< the criterion
    std::vector<double> standing;            ///< not overturned, limits ignored
    std::vector<double> rate, standing_rate; ///< with a hazard curve: the annual rates [1/yr] of the unacceptable state and of overturning (NaN without)
    std::vector<std::int32_t> round;         ///< search round that evaluated it: 0 the coarse one
    std::size_t optimum = 0;                 ///< index of the recommended value (best_point)
    std::size_t near_lo = 0, near_hi = 0;    ///< the run of values around it within DesignReport::near_optimal of its criterion
};

/// A record suite as the hazard: its runs at each level count equally.
struct SuiteHazard {
    std::string suite_path;
    std::string measure;  ///< "pga_g", ...
    std::string units;
    Axis levels;
    std::size_t records = 0;
};

/// A site's hazard curve as the design's criterion (design --hazard): the safe fraction is then
/// exp(-rate t), the probability of no unacceptable event in the exposure time t.
struct RiskHazard {
    std::string path;
    std::string measure;  ///< "PGA", ...
    double exposure_years = 50;
};

struct DesignReport {
    SweepSpec hazard;                  ///< block and region; its scenarios are not written
    DesignConstraints constraints;
    double strength_n = 0.0;           ///< F_u [N]
    double object_force_n = 0.0;       ///< the object's own force limit [N]; 0: none
    double k_max_n_per_m = 0.0;        ///< the adaptive anchorage's K_max
    double k_max_theta_f_ratio = 1.0;  ///< its theta_f / alpha
    RegionScore free;                  ///< the free-standing block, the reference
    DesignCurve constant, adaptive;
    SearchSettings stiffness_search, kmin_search;  ///< x = log10 K [N/m], log10 (K_min / K_max)
    double near_optimal = 0.0;         ///< margin of the near-optimal ranges
    std::size_t refine_stride = 0;     ///< boundary refinement of each sweep; 0: every cell computed
    std::optional<SuiteHazard> suite;  ///< set: the hazard is this suite, not hazard's region
    std::optional<RiskHazard> risk;    ///< set (with suite): the criterion is the annual rate at this site
    double free_rate = 0.0, free_standing_rate = 0.0;  ///< the free block's rates [1/yr] (NaN without risk)
};

/// Writes `path` atomically (publish_h5_atomically). Throws std::invalid_argument if a
/// curve's columns differ in length or its optimum is out of range; std::runtime_error
/// ("cannot write PATH: ...") for a failed write.
void write_design(const std::string& path, const DesignReport& report, const Provenance& prov);

}  // namespace rocksweep
