#pragma once
/// The spectra file of a running sweep, written as chunks complete (docs/streaming.md;
/// layout: docs/hdf5.md). Rank 0 holds only the cells finished since the last checkpoint; a checkpoint
/// writes those cells' bytes in place and costs in proportion to them, not to the file.
///
/// The file's result datasets are contiguous and allocated when it is created, so a checkpoint
/// changes no HDF5 metadata: it is a few pwrite calls into space that already exists, data
/// columns first, then (after fdatasync) the `done` column. A kill at any instant therefore
/// leaves a file that every reader opens, in which each cell with done != 0 holds its final
/// values; --resume recomputes the rest, and the results are bitwise those of an uninterrupted
/// run. (docs/streaming.md says why this was chosen over a journal, SWMR and parallel HDF5.)
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "rocksweep/grid/sweep.hpp"
#include "rocksweep/io/result_stream.hpp"
#include "rocksweep/io/spectra_file.hpp"

namespace rocksweep {

class SpectraStream {
public:
    /// Without `resume`: builds a new file for `spec` at path + ".tmp" (a 0-byte-per-cell
    /// skeleton: the storage is a hole until written) that replaces `path` at the first
    /// checkpoint, so that `path` (say the previous file of an --overwrite) is untouched until
    /// there is something to show. With `resume`: continues `path`, which must be a file for the
    /// same sweep and settings (the checks and exceptions of read_spectra_results); a file
    /// written whole by an older rocksweep or by merge is first rewritten in the streaming layout.
    /// Throws InputError (bad file or scenario names), std::runtime_error("cannot write PATH:
    /// ...") when the file cannot be written (e.g. a full disk: nothing is left behind).
    SpectraStream(std::string path, const SweepSpec& spec, const IntegratorSettings& settings, Provenance prov,
                  bool resume);
    // Its ResultStream removes path + ".tmp" if no checkpoint published it.
    SpectraStream(const SpectraStream&) = delete;
    SpectraStream& operator=(const SpectraStream&) = delete;

    /// Cells done (computed or inferred): in the file, plus those added since.
    std::size_t done_count() const { return cells_.done_count(); }
    /// Whether the file resumed was closed out by finish(): one killed (or converted) after its
    /// last cell was written holds every cell but still needs its finish().
    bool closed_out() const { return cells_.closed_out(); }
    /// Result dataset `name` (e.g. "done", "mu_required") of cells [first, first + count), as
    /// the file holds it (cells added since the last checkpoint read 0), into `out`, an array
    /// of the dataset's element type (docs/hdf5.md). Throws std::invalid_argument for an unknown
    /// name, std::runtime_error on a read error.
    void read_column(std::string_view name, std::size_t first, std::size_t count, void* out) const {
        cells_.read_column(name, first, count, out);
    }
    /// `outcome` and `done` of `count` cells of one scenario from its cell `first`, as the file
    /// holds them (refinement reads one spectrum, a plane of the grid, at a time).
    void read_outcomes(std::size_t scenario, std::size_t first, std::size_t count, std::uint8_t* outcome,
                       std::uint8_t* done) const;

    /// Takes finished cells [first, first + count) (any order, each cell once) until the next
    /// checkpoint.
    void add(std::size_t first, std::size_t count, const CellResult* cells) { cells_.add(first, count, cells); }
    /// Bytes held for the next checkpoint.
    std::size_t pending_bytes() const { return cells_.pending_bytes(); }
    /// Of the `count` cells of `scenario` from its cell `first`, marks those whose `done_after` is
    /// cell_inferred and `done_before` is not as inferred, with `outcome` (the other columns take
    /// the empty values NaN / 0), and writes them now.
    void add_inferred(std::size_t scenario, std::size_t first, std::size_t count, const std::uint8_t* outcome,
                      const std::uint8_t* done_before, const std::uint8_t* done_after);

    /// Writes the cells added since the last checkpoint and syncs them, then the root attribute
    /// n_done; the first one also publishes the file under `path`. Throws std::runtime_error("cannot write PATH: ...").
    void checkpoint() { cells_.checkpoint(); }
    /// A last checkpoint, then the root attributes n_done and complete, /provenance (wall_s,
    /// ranks, checkpoint cost) and each scenario's checksum of its results (results_checksum.hpp).
    /// Throws like checkpoint().
    void finish(double wall_s);

    const CheckpointStats& stats() const { return cells_.stats(); }
    const std::string& path() const { return cells_.path(); }

private:
    const SweepSpec& spec_;
    const IntegratorSettings& settings_;
    Provenance prov_;
    ResultStream cells_;
};

}  // namespace rocksweep
