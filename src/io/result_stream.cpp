// Result datasets filled in place by pwrite: the part of the streaming writers that knows
// nothing of spectra or suites. Why this design, and what it was measured against:
// docs/streaming.md.
#include "rocksweep/io/result_stream.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <system_error>

#include "result_columns.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/results_checksum.hpp"

namespace rocksweep {

namespace {

// Cells read per pread when scanning `done` (1 byte each): what a resume holds at once.
constexpr std::size_t scan_block = std::size_t{1} << 24;

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

void as_save(const std::string& path, const std::function<void()>& f) {
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

struct ResultStream::Placement {
    std::uint64_t offset = 0;
    std::size_t element_bytes = 0;
};

/// An open file descriptor for pread/pwrite; errors carry errno as std::system_error.
class ResultStream::Descriptor {
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

ResultStream::ResultStream(std::string path, Shape shape) : path_(std::move(path)), shape_(std::move(shape)) {}

ResultStream::~ResultStream() {
    if (published_) return;
    fd_.reset();
    std::error_code ignored;
    std::filesystem::remove(path_ + ".tmp", ignored);
}

void ResultStream::create(const Skeleton& skeleton, const SweepResults* whole) {
    const std::string tmp = path_ + ".tmp";
    try {
        as_save(path_, [&] {
            if (shape_.built_in_memory()) {  // else on disk, its storage a hole
                h5::write_h5_image(tmp, path_, skeleton);
            } else {
                h5::File f = h5::File::create(tmp);
                skeleton(f);
                f.close();
            }
            locate(tmp);
            fd_ = std::make_unique<Descriptor>(tmp);
            if (!whole) return;
            std::vector<Run> runs;
            const std::size_t per = shape_.cells_per_group;
            for (std::size_t g = 0; g < shape_.groups.size(); ++g) runs.push_back({g, 0, g * per, per});
            write_runs(*whole, runs);
            done_count_ = whole->done_count();
        });
    } catch (...) {
        fd_.reset();
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw;
    }
}

void ResultStream::open() {
    locate(path_);
    as_save(path_, [&] { fd_ = std::make_unique<Descriptor>(path_); });
    published_ = true;
    count_done();
    const h5::File f = h5::File::open_read_only(path_);
    closed_out_ = true;
    for (const std::string& name : shape_.groups) {  // each closed before the file
        const h5::Group g = f.open_group(name);
        if (g.has_attribute(results_checksum_attribute) && h5::read_int64_attribute(g, results_checksum_attribute) == 0)
            closed_out_ = false;
    }
}

void ResultStream::locate(const std::string& file) {
    const h5::File f = h5::File::open_read_only(file);
    place_.assign(shape_.groups.size(), {});
    for (std::size_t g = 0; g < shape_.groups.size(); ++g) {
        const h5::Group group = f.open_group(shape_.groups[g]);
        SweepResults none;
        io::for_each_result_column(none, shape_.sensitive, [&](const char* name, auto&) {
            const h5::RawPlacement p = h5::raw_placement(group.open_dataset(name));
            place_[g].push_back({p.offset, p.element_bytes});
        });
    }
}

void ResultStream::count_done() {
    std::vector<std::uint8_t> block;
    done_count_ = 0;
    for (std::size_t first = 0; first < shape_.cell_count(); first += scan_block) {
        block.resize(std::min(scan_block, shape_.cell_count() - first));
        read_column("done", first, block.size(), block.data());
        done_count_ += static_cast<std::size_t>(std::count_if(block.begin(), block.end(), [](std::uint8_t d) { return d != 0; }));
    }
}

void ResultStream::read_column(std::string_view name, std::size_t first, std::size_t count, void* out) const {
    std::size_t k = 0, column = SIZE_MAX;
    SweepResults none;
    io::for_each_result_column(none, shape_.sensitive, [&](const char* n, auto&) {
        if (n == name) column = k;
        ++k;
    });
    if (column == SIZE_MAX) throw std::invalid_argument("read_column: no result dataset " + std::string(name));
    const std::size_t per = shape_.cells_per_group;
    auto* bytes = static_cast<unsigned char*>(out);
    as_save(path_, [&] {
        while (count > 0) {
            const std::size_t g = first / per, cell = first % per, n = std::min(count, per - cell);
            const Placement& p = place_[g][column];
            fd_->read_at(bytes, n * p.element_bytes, p.offset + cell * p.element_bytes);
            first += n, count -= n, bytes += n * p.element_bytes;
        }
    });
}

void ResultStream::read_cells(std::size_t first, std::size_t count, SweepResults& out) const {
    out.resize(count);
    io::for_each_result_column(out, shape_.sensitive,
                               [&](const char* name, auto& column) { read_column(name, first, count, column.data()); });
}

void ResultStream::add(std::size_t first, std::size_t count, const CellResult* cells) {
    for (std::size_t i = 0; i < count; ++i) pending_index_.push_back(first + i);
    pending_cells_.insert(pending_cells_.end(), cells, cells + count);
    done_count_ += count;
}

void ResultStream::write_now(const SweepResults& cells, const std::vector<Run>& runs) {
    if (runs.empty()) return;
    as_save(path_, [&] {
        forget_checksums();
        write_runs(cells, runs);
    });
    for (const Run& r : runs) done_count_ += r.count;
}

void ResultStream::write_runs(const SweepResults& cells, const std::vector<Run>& runs) {
    // Values first, synced, then `done`: a cell never reads done before its values are there.
    std::size_t k = 0;
    io::for_each_result_column(cells, shape_.sensitive, [&](const char* name, const auto& column) {
        if (std::string_view(name) == "done") fd_->sync();
        for (const Run& r : runs) {
            const Placement& p = place_[r.group][k];
            fd_->write_at(column.data() + r.from, r.count * p.element_bytes, p.offset + r.cell * p.element_bytes);
        }
        ++k;
    });
    fd_->sync();
}

void ResultStream::checkpoint() {
    const auto t0 = std::chrono::steady_clock::now();
    // In index order, as runs of contiguous cells within a group: few, long writes.
    std::vector<std::size_t> order(pending_index_.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return pending_index_[a] < pending_index_[b]; });
    SweepResults cells;
    cells.resize(order.size());
    std::vector<Run> runs;
    const std::size_t per = shape_.cells_per_group;
    for (std::size_t j = 0; j < order.size(); ++j) {
        const std::size_t index = pending_index_[order[j]];
        cells.store(j, pending_cells_[order[j]]);
        const std::size_t g = index / per, cell = index % per;
        if (runs.empty() || runs.back().group != g || runs.back().cell + runs.back().count != cell)
            runs.push_back({g, cell, j, 0});
        ++runs.back().count;
    }
    as_save(path_, [&] {
        forget_checksums();
        write_runs(cells, runs);
        if (!published_) publish();
        h5::File f = h5::File::open_for_update(path_);  // in place, a value of fixed size
        h5::update_attribute(f, "n_done", static_cast<std::int64_t>(done_count_));
        f.close();
    });
    stats_.cells += order.size();
    pending_index_.clear();
    pending_cells_.clear();
    pending_index_.shrink_to_fit();  // the memory bound holds between checkpoints too
    pending_cells_.shrink_to_fit();
    ++stats_.checkpoints;
    stats_.seconds += seconds_since(t0);
}

void ResultStream::publish() {
    std::error_code ec;
    std::filesystem::rename(path_ + ".tmp", path_, ec);
    if (ec) throw InputError("output", path_, "a writable location (renaming " + path_ + ".tmp onto it: " + ec.message() + ")");
    published_ = true;
}

void ResultStream::close_out(bool complete, double wall_s, std::int64_t ranks) {
    // In place, values of fixed size: no metadata moves, so a kill here leaves a readable file.
    as_save(path_, [&] {
        h5::File f = h5::File::open_for_update(path_);
        const auto n = static_cast<std::int64_t>(shape_.cell_count()), done = static_cast<std::int64_t>(done_count_);
        h5::update_attribute(f, "n_done", done);
        h5::update_attribute(f, "complete", std::int64_t{complete && done == n ? 1 : 0});
        {  // closed before the file
            const h5::Group g = f.open_group("provenance");
            h5::update_attribute(g, "wall_s", wall_s);
            h5::update_attribute(g, "ranks", ranks);
            h5::update_attribute(g, "checkpoint_s", stats_.seconds);
            h5::update_attribute(g, "checkpoints", static_cast<std::int64_t>(stats_.checkpoints));
        }
        store_checksums(f);
        f.close();
    });
}

void ResultStream::forget_checksums() {
    // Before the first change to a published file (a resume): a kill from here on must not leave
    // a checksum that no longer matches. A new file's are 0 until it finishes.
    if (!published_ || checksums_forgotten_) return;
    h5::File f = h5::File::open_for_update(path_);
    for (const std::string& name : shape_.groups) {  // each closed before the file
        const h5::Group g = f.open_group(name);
        if (g.has_attribute(results_checksum_attribute)) h5::update_attribute(g, results_checksum_attribute, std::int64_t{0});
    }
    f.close();
    checksums_forgotten_ = true;
}

void ResultStream::store_checksums(const h5::File& f) {
    // Hashed from the file as it now holds the cells, a block at a time: rank 0 never holds
    // the whole grid. A file without the attribute (from before checksums, or a suite's) has
    // none to fill, and stays without.
    const std::size_t per = shape_.cells_per_group;
    std::vector<unsigned char> block;
    for (std::size_t g = 0; g < shape_.groups.size(); ++g) {
        const h5::Group group = f.open_group(shape_.groups[g]);
        if (!group.has_attribute(results_checksum_attribute)) continue;
        Fnv1a64 h;
        std::size_t k = 0;
        SweepResults none;
        io::for_each_result_column(none, shape_.sensitive, [&](const char* name, auto&) {
            const std::size_t bytes = place_[g][k++].element_bytes;
            for (std::size_t first = 0; first < per; first += scan_block) {
                const std::size_t n = std::min(scan_block, per - first);
                block.resize(n * bytes);
                read_column(name, g * per + first, n, block.data());
                h.add(block.data(), block.size());
            }
        });
        h5::update_attribute(group, results_checksum_attribute, h.stored());
    }
    checksums_forgotten_ = false;
}

}  // namespace rocksweep
