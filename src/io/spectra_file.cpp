// Writing a spectra file: the layout of docs/hdf5.md, whole (write_spectra) or as the skeleton
// the streaming writer fills in place (spectra_stream.cpp).
#include "rocksweep/io/spectra_file.hpp"

#include <algorithm>
#include <cstdint>
#include <set>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/grid_layout.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/results_checksum.hpp"
#include "spectra_layout.hpp"

namespace rocksweep {

using namespace spectra_detail;

namespace {

void check_columns(const SweepSpec& spec, const SweepResults& r) {
    const std::size_t n = spec.cell_count();
    const std::pair<const char*, std::size_t> sizes[] = {
        {"outcome", r.outcome.size()},
        {"max_rotation", r.max_rotation.size()},
        {"impacts", r.impacts.size()},
        {"t_overturn", r.t_overturn.size()},
        {"peak_force_ratio", r.peak_force_ratio.size()},
        {"broken", r.broken.size()},
        {"impacts_total", r.impacts_total.size()},
        {"mu_required", r.mu_required.size()},
        {"pivot_uplift", r.pivot_uplift.size()},
        {"done", r.done.size()},
    };
    for (const auto& [name, size] : sizes)
        if (size != n)
            throw std::invalid_argument(std::string("write_spectra: column ") + name + " has " +
                                        std::to_string(size) + " entries, the sweep has " +
                                        std::to_string(n) + " cells");
}

void check_scenario_names(const SweepSpec& spec) {
    std::set<std::string> seen;
    for (const Scenario& s : spec.scenarios) {
        if (s.name.empty() || s.name == "." || s.name.find('/') != std::string::npos)
            throw InputError("scenario name", "'" + s.name + "'",
                             "a non-empty name without '/' (it names an HDF5 group)");
        if (!seen.insert(s.name).second)
            throw InputError("scenario name", "'" + s.name + "'", "a name used only once");
    }
}

// ---------------------------------------------------------------------------------------
// Writing

// One scenario's block of a column (the columns hold the scenarios one after the other) as a
// dataset; without a column, the dataset the streaming writer fills in place (spectra_stream.cpp).
template <h5::Element T>
h5::Dataset write_column(const GridGroup& grid, const char* name, const std::vector<T>* column, std::size_t scenario) {
    const std::size_t cells = grid.cell_count();
    if (column) return grid.write<T>(name, std::span<const T>(column->data() + scenario * cells, cells));
    return grid.create<T>(name);
}

// Where the columns come from: a SweepResults, or nothing (fixed datasets to fill in place).
struct Columns {
    const SweepResults* r;
    template <class T>
    const std::vector<T>* operator()(std::vector<T> SweepResults::*m) const { return r ? &(r->*m) : nullptr; }
};

void write_root(const h5::File& f, const SweepSpec& spec, const IntegratorSettings& settings,
                const SweepResults* r) {
    h5::write_attribute(f, "title", "rocksweep overturning spectra");
    h5::write_attribute(f, "Conventions", h5::cf_conventions);
    h5::write_attribute(f, "format_version", format_version);
    for (const NamedNumber& n : root_numbers(spec)) h5::write_attribute(f, n.name, n.value);
    // Numbers that are integers in meaning (max_steps, energy_stop) stay float64 like the
    // rest: read back as double they compare exactly (max_steps <= 1e9 < 2^53).
    for (const Setting& x : result_settings(spec, settings)) {
        if (x.is_text) h5::write_attribute(f, x.attribute, x.text);
        else h5::write_attribute(f, x.attribute, x.number);
    }
    h5::write_attribute(f, "friction_coefficient", spec.friction);  // 0: not checked
    h5::write_attribute(f, "parameter_axes", parameter_axis_names(spec));
    h5::write_attribute(f, "spectrum_axes", spectrum_axis_names(spec));
    const auto n_done = r ? static_cast<std::int64_t>(std::count_if(r->done.begin(), r->done.end(),
                                                                    [](std::uint8_t d) { return d != 0; }))
                          : std::int64_t{0};
    const auto n_cells = static_cast<std::int64_t>(spec.cell_count());
    h5::write_attribute(f, "n_cells", n_cells);
    h5::write_attribute(f, "n_done", n_done);
    h5::write_attribute(f, "complete", std::int64_t{n_done == n_cells ? 1 : 0});
}

/// A measured quantity: the grid with its units, long_name and, where there is one, comment.
template <h5::Element T>
void write_measure(const GridGroup& grid, const char* name, const std::vector<T>* column, std::size_t index,
                   const char* units, const char* long_name, const char* comment = nullptr) {
    const h5::Dataset ds = write_column(grid, name, column, index);
    h5::write_attribute(ds, "units", units);
    h5::write_attribute(ds, "long_name", long_name);
    if (comment) h5::write_attribute(ds, "comment", comment);
}

/// A code: the grid with its long_name and the CF flag attributes (flag_values or flag_masks,
/// flag_meanings), and a comment where there is one.
void write_code(const GridGroup& grid, const char* name, const std::vector<std::uint8_t>* column,
                std::size_t index, const char* long_name, const char* flag_kind,
                std::span<const std::uint8_t> flags, const char* meanings, const char* comment = nullptr) {
    const h5::Dataset ds = write_column(grid, name, column, index);
    h5::write_attribute(ds, "long_name", long_name);
    h5::write_attribute(ds, flag_kind, flags);
    h5::write_attribute(ds, "flag_meanings", meanings);
    if (comment) h5::write_attribute(ds, "comment", comment);
}

void write_scenario(const h5::Group& spectra, std::size_t index, const SweepSpec& spec,
                    const SweepResults* r, std::span<const GridAxis> axes) {
    const Scenario& s = spec.scenarios[index];
    const h5::Group g = spectra.create_group(s.name);
    h5::write_attribute(g, "index", index);  // position in the config: group listings sort by name
    // Of results written whole; a streamed file's is filled in place when its run finishes.
    const std::size_t per = spec.cells_per_scenario();
    h5::write_attribute(g, results_checksum_attribute, r ? results_checksum(*r, index * per, per) : std::int64_t{0});
    for (const NamedText& t : scenario_texts(s)) h5::write_attribute(g, t.name, t.value);
    for (const NamedNumber& n : scenario_numbers(s)) h5::write_attribute(g, n.name, n.value);
    const GridGroup grid(g, axes);
    const Columns c{r};

    const std::uint8_t outcomes[] = {0, 1, 2, 255};
    write_code(grid, "outcome", c(&SweepResults::outcome), index, "outcome of the pulse", "flag_values", outcomes,
               "safe overturned_with_impact overturned_without_impact not_converged");
    write_measure(grid, "max_rotation", c(&SweepResults::max_rotation), index, "1", "max |theta| / alpha");
    write_measure(grid, "impacts", c(&SweepResults::impacts), index, "1", "impacts with approach speed above the threshold");
    write_measure(grid, "impacts_total", c(&SweepResults::impacts_total), index, "1",
                  "impacts, the settling one included",
                  "the first impact slower than impact_threshold p alpha puts the block at rest "
                  "(the rest would pile up in finite time); it counts here, not in impacts");
    write_measure(grid, "t_overturn", c(&SweepResults::t_overturn), index, "s",
                  "time at which |theta| reached pi/2",
                  "NaN when the block did not overturn");
    write_measure(grid, "peak_force_ratio", c(&SweepResults::peak_force_ratio), index, "1",
                  "peak anchorage force / F_u",
                  "NaN for a free-standing block");
    const std::uint8_t masks[] = {broken_left, broken_right};
    write_code(grid, "broken", c(&SweepResults::broken), index, "restrainers broken during the run", "flag_masks", masks,
               "left_spring_broken right_spring_broken",
               "bit 1: left spring (works for theta > 0); bit 2: right spring (works for theta < 0)");
    write_measure(grid, "mu_required", c(&SweepResults::mu_required), index, "1",
                  "friction coefficient needed to rock without sliding, max |f_x / f_y|",
                  "base reactions from the motion of the centre of mass (Eq. 16-18); where it exceeds the "
                  "interface's static friction coefficient the block would slide and this cell's "
                  "pure-rocking result does not hold");
    const std::uint8_t uplift[] = {0, 1};
    write_code(grid, "pivot_uplift", c(&SweepResults::pivot_uplift), index, "vertical reaction at the pivot went negative",
               "flag_values", uplift, "pivot_stays_down pivot_lifts",
               "1: the block would jump; the rocking model does not hold there");
    const std::uint8_t done[] = {0, 1, 2};
    write_code(grid, "done", c(&SweepResults::done), index, "cell computed", "flag_values", done, "pending computed inferred",
               "the other datasets are meaningful only where done = 1; done = 2: outcome inferred by "
               "boundary refinement from a uniform square of computed cells (other datasets NaN/0)");
}

void write_provenance(const h5::File& f, const Provenance& prov, const IntegratorSettings& settings) {
    const h5::Group g = io::write_provenance(f, prov, settings);
    // What saving cost the run (the streaming writer fills them in; see docs/hdf5.md).
    h5::write_attribute(g, "checkpoint_s", 0.0);
    h5::write_attribute(g, "checkpoints", std::int64_t{0});
}

}  // namespace

// All objects opened here are closed on return, so the caller can close the file.
void spectra_detail::write_contents(const h5::File& f, const SweepSpec& spec, const SweepResults* r,
                                    const Provenance& prov, const IntegratorSettings& settings) {
    check_scenario_names(spec);
    // The numerics that shape the results are part of the result (root); they stay in
    // /provenance too.
    write_root(f, spec, settings, r);
    h5::write_attribute(f, "rocksweep_version", prov.version);
    const std::vector<GridAxis> axes = grid_axes(spec);
    const h5::Group spectra = f.create_group("spectra");
    for (std::size_t i = 0; i < spec.scenarios.size(); ++i) write_scenario(spectra, i, spec, r, axes);
    write_provenance(f, prov, settings);
}

void write_spectra(const std::string& path, const SweepSpec& spec, const SweepResults& r,
                   const Provenance& prov, const IntegratorSettings& settings) {
    check_columns(spec, r);
    h5::publish_h5_atomically(path, [&](const h5::File& f) { spectra_detail::write_contents(f, spec, &r, prov, settings); });
}

}  // namespace rocksweep
