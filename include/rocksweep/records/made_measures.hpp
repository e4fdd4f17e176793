#pragma once
/// The measures of a suite's made motions, computed in shares and moved between processes as
/// plain numbers. Measuring a motion (its floor spectra above all) costs ~10 times making it,
/// and only the writer needs every measure; so the ranks each measure a share, the writer
/// gathers them all, and every rank keeps only the measures a level is scaled by
/// (docs/synthetic.md, "Cost and scale"). The same function of the same motion measures it
/// wherever it runs, so the numbers are those of make_suite_spec's eager path, bit for bit.
#include <cstddef>
#include <span>
#include <vector>

#include "rocksweep/records/suite_sweep.hpp"

namespace rocksweep {

/// Measures made motions [first, first + count) of `spec` (indices into spec.motions) on the
/// ground and every floor, as make_suite_spec with MadeMeasures::all does.
void measure_made_motions(SuiteSpec& spec, std::size_t first, std::size_t count);

/// Throws InputError, as make_suite_spec does, for the first made motion whose own measure
/// (the one spec.measure divides by) is not positive: it cannot be scaled to a level.
void check_made_measures(const SuiteSpec& spec);

/// Every measure of made motions [first, first + count), as a fixed number of doubles per
/// motion, and back into `spec` (whose floors and members the numbers must fit: throws
/// std::invalid_argument otherwise).
std::vector<double> pack_made_measures(const SuiteSpec& spec, std::size_t first, std::size_t count);
void unpack_made_measures(SuiteSpec& spec, std::size_t first, std::span<const double> packed);

/// Only what SuiteSpec::scale_factor and check_made_measures read (PGA, PGV, Sa, the PFA of
/// each floor) of every made motion, and back: what a rank that does not write needs.
std::vector<double> pack_scaling_measures(const SuiteSpec& spec);
void unpack_scaling_measures(SuiteSpec& spec, std::span<const double> packed);

}  // namespace rocksweep
