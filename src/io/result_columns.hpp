#pragma once
/// What every file of sweep results shares (spectra, suite; risk copies a suite's fit status):
/// the result columns of a group of cells with their units and meanings, the block's and a
/// scenario's attributes, and the numerical settings that shape results, each written and
/// compared from one list so that a writer and its resume reader can never disagree. Private
/// to rocksweep_io.
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "rocksweep/grid/sweep.hpp"
#include "rocksweep/io/grid_layout.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/spectra_file.hpp"
#include "rocksweep/physics/integrator.hpp"

namespace rocksweep::io {

struct NamedNumber {
    const char* name;
    double value;
};
struct NamedText {
    const char* name;
    std::string value;
};

/// The block as root attributes: sizes, alpha, p, e, I0/(mR^2), m, g.
std::vector<NamedNumber> block_numbers(const Block& b);
std::vector<NamedNumber> scenario_numbers(const Scenario& s);
std::vector<NamedText> scenario_texts(const Scenario& s);

/// A setting that shapes results without defining the cells: a resume must use the same one,
/// and an error names the option that differs.
struct Setting {
    const char* attribute;
    const char* option;   ///< as the user writes it, without "--"
    std::string text;     ///< what the user gave, for messages and string attributes
    double number = 0.0;  ///< for numeric attributes
    bool is_text = false;
    /// What a file written before this setting existed (without its attribute) was computed
    /// with: nullptr, every file has it; "" unknown, the check is skipped; else that text.
    const char* absent = nullptr;
};
/// The integrator's: method, its step setting, max-steps, energy stop, impact threshold, equations.
std::vector<Setting> numerics_settings(const IntegratorSettings& s, double impact_threshold, Equations equations);

void write_numbers(const h5::Object& obj, std::span<const NamedNumber> numbers);
void write_settings(const h5::Object& obj, std::span<const Setting> settings);

/// Called with what differs, in words; must throw.
using Mismatch = std::function<void(const std::string&)>;
void compare_numbers(const h5::Object& obj, std::span<const NamedNumber> numbers, const Mismatch& mismatch);
void compare_texts(const h5::Object& obj, std::span<const NamedText> texts, const Mismatch& mismatch);
/// Throws InputError naming the option whose value differs from the file's `path`.
void compare_settings(const std::string& path, const h5::Object& obj, std::span<const Setting> settings);

/// A scenario's group: its index, anchorage texts and numbers.
void write_scenario_attributes(const h5::Group& g, std::size_t index, const Scenario& s);

/// Creates every result column as an empty dataset over the grid, with its units and meanings,
/// for a writer to fill: without `chunk` in place (GridGroup::create), with it a slab at a time;
/// `sensitive` adds the suite's column of that name (--check-sensitivity).
void write_result_columns(const GridGroup& grid, std::span<const hsize_t> chunk, bool sensitive);
/// Reads them back into cells [first, ...) of `r`; a dataset of another shape is a mismatch.
void read_result_columns(const h5::Group& g, std::span<const GridAxis> axes, SweepResults& r, std::size_t first,
                         const Mismatch& mismatch);

/// Calls f(name, column) for every result column of `r` a stream writes in place, in writing
/// order: `done` last, so that a cell is marked done only once its values are in the file;
/// `sensitive` (the suite's --check-sensitivity) only when `sensitive` is set.
template <class R, class F>
void for_each_result_column(R& r, bool sensitive, F&& f) {
    f("outcome", r.outcome);
    f("max_rotation", r.max_rotation);
    f("impacts", r.impacts);
    f("impacts_total", r.impacts_total);
    f("t_overturn", r.t_overturn);
    f("peak_force_ratio", r.peak_force_ratio);
    f("broken", r.broken);
    f("mu_required", r.mu_required);
    f("pivot_uplift", r.pivot_uplift);
    if (sensitive) f("sensitive", r.sensitive);
    f("done", r.done);
}

/// The suite's `sensitive` flags (--check-sensitivity), read like the columns above.
void read_sensitive_column(const h5::Group& g, std::span<const GridAxis> axes, SweepResults& r, std::size_t first,
                           const Mismatch& mismatch);

/// /provenance: what produced the file (everything there may differ between two runs): version,
/// config, created_utc, wall_s; returns the group, for a writer's own additions (ranks, where
/// the run had them). Every file rocksweep writes but the basin's has it.
h5::Group write_provenance(const h5::File& f, const Provenance& prov);
/// The same with the ranks and the numerical settings, for a file of sweep results.
h5::Group write_provenance(const h5::File& f, const Provenance& prov, const IntegratorSettings& settings);

/// A dataset of FitStatus codes (the suite file's fit_status, and the risk file's copy of it):
/// its long_name and the CF flag_values and flag_meanings, the codes and names of every status.
void write_fit_status_flags(const h5::Dataset& ds, const std::string& long_name);

/// Root attributes n_cells, n_done, complete.
void write_progress(const h5::Object& obj, const SweepResults& r);

}  // namespace rocksweep::io
