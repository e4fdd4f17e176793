// The streaming spectra writer: the spectra layout laid out once, then filled in place by the
// ResultStream (result_stream.cpp). Why this design, and what it was measured against:
// docs/streaming.md.
#include "rocksweep/io/spectra_stream.hpp"

#include "rocksweep/core/errors.hpp"
#include "rocksweep/grid/refine.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "spectra_layout.hpp"

namespace rocksweep {

namespace {

ResultStream::Shape spectra_shape(const SweepSpec& spec) {
    ResultStream::Shape shape;
    for (const Scenario& s : spec.scenarios) shape.groups.push_back("spectra/" + s.name);
    shape.cells_per_group = spec.cells_per_scenario();
    return shape;
}

}  // namespace

SpectraStream::SpectraStream(std::string path, const SweepSpec& spec, const IntegratorSettings& settings,
                             Provenance prov, bool resume)
    : spec_(spec), settings_(settings), prov_(std::move(prov)), cells_(std::move(path), spectra_shape(spec)) {
    const std::string& file = cells_.path();
    auto skeleton = [&](const h5::File& f) { spectra_detail::write_contents(f, spec_, nullptr, prov_, settings_); };
    if (!resume) {
        cells_.create(skeleton, nullptr);
        return;
    }
    spectra_detail::open_checked(file, spec_, settings_, nullptr).close();
    try {
        cells_.open();
    } catch (const Hdf5Error&) {
        // Written whole (compressed) by an older rocksweep or by merge: rewritten once in the
        // streaming layout, through NAME.tmp, so that a kill meanwhile leaves the original.
        const SweepResults whole = read_spectra_results(file, spec_, settings_);
        cells_.create(skeleton, &whole);
        cells_.publish();
    }
}

void SpectraStream::read_outcomes(std::size_t scenario, std::size_t first, std::size_t count, std::uint8_t* outcome,
                                  std::uint8_t* done) const {
    const std::size_t cell = scenario * spec_.cells_per_scenario() + first;
    cells_.read_column("outcome", cell, count, outcome);
    cells_.read_column("done", cell, count, done);
}

void SpectraStream::add_inferred(std::size_t scenario, std::size_t first, std::size_t count, const std::uint8_t* outcome,
                                 const std::uint8_t* done_before, const std::uint8_t* done_after) {
    std::vector<ResultStream::Run> runs;
    std::size_t n = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (done_after[i] != cell_inferred || done_before[i] == cell_inferred) continue;
        if (runs.empty() || runs.back().cell + runs.back().count != first + i) runs.push_back({scenario, first + i, n, 0});
        ++runs.back().count, ++n;
    }
    SweepResults cells;  // the empty values of resize(), then the inferred outcome
    cells.resize(n);
    for (const ResultStream::Run& r : runs)
        for (std::size_t j = 0; j < r.count; ++j) {
            cells.outcome[r.from + j] = outcome[r.cell - first + j];
            cells.done[r.from + j] = cell_inferred;
        }
    cells_.write_now(cells, runs);
}

void SpectraStream::finish(double wall_s) {
    cells_.checkpoint();
    cells_.close_out(true, wall_s, prov_.ranks);
}

}  // namespace rocksweep
