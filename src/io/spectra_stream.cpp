// The streaming spectra writer: the file is laid out once, then filled in place by pwrite.
// Why this design, and what it was measured against: docs/streaming.md.
#include "rocksweep/io/spectra_stream.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <system_error>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/grid/refine.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/results_checksum.hpp"
#include "spectra_layout.hpp"

namespace rocksweep {

namespace {

// Grids up to this many bytes of results get their skeleton built in memory and written by
// plain write(), like a whole file, so that a full disk is an errno and never a failure inside
// HDF5's own flush; larger skeletons are created on disk by HDF5 (their storage is a hole).
constexpr std::size_t in_memory_skeleton_bytes = std::size_t{16} << 20;

// Cells read per pread when scanning `done` (1 byte each): what a resume holds at once.
constexpr std::size_t scan_block = std::size_t{1} << 24;

/// The result datasets of a scenario group in writing order: `done` last, so that a cell is
/// marked done only once its values are in the file.
template <class R, class F>
void for_each_column(R& r, F&& f) {
    f("outcome", r.outcome);
    f("max_rotation", r.max_rotation);
    f("impacts", r.impacts);
    f("impacts_total", r.impacts_total);
    f("t_overturn", r.t_overturn);
    f("peak_force_ratio", r.peak_force_ratio);
    f("broken", r.broken);
    f("mu_required", r.mu_required);
    f("pivot_uplift", r.pivot_uplift);
    f("done", r.done);
}
constexpr std::size_t column_count = 10;
constexpr std::size_t done_column = column_count - 1;

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

struct SpectraStream::Placement {
    std::uint64_t offset = 0;
    std::size_t element_bytes = 0;
};

struct SpectraStream::Run {
    std::size_t scenario = 0, cell = 0;  // first cell, within its scenario
    std::size_t from = 0, count = 0;     // its entries in the SweepResults written
};

/// An open file descriptor for pread/pwrite; errors carry errno as std::system_error.
class SpectraStream::Descriptor {
public:
    explicit Descriptor(const std::string& file) : file_(file), fd_(::open(file.c_str(), O_RDWR | O_CLOEXEC)) {
        if (fd_ < 0) throw std::system_error(errno, std::generic_category(), "opening " + file);
    }
    ~Descriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;

