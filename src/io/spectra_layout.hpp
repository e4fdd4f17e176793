#pragma once
// Internal to rocksweep_io: what the whole-file writer (spectra_file.cpp) and the streaming
// writer (spectra_stream.cpp) share, so that both write and check one layout.
#include <string>

#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/spectra_file.hpp"

namespace rocksweep::spectra_detail {

/// Writes the whole layout into `f`. With `r` the result datasets hold its columns (compressed
/// where large); without, they are created by h5::create_fixed_dataset: contiguous, allocated,
/// unwritten, for the streaming writer to fill in place. Objects opened here are closed on return.
void write_contents(const h5::File& f, const SweepSpec& spec, const SweepResults* r, const Provenance& prov,
                    const IntegratorSettings& settings);

/// Opens `path` read-only and makes every check read_spectra_results makes (same exceptions);
/// reads the results into `*r` when `r` is given. Returns the open file.
h5::File open_checked(const std::string& path, const SweepSpec& spec, const IntegratorSettings& settings,
                      SweepResults* r);

}  // namespace rocksweep::spectra_detail
