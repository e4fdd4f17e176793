#pragma once
/// Boundary refinement as a sweep command asks for it (--refine, --refine-axes): the planes it
/// works on, and the sweep's cells with the refinement recorded in them.
#include <optional>

#include "rocksweep/app/cli.hpp"
#include "rocksweep/app/options.hpp"
#include "rocksweep/grid/refine_planes.hpp"
#include "rocksweep/grid/sweep.hpp"

namespace rocksweep {

/// The planes --refine works on: over --refine-axes (two of the grid's axes, by name), by
/// default the spectrum's own a_p0/(alpha g) x omega_p/p. None without --refine. Throws
/// InputError naming --refine-axes when the pair is not two different axes of the grid.
std::optional<RefinePlanes> refine_planes(const SweepSpec& spec, const SweepCommand& cmd);

/// make_sweep_spec(opts) with `cmd`'s refinement: its stride and the pair of axes, in grid
/// order whatever order they were given in. A file records them, and --resume checks them as
/// it checks the integrator's settings: a pass of another refinement would choose other cells.
SweepSpec sweep_spec(const Options& opts, const SweepCommand& cmd);

}  // namespace rocksweep
