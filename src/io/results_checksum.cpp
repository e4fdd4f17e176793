#include "rocksweep/io/results_checksum.hpp"

namespace rocksweep {

std::int64_t results_checksum(const SweepResults& r, std::size_t first, std::size_t count) {
    Fnv1a64 h;
    const auto add = [&](const auto& column) { h.add(column.data() + first, count * sizeof(column[0])); };
    // The order of the streaming writer's columns (spectra_stream.cpp), which hashes the file.
    add(r.outcome);
    add(r.max_rotation);
    add(r.impacts);
    add(r.impacts_total);
    add(r.t_overturn);
    add(r.peak_force_ratio);
    add(r.broken);
    add(r.mu_required);
    add(r.pivot_uplift);
    add(r.done);
    return h.stored();
}

}  // namespace rocksweep
