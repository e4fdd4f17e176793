// The streaming suite writer: the running file is the suite layout with its result datasets in
// place (ResultStream, result_stream.cpp); the finished one is written once, from it, with the
// products. Why, and what a kill at any instant leaves: docs/streaming.md.
#include "rocksweep/io/suite_stream.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <system_error>

#include "result_columns.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "suite_layout.hpp"

namespace rocksweep {

namespace {

// A record's share of a suite file beside its results: its /records group and attributes and
// its measures, ~1 KB on disk (990 B a motion for 10^5 synthetic motions); the HDF5 library
// holds several times that while it builds the file in memory.
constexpr std::size_t layout_bytes_per_record = 1024;

// Cells of a chunk of the finished file's result datasets: 128 KiB of doubles, as the chunks
// of a dataset written whole (h5::write_dataset).
constexpr std::size_t chunk_cells = 16384;

ResultStream::Shape suite_shape(const SuiteSpec& spec) {
    ResultStream::Shape shape;
    for (const Scenario& s : spec.scenarios) shape.groups.push_back("suite/" + s.name);
    shape.cells_per_group = spec.cells_per_scenario();
    shape.sensitive = spec.sensitivity.on;
    shape.layout_bytes = spec.records.size() * layout_bytes_per_record;
    return shape;
}

/// The chunks of the finished file's result datasets [record, alpha, radius, level]: whole
/// records, as many as fill a chunk, so that a slab of that many records writes whole chunks
/// and each is compressed once; a record larger than a chunk is split on its slowest axes.
/// Empty (contiguous) for results too small to compress.
std::vector<hsize_t> result_chunk(std::span<const hsize_t> dims) {
    auto cells = [](std::span<const hsize_t> d) {
        std::size_t n = 1;
        for (hsize_t x : d) n *= x;
        return n;
    };
    if (cells(dims) * sizeof(double) < h5::compress_min_bytes) return {};
    std::vector<hsize_t> chunk(dims.begin(), dims.end());
    chunk[0] = std::clamp<hsize_t>(chunk_cells / cells(dims.subspan(1)), 1, dims[0]);
    for (std::size_t d = 1; d < chunk.size(); ++d)
        while (chunk[d] > 1 && cells(chunk) > chunk_cells) chunk[d] = (chunk[d] + 1) / 2;
    return chunk;
}

/// fsync of a file HDF5 wrote and closed: on disk before the rename that publishes it.
void sync_file(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw std::system_error(errno, std::generic_category(), "opening " + path);
    const int status = ::fsync(fd), err = errno;
    ::close(fd);
    if (status != 0) throw std::system_error(err, std::generic_category(), "syncing " + path);
}

}  // namespace

SuiteStream::SuiteStream(std::string path, const SuiteSpec& spec, const IntegratorSettings& settings, Provenance prov,
                         bool resume)
    : spec_(spec), settings_(settings), prov_(std::move(prov)), cells_(std::move(path), suite_shape(spec)) {
    const std::string& file = cells_.path();
    std::size_t n_done = 0;
    auto skeleton = [&](const h5::File& f) {
        suite_detail::write_contents(f, spec_, false, {}, n_done, prov_, settings_, CheckpointStats{});
    };
    if (!resume) {
        cells_.create(skeleton, nullptr);
        return;
    }
    bool streaming = false;
    {
        const h5::File f = suite_detail::open_checked(file, spec_, settings_, nullptr);
        finished_ = h5::read_int64_attribute(f, "complete") == 1;
        // A file written whole before streaming has no checkpoint cost to update in place.
        streaming = f.open_group("provenance").has_attribute("checkpoint_s");
    }
    if (finished_) return;
    if (streaming) {
        try {
            cells_.open();
            return;
        } catch (const Hdf5Error&) {
            // Its result datasets are not contiguous: written whole after all.
        }
    }
    // Written whole (compressed) by an older rocksweep: rewritten once in the streaming layout,
    // through NAME.tmp, so that a kill meanwhile leaves the original. It held every result.
    const SweepResults whole = read_suite_results(file, spec_, settings_);
    n_done = whole.done_count();
    cells_.create(skeleton, &whole);
    cells_.publish();
}

std::vector<SuiteFragility> SuiteStream::finish(const std::vector<DamageState>& states, double wall_s) {
    cells_.checkpoint();
    if (cells_.done_count() == spec_.cell_count()) return write_finished(states, wall_s);
    cells_.close_out(false, wall_s, prov_.ranks);
    return {};
}

std::vector<SuiteFragility> SuiteStream::write_finished(const std::vector<DamageState>& states, double wall_s) {
    Provenance prov = prov_;
    prov.wall_s = wall_s;
    const std::vector<hsize_t> dims = grid_dims(suite_detail::result_axes(spec_)), chunk = result_chunk(dims);
    const std::size_t per_record = spec_.cells_per_scenario() / dims[0], rows = chunk.empty() ? dims[0] : chunk[0];
    std::vector<SuiteFragility> fragility;
    auto write = [&](const h5::File& f) {
        fragility.clear();
        suite_detail::write_contents(f, spec_, true, chunk, cells_.done_count(), prov, settings_, cells_.stats());
        SweepResults slab;
        for (std::size_t s = 0; s < spec_.scenarios.size(); ++s) {
            const h5::Group g = f.open_group("suite/" + spec_.scenarios[s].name);
            std::vector<h5::Dataset> columns;
            io::for_each_result_column(slab, spec_.sensitivity.on,
                                       [&](const char* name, auto&) { columns.push_back(g.open_dataset(name)); });
            SuiteProducts products(spec_, s, states);
            for (std::size_t first = 0; first < dims[0]; first += rows) {
                const std::size_t n = std::min<std::size_t>(rows, dims[0] - first);
                cells_.read_cells(s * spec_.cells_per_scenario() + first * per_record, n * per_record, slab);
                std::size_t k = 0;
                io::for_each_result_column(slab, spec_.sensitivity.on, [&](const char*, const auto& column) {
                    using T = typename std::decay_t<decltype(column)>::value_type;
                    h5::write_rows<T>(columns[k++], first, n, std::span<const T>(column));
                });
                products.add(slab, 0, first, n);
            }
            // The fits' errors need each record's runs again, with the fit in hand.
            products.fit();
            for (std::size_t first = 0; first < dims[0]; first += rows) {
                const std::size_t n = std::min<std::size_t>(rows, dims[0] - first);
                cells_.read_cells(s * spec_.cells_per_scenario() + first * per_record, n * per_record, slab);
                products.add_errors(slab, 0, n);
            }
            fragility.push_back(products.fragility());
            suite_detail::write_products(g, spec_, products.overturning(), fragility.back());
        }
    };
    // The running file stays whole until the rename: a kill before it leaves every result there
    // (and --resume writes this file again); one after it leaves this file.
    const std::string& path = cells_.path();
    h5::publish_atomically(path, [&](const std::string& tmp) {
        if (cells_.shape().built_in_memory()) {  // as the running file's skeleton was
            h5::write_h5_image(tmp, path, write);
            return;
        }
        h5::File f = h5::File::create(tmp);
        write(f);
        f.close();
        sync_file(tmp);
    });
    finished_ = true;
    return fragility;
}

}  // namespace rocksweep
