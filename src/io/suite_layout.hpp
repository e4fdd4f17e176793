#pragma once
// Internal to rocksweep_io: the suite file's layout (docs/suite.md) as the streaming writer
// (suite_stream.cpp) lays out its running file and its finished one, and as a resume checks it.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "rocksweep/io/grid_layout.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/result_stream.hpp"
#include "rocksweep/io/suite_file.hpp"

namespace rocksweep::suite_detail {

/// The axes of every scenario's results, slowest first: record, alpha_rad, radius_m, intensity.
std::vector<GridAxis> result_axes(const SuiteSpec& spec);

/// Writes the whole layout but the products, the result datasets empty: without `chunk`
/// contiguous and allocated, to be filled in place (the running file), with it chunked so and
/// compressed, to be filled a slab at a time (the finished file). `finished`: the products
/// follow, so `complete` is 1 when n_done is every cell. Objects opened here are closed on return.
void write_contents(const h5::File& f, const SuiteSpec& spec, bool finished, std::span<const hsize_t> chunk,
                    std::size_t n_done, const Provenance& prov, const IntegratorSettings& settings,
                    const CheckpointStats& saves);

/// A float64 summary over some of the grid's axes, with its units and long_name.
void write_measure_on(const GridGroup& grid, const char* name, const std::vector<double>& v,
                      std::initializer_list<std::string_view> axes, const char* units, const char* long_name);

/// The overturning spectrum and the fragility of one scenario, into its group
/// (suite_products_file.cpp).
void write_products(const h5::Group& scenario, const SuiteSpec& spec, const OverturningSpectrum& o,
                    const SuiteFragility& fr);

/// Opens `path` read-only and makes every check read_suite_results makes (same exceptions);
/// reads the results into `*r` when `r` is given, else checks only their datasets' shapes.
h5::File open_checked(const std::string& path, const SuiteSpec& spec, const IntegratorSettings& settings,
                      SweepResults* r);

}  // namespace rocksweep::suite_detail
