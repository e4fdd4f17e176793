#pragma once
/// A suite's made motions measured once over the job rather than on every rank.
#include "rocksweep/parallel/mpi_session.hpp"
#include "rocksweep/records/suite_sweep.hpp"

namespace rocksweep {

/// Fills the measures of the made motions of `spec` (made with SuiteMotions::Measures::none):
/// each rank of `mpi` measures an equal share, rank 0 (the writer) gathers every measure, and
/// every other rank receives only those a level is scaled by (made_measures.hpp). Then checks
/// them on every rank (check_made_measures), so an error is the same everywhere. Collective.
/// docs/synthetic.md, "Cost and scale".
void measure_made_on_ranks(SuiteSpec& spec, const MpiSession& mpi);

}  // namespace rocksweep