    void write_at(const void* data, std::size_t bytes, std::uint64_t offset) const {
        const auto* p = static_cast<const unsigned char*>(data);
        while (bytes > 0) {
            const ssize_t n = ::pwrite(fd_, p, bytes, static_cast<off_t>(offset));
            if (n < 0 && errno == EINTR) continue;  // a signal that only raised a flag
            if (n < 0) fail("writing");
            p += n, bytes -= static_cast<std::size_t>(n), offset += static_cast<std::uint64_t>(n);
        }
    }
    void read_at(void* data, std::size_t bytes, std::uint64_t offset) const {
        auto* p = static_cast<unsigned char*>(data);
        while (bytes > 0) {
            const ssize_t n = ::pread(fd_, p, bytes, static_cast<off_t>(offset));
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) fail("reading");
            if (n == 0) {  // past the end of a sparse file that was cut short: never written
                std::memset(p, 0, bytes);
                return;
            }
            p += n, bytes -= static_cast<std::size_t>(n), offset += static_cast<std::uint64_t>(n);
        }
    }
    void sync() const {
        if (::fdatasync(fd_) != 0) fail("syncing");
    }

private:
    [[noreturn]] void fail(const char* doing) const {
        throw std::system_error(errno, std::generic_category(), std::string(doing) + " " + file_);
    }
    std::string file_;
    int fd_;
};

namespace {

/// Runs `f`, turning any failure to write `path` into the one-line message of a failed save.
template <class F>
void as_save(const std::string& path, F&& f) {
    try {
        f();
    } catch (const InputError&) {
        throw;
    } catch (const Hdf5Error& e) {
        throw h5::write_failure(path, e.sys_errno(), e.what());
    } catch (const std::system_error& e) {
        throw h5::write_failure(path, e.code().value(), e.what());
    }
}

}  // namespace

SpectraStream::SpectraStream(std::string path, const SweepSpec& spec, const IntegratorSettings& settings,
                             Provenance prov, bool resume)
    : path_(std::move(path)), spec_(spec), settings_(settings), prov_(std::move(prov)) {
    if (!resume) {
        create_skeleton(nullptr);
        return;
    }
    spectra_detail::open_checked(path_, spec_, settings_, nullptr).close();
    try {
        locate(path_);
    } catch (const Hdf5Error&) {
        // Written whole (compressed) by an older rocksweep or by merge: rewritten once in the
        // streaming layout, through NAME.tmp, so that a kill meanwhile leaves the original.
        const SweepResults whole = read_spectra_results(path_, spec_, settings_);
        create_skeleton(&whole);
        publish();
    }
    as_save(path_, [&] { fd_ = std::make_unique<Descriptor>(path_); });
    published_ = true;
    count_done();
}

SpectraStream::~SpectraStream() {
    if (published_) return;
    fd_.reset();
    std::error_code ignored;
    std::filesystem::remove(path_ + ".tmp", ignored);
}

void SpectraStream::create_skeleton(const SweepResults* whole) {
    const std::string tmp = path_ + ".tmp";
    auto write = [&](const h5::File& f) { spectra_detail::write_contents(f, spec_, nullptr, prov_, settings_); };
    try {
        as_save(path_, [&] {
            if (spec_.cell_count() * SweepResults::bytes_per_cell() <= in_memory_skeleton_bytes) {
                h5::write_h5_image(tmp, path_, write);
            } else {
                h5::File f = h5::File::create(tmp);
                write(f);
                f.close();
            }
            locate(tmp);
            fd_ = std::make_unique<Descriptor>(tmp);
            if (!whole) return;
            std::vector<Run> runs;
            const std::size_t per = spec_.cells_per_scenario();
            for (std::size_t s = 0; s < spec_.scenarios.size(); ++s) runs.push_back({s, 0, s * per, per});
            write_runs(*whole, runs);
        });
    } catch (...) {
        fd_.reset();
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw;
    }
}

void SpectraStream::locate(const std::string& file) {
    const h5::File f = h5::File::open_read_only(file);
    const h5::Group spectra = f.open_group("spectra");
    place_.assign(spec_.scenarios.size(), {});
    for (std::size_t s = 0; s < spec_.scenarios.size(); ++s) {
        const h5::Group g = spectra.open_group(spec_.scenarios[s].name);
        SweepResults none;
        for_each_column(none, [&](const char* name, auto&) {
            const h5::RawPlacement p = h5::raw_placement(g.open_dataset(name));
            place_[s].push_back({p.offset, p.element_bytes});
        });
    }
}

void SpectraStream::count_done() {
    std::vector<std::uint8_t> block;
    done_count_ = 0;
    for (std::size_t first = 0; first < spec_.cell_count(); first += scan_block) {
        block.resize(std::min(scan_block, spec_.cell_count() - first));
        read_column("done", first, block.size(), block.data());
        done_count_ += static_cast<std::size_t>(std::count_if(block.begin(), block.end(), [](std::uint8_t d) { return d != 0; }));
    }
}

void SpectraStream::read_column(std::string_view name, std::size_t first, std::size_t count, void* out) const {
    std::size_t k = 0, column = column_count;
    SweepResults none;
    for_each_column(none, [&](const char* n, auto&) {
        if (n == name) column = k;
        ++k;
    });
    if (column == column_count) throw std::invalid_argument("read_column: no result dataset " + std::string(name));
    const std::size_t per = spec_.cells_per_scenario();
    auto* bytes = static_cast<unsigned char*>(out);
    as_save(path_, [&] {
        while (count > 0) {
            const std::size_t s = first / per, cell = first % per, n = std::min(count, per - cell);
            const Placement& p = place_[s][column];
            fd_->read_at(bytes, n * p.element_bytes, p.offset + cell * p.element_bytes);
            first += n, count -= n, bytes += n * p.element_bytes;
        }
    });
}

void SpectraStream::read_outcomes(std::size_t scenario, std::size_t first, std::size_t count, std::uint8_t* outcome,
                                  std::uint8_t* done) const {
    as_save(path_, [&] {  // both columns are one byte a cell
        fd_->read_at(outcome, count, place_[scenario][0].offset + first);
        fd_->read_at(done, count, place_[scenario][done_column].offset + first);
    });
}

void SpectraStream::add(std::size_t first, std::size_t count, const CellResult* cells) {
    for (std::size_t i = 0; i < count; ++i) pending_index_.push_back(first + i);
    pending_cells_.insert(pending_cells_.end(), cells, cells + count);
    done_count_ += count;
}

void SpectraStream::add_inferred(std::size_t scenario, std::size_t first, std::size_t count, const std::uint8_t* outcome,
                                 const std::uint8_t* done_before, const std::uint8_t* done_after) {
    std::vector<Run> runs;
    std::size_t n = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (done_after[i] != cell_inferred || done_before[i] == cell_inferred) continue;
        if (runs.empty() || runs.back().cell + runs.back().count != first + i) runs.push_back({scenario, first + i, n, 0});
        ++runs.back().count, ++n;
    }
    SweepResults cells;  // the empty values of resize(), then the inferred outcome
    cells.resize(n);
    for (const Run& r : runs)
        for (std::size_t j = 0; j < r.count; ++j) {
            cells.outcome[r.from + j] = outcome[r.cell - first + j];
            cells.done[r.from + j] = cell_inferred;
        }
    done_count_ += n;
    if (!runs.empty()) as_save(path_, [&] {
        forget_checksums();
        write_runs(cells, runs);
    });
}

