#include "rocksweep/app/made_on_ranks.hpp"

#include <algorithm>

#include "rocksweep/records/made_measures.hpp"

namespace rocksweep {

void measure_made_on_ranks(SuiteSpec& spec, const MpiSession& mpi) {
    if (!spec.motions) return;
    const std::size_t n = spec.motions->size(), ranks = static_cast<std::size_t>(mpi.size());
    const std::size_t rank = static_cast<std::size_t>(mpi.rank());
    // In rounds, so that what one gather brings to rank 0 stays within MPI's int counts and a
    // few tens of MB (1024 motions a rank: ~1 MB a floor) however many motions there are.
    const std::size_t round = 1024 * ranks;
    for (std::size_t start = 0; start < n; start += round) {
        const std::size_t len = std::min(round, n - start);
        const std::size_t lo = start + len * rank / ranks, hi = start + len * (rank + 1) / ranks;
        measure_made_motions(spec, lo, hi - lo);
        if (ranks == 1) continue;
        const std::vector<double> all = mpi.gather(pack_made_measures(spec, lo, hi - lo));
        if (mpi.is_root()) unpack_made_measures(spec, start, all);
    }
    if (ranks > 1) {
        std::vector<double> scaling;
        if (mpi.is_root()) scaling = pack_scaling_measures(spec);
        mpi.broadcast(scaling);
        if (!mpi.is_root()) unpack_scaling_measures(spec, scaling);  // drops its share's spectra too
    }
    check_made_measures(spec);
}

}  // namespace rocksweep
