#pragma once
/// Hazard curves from text files (docs/risk.md, "Hazard curve files"): a plain two-column CSV
/// whose header names the measure with its unit and the rate with "[1/yr]", or OpenQuake's
/// hazard-curve CSV export (probabilities of exceedance in an investigation time, one row per
/// site). Plain C++: no HDF5.
#include <cstddef>
#include <string>
#include <utility>

#include "rocksweep/risk/hazard_curve.hpp"

namespace rocksweep {

struct HazardFile {
    explicit HazardFile(HazardCurve c) : curve(std::move(c)) {}
    HazardCurve curve;
    std::string format;                    ///< "plain" or "openquake"
    double investigation_time_years = 0;   ///< OpenQuake's; 0 for a plain curve
    std::string site;                      ///< OpenQuake: "lon lat [depth]" of the row read; "" for a plain curve
    /// Points left out, and said so: at the low end those whose probability of exceedance is 1
    /// (an infinite rate), at the high end those of rate 0 (OpenQuake writes 0 where the
    /// sources cannot reach an intensity; a log-log curve cannot pass through 0).
    std::size_t dropped_low = 0, dropped_high = 0;
};

/// Reads `path`: OpenQuake's format if its first line is a '#' comment holding
/// "investigation_time=", the plain one otherwise. `site` picks an OpenQuake row (0-based;
/// -1: the file must hold one site). Intensities are converted to g (PGA, SA) or m/s (PGV).
/// Throws InputError naming `field` and path:line with what was expected: an unknown measure
/// or unit, a missing investigation_time or imt, a probability outside [0, 1], a curve that is
/// not monotone or rises, negative rates, fewer than two usable points.
HazardFile read_hazard_file(const std::string& field, const std::string& path, int site = -1);

}  // namespace rocksweep
