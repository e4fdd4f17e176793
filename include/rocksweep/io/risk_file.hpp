#pragma once
/// The risk file (docs/risk.md): the hazard curve as used, and per anchorage scenario the
/// annual rate of every damage state and block, its probability in the exposure time, its
/// return period and its deaggregation. And the reader of what it needs from a suite file.
#include <string>

#include "rocksweep/io/spectra_file.hpp"
#include "rocksweep/risk/hazard_file.hpp"
#include "rocksweep/risk/suite_risk.hpp"

namespace rocksweep {

/// The fragility of a complete suite file (docs/suite.md): measure, states, axes, and per
/// scenario the fractions with Wilson's bounds and the lognormal fits. Throws InputError
/// (field "suite-file") for a file that is not a suite file, or a partial one (no fragility).
SuiteFragilityTable read_suite_fragility(const std::string& path);

struct RiskReport {
    std::string suite_path, hazard_path;
    HazardFile hazard;
    std::string intensity_measure, intensity_units;  ///< the suite's
    double exposure_years = 50;
    SuiteFragilityTable fragility;
    SuiteRisk risk;
};

/// Writes `path` atomically (publish_h5_atomically). Throws as write_spectra.
void write_risk(const std::string& path, const RiskReport& report, const Provenance& prov);

}  // namespace rocksweep
