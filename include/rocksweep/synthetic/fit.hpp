#pragma once
/// The model's parameters fitted to one record, as Rezaeian & Der Kiureghian (2008) fit them:
/// the envelope from the record's cumulative Arias intensity, the filter's frequency and drift
/// from its zero-level up-crossings, the filter's damping from its positive minima and negative
/// maxima, matched to the mean count of simulated motions. docs/synthetic.md.
#include <cstdint>
#include <vector>

#include "rocksweep/synthetic/ground_model.hpp"
#include "rocksweep/synthetic/motion_measures.hpp"

namespace rocksweep::synthetic {

struct FitSettings {
    double fc_hz = 0.2;              ///< high-pass corner (not fitted: a choice, docs/synthetic.md)
    int realisations = 24;           ///< simulated motions per damping tried
    std::uint64_t seed = 0x5eed;     ///< their seed: the fit is deterministic
};

struct FitResult {
    ModelParameters params;
    AriasTimes record;                ///< the record's landmarks the envelope reproduces
    std::size_t record_extrema = 0;   ///< its positive minima + negative maxima in [t5, t95]
    double simulated_extrema = 0.0;   ///< the fitted model's mean count there
};

/// Fits the model to `a_g` (units of standard gravity, sampled every `dt_s`). Throws InputError
/// ("record", ...) for a record whose shape the model cannot take (fewer than 10 up-crossings
/// in its strong phase, a duration ratio outside the envelope's range).
FitResult fit_model(const std::vector<double>& a_g, double dt_s, const FitSettings& settings = {});

}  // namespace rocksweep::synthetic
