#pragma once
/// The --axis options of a sweep into its spec, checked against the other options.
#include "rocksweep/app/options.hpp"
#include "rocksweep/grid/sweep.hpp"

namespace rocksweep {

/// Parses o.grid.axes into spec.axes (the first varies slowest), after spec's scenarios and
/// pulse are made. An axis of theta_f / alpha or K makes the constant scenarios one, "constant";
/// one of K_min / K_max the adaptive ones one, "adaptive". Throws InputError("axis", ...).
void add_parameter_axes(const Options& o, SweepSpec& spec);

/// Builds every point's block and anchorages once, so that a combination that makes none is
/// refused, with its point, before any work. Throws InputError("axis", ...).
void check_planes(const SweepSpec& spec);

}  // namespace rocksweep
