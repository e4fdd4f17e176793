#pragma once
/// The suite file of a running suite, written in place as chunks complete (docs/streaming.md;
/// layout: docs/suite.md). Rank 0 holds only the cells finished since the last checkpoint (the
/// ResultStream shared with `sweep`), and the records' own measures; at the end the products
/// are computed from the file a slab of records at a time, and the finished file, its result
/// datasets compressed, replaces the running one by a rename.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "rocksweep/io/result_stream.hpp"
#include "rocksweep/io/spectra_file.hpp"
#include "rocksweep/records/suite_products.hpp"

namespace rocksweep {

class SuiteStream {
public:
    /// Without `resume`: builds a new file for `spec` at path + ".tmp" that replaces `path` at
    /// the first checkpoint (so an --overwrite's previous file stays until then). With `resume`:
    /// continues `path`, which must be a suite file for the same spec and settings (the checks
    /// and exceptions of read_suite_results); one written whole (before streaming) is first
    /// rewritten in the streaming layout; a finished one is left as it is (finished()).
    /// Throws InputError, std::runtime_error("cannot write PATH: ...") (nothing is left behind).
    SuiteStream(std::string path, const SuiteSpec& spec, const IntegratorSettings& settings, Provenance prov, bool resume);

    /// The file holds every cell and the products (`complete` = 1): nothing is left to do.
    bool finished() const { return finished_; }
    /// Cells done: in the file, plus those added since.
    std::size_t done_count() const { return finished_ ? spec_.cell_count() : cells_.done_count(); }
    /// The `done` bytes of cells [first, first + count) as the file holds them.
    void read_done(std::size_t first, std::size_t count, std::uint8_t* out) const {
        cells_.read_column("done", first, count, out);
    }

    /// Takes finished cells [first, first + count) (any order, each once) until the next checkpoint.
    void add(std::size_t first, std::size_t count, const CellResult* cells) { cells_.add(first, count, cells); }
    /// Bytes held for the next checkpoint.
    std::size_t pending_bytes() const { return cells_.pending_bytes(); }
    /// Writes the cells added since the last checkpoint in place (the first publishes the file).
    /// Throws std::runtime_error("cannot write PATH: ...").
    void checkpoint() { cells_.checkpoint(); }

    /// A last checkpoint. With every cell done: the finished file, the products of `states`
    /// included, written to path + ".tmp" from the running file a slab of records at a time and
    /// renamed onto `path`; returns each scenario's fragility. Otherwise n_done and /provenance
    /// updated in place, and nothing returned. Throws like checkpoint().
    std::vector<SuiteFragility> finish(const std::vector<DamageState>& states, double wall_s);

private:
    std::vector<SuiteFragility> write_finished(const std::vector<DamageState>& states, double wall_s);

    const SuiteSpec& spec_;
    const IntegratorSettings& settings_;
    Provenance prov_;
    ResultStream cells_;
    bool finished_ = false;
};

}  // namespace rocksweep