void SpectraStream::write_runs(const SweepResults& cells, const std::vector<Run>& runs) {
    // Values first, synced, then `done`: a cell never reads done before its values are there.
    std::size_t k = 0;
    for_each_column(cells, [&](const char*, const auto& column) {
        if (k == done_column) fd_->sync();
        for (const Run& r : runs) {
            const Placement& p = place_[r.scenario][k];
            fd_->write_at(column.data() + r.from, r.count * p.element_bytes, p.offset + r.cell * p.element_bytes);
        }
        ++k;
    });
    fd_->sync();
}

void SpectraStream::checkpoint() {
    const auto t0 = std::chrono::steady_clock::now();
    // In index order, as runs of contiguous cells within a scenario: few, long writes.
    std::vector<std::size_t> order(pending_index_.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return pending_index_[a] < pending_index_[b]; });
    SweepResults cells;
    cells.resize(order.size());
    std::vector<Run> runs;
    const std::size_t per = spec_.cells_per_scenario();
    for (std::size_t j = 0; j < order.size(); ++j) {
        const std::size_t index = pending_index_[order[j]];
        cells.store(j, pending_cells_[order[j]]);
        const std::size_t s = index / per, cell = index % per;
        if (runs.empty() || runs.back().scenario != s || runs.back().cell + runs.back().count != cell)
            runs.push_back({s, cell, j, 0});
        ++runs.back().count;
    }
    as_save(path_, [&] {
        forget_checksums();
        write_runs(cells, runs);
        if (!published_) publish();
        update_counts(false, nullptr);
    });
    stats_.cells += order.size();
    pending_index_.clear();
    pending_cells_.clear();
    pending_index_.shrink_to_fit();  // the memory bound holds between checkpoints too
    pending_cells_.shrink_to_fit();
    ++stats_.checkpoints;
    stats_.seconds += seconds_since(t0);
}

void SpectraStream::publish() {
    std::error_code ec;
    std::filesystem::rename(path_ + ".tmp", path_, ec);
    if (ec) throw InputError("output", path_, "a writable location (renaming " + path_ + ".tmp onto it: " + ec.message() + ")");
    published_ = true;
}

void SpectraStream::update_counts(bool final, const double* wall_s) {
    // In place, values of fixed size: no metadata moves, so a kill here leaves a readable file.
    h5::File f = h5::File::open_for_update(path_);
    const auto n = static_cast<std::int64_t>(spec_.cell_count()), done = static_cast<std::int64_t>(done_count_);
    h5::update_attribute(f, "n_done", done);
    if (final) {
        h5::update_attribute(f, "complete", std::int64_t{done == n ? 1 : 0});
        const h5::Group g = f.open_group("provenance");
        h5::update_attribute(g, "wall_s", *wall_s);
        h5::update_attribute(g, "ranks", std::int64_t{prov_.ranks});
        h5::update_attribute(g, "checkpoint_s", stats_.seconds);
        h5::update_attribute(g, "checkpoints", static_cast<std::int64_t>(stats_.checkpoints));
        store_checksums(f);
    }
    f.close();
}

void SpectraStream::forget_checksums() {
    // Before the first change to a published file (a resume): a kill from here on must not leave
    // a checksum that no longer matches. A new file's are 0 until it finishes.
    if (!published_ || checksums_forgotten_) return;
    h5::File f = h5::File::open_for_update(path_);
    {  // closed before the file
        const h5::Group spectra = f.open_group("spectra");
        for (const Scenario& sc : spec_.scenarios) {
            const h5::Group g = spectra.open_group(sc.name);
            if (g.has_attribute(results_checksum_attribute)) h5::update_attribute(g, results_checksum_attribute, std::int64_t{0});
        }
    }
    f.close();
    checksums_forgotten_ = true;
}

void SpectraStream::store_checksums(const h5::File& f) {
    // Hashed from the file as it now holds the cells, a block at a time: rank 0 never holds
    // the whole grid. A file from before checksums has no attribute to fill, and stays without.
    const h5::Group spectra = f.open_group("spectra");
    const std::size_t per = spec_.cells_per_scenario();
    std::vector<unsigned char> block;
    for (std::size_t s = 0; s < spec_.scenarios.size(); ++s) {
        const h5::Group g = spectra.open_group(spec_.scenarios[s].name);
        if (!g.has_attribute(results_checksum_attribute)) continue;
        Fnv1a64 h;
        std::size_t k = 0;
        SweepResults none;
        for_each_column(none, [&](const char* name, auto&) {
            const std::size_t bytes = place_[s][k++].element_bytes;
            for (std::size_t first = 0; first < per; first += scan_block) {
                const std::size_t n = std::min(scan_block, per - first);
                block.resize(n * bytes);
                read_column(name, s * per + first, n, block.data());
                h.add(block.data(), block.size());
            }
        });
        h5::update_attribute(g, results_checksum_attribute, h.stored());
    }
    checksums_forgotten_ = false;
}

void SpectraStream::finish(double wall_s) {
    checkpoint();
    as_save(path_, [&] { update_counts(true, &wall_s); });
}

}  // namespace rocksweep
