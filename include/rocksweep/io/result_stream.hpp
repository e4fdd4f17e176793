#pragma once
/// Result datasets filled in place while a run goes on: what the spectra writer
/// (spectra_stream.hpp) and the suite writer (suite_stream.hpp) share. Why this design and
/// what a kill at any instant leaves: docs/streaming.md.
///
/// The file is laid out once with its result datasets contiguous and allocated (never filled:
/// a hole on disk); rank 0 then holds only the cells finished since the last checkpoint, and a
/// checkpoint pwrites their bytes at the datasets' offsets (values, fdatasync, then `done`,
/// fdatasync, then the root attribute n_done in place): no HDF5 metadata ever moves.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "rocksweep/grid/sweep.hpp"

namespace rocksweep::h5 {
class File;
}

namespace rocksweep {

/// What the checkpoints of a run cost, for the log line and /provenance.
struct CheckpointStats {
    std::size_t checkpoints = 0;
    double seconds = 0.0;       ///< wall time spent writing and syncing
    std::uint64_t cells = 0;    ///< cells written
};

class ResultStream {
public:
    /// Where the cells are: one group per scenario (a path from the root, "spectra/free"), each
    /// holding `cells_per_group` cells of every result column, cell i of the run in group
    /// i / cells_per_group; `sensitive`: the suite's column of that name is one of them.
    struct Shape {
        std::vector<std::string> groups;
        std::size_t cells_per_group = 0;
        bool sensitive = false;
        /// What the file holds beside its result datasets, estimated (a suite's /records: a group
        /// and measures per record): with the results, it decides whether the file is built in memory.
        std::size_t layout_bytes = 0;
        std::size_t cell_count() const { return groups.size() * cells_per_group; }
        /// Whether the file is built in memory and written by plain write(), like a whole file,
        /// so that a full disk is an errno and never a failure inside HDF5's own flush: up to
        /// 16 MB of results, uncompressed, and layout. Larger files are created on disk by HDF5.
        bool built_in_memory() const {
            return cell_count() * SweepResults::bytes_per_cell() + layout_bytes <= (std::size_t{16} << 20);
        }
    };
    /// Cells [cell, cell + count) of group `group`, taken from entries [from, from + count) of
    /// the SweepResults written.
    struct Run {
        std::size_t group = 0, cell = 0;
        std::size_t from = 0, count = 0;
    };
    /// Writes a file's whole layout into `f`, its result datasets by h5::create_fixed_dataset.
    using Skeleton = std::function<void(const h5::File& f)>;

    /// Nothing is opened yet: create() or open() follows.
    ResultStream(std::string path, Shape shape);
    ~ResultStream();  ///< removes path + ".tmp" if no checkpoint published it
    ResultStream(const ResultStream&) = delete;
    ResultStream& operator=(const ResultStream&) = delete;

    /// Builds the file at path + ".tmp" (in memory and written by write() when its results are
    /// small, so that a full disk is an errno), holding `whole`'s cells if given (a file written
    /// whole, converted), and keeps it open. On failure nothing is left behind.
    /// Throws std::runtime_error("cannot write PATH: ...").
    void create(const Skeleton& skeleton, const SweepResults* whole);
    /// Continues the file at `path` and counts its cells done (reading `done` a block at a time).
    /// Throws Hdf5Error when its result datasets are not in the streaming layout (a file
    /// written whole, with compressed datasets), std::runtime_error on a read error.
    void open();
    /// Renames path + ".tmp" onto `path`. Throws InputError when it cannot.
    void publish();
    bool published() const { return published_; }
    /// Whether the file opened was closed out (close_out() stored its checksums, or it has none):
    /// a run killed after its last cell was written but before its close-out holds every cell
    /// and must still be closed out.
    bool closed_out() const { return closed_out_; }

    /// Cells done (computed or inferred): in the file, plus those added since.
    std::size_t done_count() const { return done_count_; }
    /// Column `name` of cells [first, first + count) as the file holds them, into `out`, an
    /// array of the dataset's element type. Throws std::invalid_argument for an unknown name.
    void read_column(std::string_view name, std::size_t first, std::size_t count, void* out) const;
    /// Every column of cells [first, first + count) into `out` (resized to count).
    void read_cells(std::size_t first, std::size_t count, SweepResults& out) const;

    /// Takes finished cells [first, first + count) (any order, each once) until the next checkpoint.
    void add(std::size_t first, std::size_t count, const CellResult* cells);
    /// Bytes held for the next checkpoint.
    std::size_t pending_bytes() const { return pending_cells_.size() * (sizeof(CellResult) + sizeof(std::size_t)); }
    /// Writes `runs` of `cells` now, counted as done (a cell written twice is the caller's error).
    void write_now(const SweepResults& cells, const std::vector<Run>& runs);

    /// Writes the cells added since the last checkpoint and syncs them, then n_done; the first
    /// one publishes the file. Throws std::runtime_error("cannot write PATH: ...").
    void checkpoint();
    /// In place: n_done, `complete` (1 if `complete` and every cell is done), /provenance's
    /// wall_s, ranks, checkpoint_s and checkpoints, and each group's checksum of its results
    /// where it has one (results_checksum.hpp). Throws like checkpoint().
    void close_out(bool complete, double wall_s, std::int64_t ranks);

    const CheckpointStats& stats() const { return stats_; }
    const std::string& path() const { return path_; }
    const Shape& shape() const { return shape_; }

private:
    struct Placement;  // where one dataset's bytes are
    class Descriptor;  // the open file, for pread/pwrite

    void locate(const std::string& file);
    void count_done();
    void write_runs(const SweepResults& cells, const std::vector<Run>& runs);
    void forget_checksums();
    void store_checksums(const h5::File& f);

    std::string path_;
    Shape shape_;
    std::vector<std::vector<Placement>> place_;  // [group][column]
    std::unique_ptr<Descriptor> fd_;
    bool published_ = false;
    bool checksums_forgotten_ = false;  // the file's checksums are 0 until close_out() stores them
    bool closed_out_ = false;
    std::size_t done_count_ = 0;
    std::vector<std::size_t> pending_index_;
    std::vector<CellResult> pending_cells_;
    CheckpointStats stats_;
};

/// Runs `f`, turning any failure to write `path` (Hdf5Error, std::system_error) into the
/// one-line message of a failed save; InputError passes unchanged.
void as_save(const std::string& path, const std::function<void()>& f);

}  // namespace rocksweep
