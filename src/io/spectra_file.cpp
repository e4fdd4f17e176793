#include "rocksweep/io/spectra_file.hpp"

#include <algorithm>
#include <optional>
#include <cmath>
#include <cstdint>
#include <set>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/grid_layout.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "spectra_layout.hpp"

namespace rocksweep {

namespace {

// Bumped when the layout changes in a way a reader must know about. 2: the axes moved from
// /axes into every scenario group, where netCDF-4 readers look for dimensions.
constexpr std::int64_t format_version = 2;

// The axes of every scenario's grid, slowest first: they alone shape the layout.
std::vector<GridAxis> grid_axes(const SweepSpec& spec) {
    return {
        {"amplitude_ratio", "1", "a_p0 / (alpha g)", spec.amplitude_ratio.values()},
        {"omega_ratio", "1", "omega_p / p", spec.omega_ratio.values()},
    };
}

// Attributes that define the cells: written by write_spectra and compared by
// read_spectra_results, so the two can never disagree about what "the same sweep" means.
struct NamedNumber {
    const char* name;
    double value;
};

std::vector<NamedNumber> root_numbers(const SweepSpec& spec) {
    const Block& b = spec.block;
    return {
        {"half_width_m", b.half_width_m()},
        {"half_height_m", b.half_height_m()},
        {"radius_m", b.radius_m},
        {"alpha_rad", b.alpha_rad},
        {"p_rad_s", b.p()},
        {"e", b.e},
        {"inertia_ratio", b.inertia_ratio},
        {"mass_kg", b.mass_kg},
        {"gravity_m_s2", b.gravity},
        {"phase_rad", spec.phase},
        {"vertical_g", spec.vertical_g},
        {"vertical_phase_rad", spec.vertical_phase},
    };
}

std::vector<NamedNumber> scenario_numbers(const Scenario& s) {
    const Anchorage& a = s.anchorage;
    return {
        {"theta_f_ratio", s.theta_f_ratio}, {"kmin_ratio", s.kmin_ratio},
        {"k_max_N_per_m", a.k_max},         {"k_min_N_per_m", a.k_min},
        {"strength_N", a.strength_n},       {"theta_f_rad", a.theta_f_rad},
    };
}

struct NamedText {
    const char* name;
    std::string value;
};

std::vector<NamedText> scenario_texts(const Scenario& s) {
    return {{"anchorage", to_string(s.anchorage.kind)},
            {"break_rule", to_string(s.anchorage.break_rule)},
            {"adaptive_law", to_string(s.anchorage.law)}};
}

bool same_number(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// The settings that shape results without defining the cells: a resume must use the same
// ones, and an error names the option that differs.
struct Setting {
    const char* attribute;
    const char* option;        // as the user writes it, without "--"
    std::string text;          // what the user gave, for messages and string attributes
    double number = 0.0;       // for numeric attributes
    bool is_text = false;
};

std::vector<Setting> result_settings(const SweepSpec& spec, const IntegratorSettings& s) {
    auto num = [](const char* attr, const char* option, double x, std::string shown) {
        return Setting{attr, option, std::move(shown), x, false};
    };
    // The method is compared first; of the two step settings only the method's own shapes results.
    const bool paper = s.method == Method::paper;
    return {
        {"method", "method", to_string(s.method), 0.0, true},
        paper ? num("paper_dt_s", "paper-dt", s.paper_dt_s, format_number(s.paper_dt_s))
              : num("steps_per_period", "steps-per-period", s.steps_per_period, format_number(s.steps_per_period)),
        num("max_steps", "max-steps", static_cast<double>(s.max_steps), std::to_string(s.max_steps)),
        // 1: a safe block is decided by energy after the pulse; 0: --no-energy-stop.
        num("energy_stop", "no-energy-stop", s.energy_stop ? 1.0 : 0.0, s.energy_stop ? "not given" : "given"),
        num("impact_threshold", "impact-threshold", spec.impact_threshold, format_number(spec.impact_threshold)),
        {"equations", "equations", to_string(spec.equations), 0.0, true},
        {"pulse", "pulse", to_string(spec.pulse_family), 0.0, true},
        num("pulse_cycles", "cycles", spec.pulse_cycles, std::to_string(spec.pulse_cycles)),
    };
}

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
h5::Dataset write_column(const GridGroup& grid, const char* name, const std::vector<T>* column, std::size_t scenario,
                         const h5::Group& g, std::span<const GridAxis> axes) {
    const std::size_t cells = grid.cell_count();
    if (column) return grid.write<T>(name, std::span<const T>(column->data() + scenario * cells, cells));
    const std::vector<hsize_t> dims = grid_dims(axes);
    h5::Dataset ds = h5::create_fixed_dataset<T>(g, name, dims);
    std::string names;
    for (unsigned d = 0; d < axes.size(); ++d) {
        h5::attach_scale(ds, g.open_dataset(axes[d].name), d);
        names += (names.empty() ? "" : ", ") + axes[d].name;
    }
    h5::write_attribute(ds, "dimensions", names);
    return ds;
}

// Where the columns come from: a SweepResults, or nothing (fixed datasets to fill in place).
struct Columns {
    const SweepResults* r;
    const h5::Group& g;
    std::span<const GridAxis> axes;
    template <class T>
    const std::vector<T>* operator()(std::vector<T> SweepResults::*m) const { return r ? &(r->*m) : nullptr; }
};

void write_root(const h5::File& f, const SweepSpec& spec, const IntegratorSettings& settings,
                const SweepResults* r) {
    h5::write_attribute(f, "title", "rocksweep overturning spectra");
    h5::write_attribute(f, "format_version", format_version);
    for (const NamedNumber& n : root_numbers(spec)) h5::write_attribute(f, n.name, n.value);
    // Numbers that are integers in meaning (max_steps, energy_stop) stay float64 like the
    // rest: read back as double they compare exactly (max_steps <= 1e9 < 2^53).
    for (const Setting& x : result_settings(spec, settings)) {
        if (x.is_text) h5::write_attribute(f, x.attribute, x.text);
        else h5::write_attribute(f, x.attribute, x.number);
    }
    h5::write_attribute(f, "friction_coefficient", spec.friction);  // 0: not checked
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
                   const Columns& from, const char* units, const char* long_name, const char* comment = nullptr) {
    const h5::Dataset ds = write_column(grid, name, column, index, from.g, from.axes);
    h5::write_attribute(ds, "units", units);
    h5::write_attribute(ds, "long_name", long_name);
    if (comment) h5::write_attribute(ds, "comment", comment);
}

/// A code: the grid with its long_name and the CF flag attributes (flag_values or flag_masks,
/// flag_meanings), and a comment where there is one.
void write_code(const GridGroup& grid, const char* name, const std::vector<std::uint8_t>* column,
                std::size_t index, const Columns& from, const char* long_name, const char* flag_kind,
                std::span<const std::uint8_t> flags, const char* meanings, const char* comment = nullptr) {
    const h5::Dataset ds = write_column(grid, name, column, index, from.g, from.axes);
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
    for (const NamedText& t : scenario_texts(s)) h5::write_attribute(g, t.name, t.value);
    for (const NamedNumber& n : scenario_numbers(s)) h5::write_attribute(g, n.name, n.value);
    const GridGroup grid(g, axes);
    const Columns c{r, g, axes};

    const std::uint8_t outcomes[] = {0, 1, 2, 255};
    write_code(grid, "outcome", c(&SweepResults::outcome), index, c, "outcome of the pulse", "flag_values", outcomes,
               "safe overturned_with_impact overturned_without_impact not_converged");
    write_measure(grid, "max_rotation", c(&SweepResults::max_rotation), index, c, "1", "max |theta| / alpha");
    write_measure(grid, "impacts", c(&SweepResults::impacts), index, c, "1", "impacts with approach speed above the threshold");
    write_measure(grid, "impacts_total", c(&SweepResults::impacts_total), index, c, "1",
                  "impacts, the settling one included",
                  "the first impact slower than impact_threshold p alpha puts the block at rest "
                  "(the rest would pile up in finite time); it counts here, not in impacts");
    write_measure(grid, "t_overturn", c(&SweepResults::t_overturn), index, c, "s",
                  "time at which |theta| reached pi/2",
                  "NaN when the block did not overturn");
    write_measure(grid, "peak_force_ratio", c(&SweepResults::peak_force_ratio), index, c, "1",
                  "peak anchorage force / F_u",
                  "NaN for a free-standing block");
    const std::uint8_t masks[] = {broken_left, broken_right};
    write_code(grid, "broken", c(&SweepResults::broken), index, c, "restrainers broken during the run", "flag_masks", masks,
               "left_spring_broken right_spring_broken",
               "bit 1: left spring (works for theta > 0); bit 2: right spring (works for theta < 0)");
    write_measure(grid, "mu_required", c(&SweepResults::mu_required), index, c, "1",
                  "friction coefficient needed to rock without sliding, max |f_x / f_y|",
                  "base reactions from the motion of the centre of mass (Eq. 16-18); where it exceeds the "
                  "interface's static friction coefficient the block would slide and this cell's "
                  "pure-rocking result does not hold");
    const std::uint8_t uplift[] = {0, 1};
    write_code(grid, "pivot_uplift", c(&SweepResults::pivot_uplift), index, c, "vertical reaction at the pivot went negative",
               "flag_values", uplift, "pivot_stays_down pivot_lifts",
               "1: the block would jump; the rocking model does not hold there");
    const std::uint8_t done[] = {0, 1, 2};
    write_code(grid, "done", c(&SweepResults::done), index, c, "cell computed", "flag_values", done, "pending computed inferred",
               "the other datasets are meaningful only where done = 1; done = 2: outcome inferred by "
               "boundary refinement from a uniform square of computed cells (other datasets NaN/0)");
}

void write_provenance(const h5::File& f, const Provenance& prov, const IntegratorSettings& settings) {
    const h5::Group g = f.create_group("provenance");
    h5::write_attribute(g, "version", prov.version);
    h5::write_attribute(g, "config", prov.config_text);
    h5::write_attribute(g, "method", to_string(settings.method));
    h5::write_attribute(g, "steps_per_period", settings.steps_per_period);
    h5::write_attribute(g, "paper_dt_s", settings.paper_dt_s);
    h5::write_attribute(g, "created_utc", prov.created_utc);
    h5::write_attribute(g, "ranks", prov.ranks);
    h5::write_attribute(g, "wall_s", prov.wall_s);
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

namespace {

// ---------------------------------------------------------------------------------------
// Reading

[[noreturn]] void mismatch(const std::string& path, const std::string& what) {
    throw InputError("spectra file", path, "a file written for the same sweep (" + what + ")");
}

void compare_number(const std::string& path, const h5::Object& obj, const NamedNumber& n) {
    const double in_file = h5::read_double_attribute(obj, n.name);
    if (!same_number(in_file, n.value))
        mismatch(path, obj.name() + " attribute " + n.name + " is " + format_number(in_file) +
                           " in the file, " + format_number(n.value) + " in the config");
}

void compare_text(const std::string& path, const h5::Object& obj, const char* name,
                  const std::string& expected) {
    // A file from before --adaptive-law has no adaptive_law: it was computed with the paper's law.
    const bool before_law = std::string_view(name) == "adaptive_law" && !obj.has_attribute(name);
    const std::string in_file = before_law ? "paper" : h5::read_string_attribute(obj, name);
    if (in_file != expected)
        mismatch(path, obj.name() + " attribute " + name + " is '" + in_file + "' in the file, '" +
                           expected + "' in the config");
}

void compare_setting(const std::string& path, const h5::File& f, const Setting& x) {
    std::string in_file;
    if (x.is_text) {
        in_file = h5::read_string_attribute(f, x.attribute);
        if (in_file == x.text) return;
    } else {
        const double value = h5::read_double_attribute(f, x.attribute);
        if (value == x.number) return;
        in_file = std::string(x.option) == "no-energy-stop" ? (value != 0.0 ? "not given" : "given") : format_number(value);
    }
    throw InputError(x.option, x.text,
                     in_file + ", as " + path + " was computed with (--resume continues a file only with the settings "
                               "that shaped its results)");
}

// Checks the shape of a result dataset and, given a column, reads it into its scenario's block.
template <h5::Element T>
void read_grid(const std::string& path, const h5::Group& g, const char* name, std::vector<T>* column,
               std::size_t scenario, std::span<const GridAxis> axes) {
    const std::vector<hsize_t> expected = grid_dims(axes);
    if (!column) {
        if (const std::vector<hsize_t> dims = g.open_dataset(name).dims(); dims != expected)
            mismatch(path, g.name() + "/" + name + " is " + dims_text(dims) + ", the config needs " + dims_text(expected));
        return;
    }
    const h5::ArrayN<T> a = h5::read_array<T>(g, name);
    if (a.dims != expected)
        mismatch(path, g.name() + "/" + name + " is " + dims_text(a.dims) + ", the config needs " +
                           dims_text(expected));
    std::copy(a.values.begin(), a.values.end(),
              column->begin() + static_cast<std::ptrdiff_t>(scenario * a.values.size()));
}

void read_contents(const std::string& path, const h5::File& f, const SweepSpec& spec,
                   const IntegratorSettings& settings, SweepResults* r) {
    for (const NamedNumber& n : root_numbers(spec)) compare_number(path, f, n);
    for (const Setting& x : result_settings(spec, settings)) compare_setting(path, f, x);

    const h5::Group spectra = f.open_group("spectra");
    std::vector<std::string> in_file = spectra.children();
    std::vector<std::string> expected;
    for (const Scenario& s : spec.scenarios) expected.push_back(s.name);
    std::sort(expected.begin(), expected.end());
    if (in_file != expected) {
        auto join = [](const std::vector<std::string>& v) {
            std::string s;
            for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
            return s.empty() ? std::string("none") : s;
        };
        mismatch(path, "scenarios in the file: " + join(in_file) + "; in the config: " + join(expected));
    }

    const std::vector<GridAxis> axes = grid_axes(spec);
    if (r) r->resize(spec.cell_count());
    auto col = [r](auto SweepResults::*m) { return r ? &(r->*m) : nullptr; };
    for (std::size_t i = 0; i < spec.scenarios.size(); ++i) {
        const Scenario& s = spec.scenarios[i];
        const h5::Group g = spectra.open_group(s.name);
        for (const NamedText& t : scenario_texts(s)) compare_text(path, g, t.name, t.value);
        for (const NamedNumber& n : scenario_numbers(s)) compare_number(path, g, n);
        if (const std::string diff = axes_difference(g, axes); !diff.empty()) mismatch(path, g.name() + ": " + diff);
        read_grid(path, g, "outcome", col(&SweepResults::outcome), i, axes);
        read_grid(path, g, "max_rotation", col(&SweepResults::max_rotation), i, axes);
        read_grid(path, g, "impacts", col(&SweepResults::impacts), i, axes);
        read_grid(path, g, "t_overturn", col(&SweepResults::t_overturn), i, axes);
        read_grid(path, g, "peak_force_ratio", col(&SweepResults::peak_force_ratio), i, axes);
        read_grid(path, g, "broken", col(&SweepResults::broken), i, axes);
        read_grid(path, g, "impacts_total", col(&SweepResults::impacts_total), i, axes);
        read_grid(path, g, "mu_required", col(&SweepResults::mu_required), i, axes);
        read_grid(path, g, "pivot_uplift", col(&SweepResults::pivot_uplift), i, axes);
        read_grid(path, g, "done", col(&SweepResults::done), i, axes);
    }
}

}  // namespace

void write_spectra(const std::string& path, const SweepSpec& spec, const SweepResults& r,
                   const Provenance& prov, const IntegratorSettings& settings) {
    check_columns(spec, r);
    h5::publish_h5_atomically(path, [&](const h5::File& f) { spectra_detail::write_contents(f, spec, &r, prov, settings); });
}

SweepResults read_spectra_results(const std::string& path, const SweepSpec& spec,
                                  const IntegratorSettings& settings) {
    SweepResults r;
    spectra_detail::open_checked(path, spec, settings, &r);
    return r;
}

h5::File spectra_detail::open_checked(const std::string& path, const SweepSpec& spec,
                                      const IntegratorSettings& settings, SweepResults* r) {
    // What the file is, in the user's words, before any HDF5 detail.
    auto not_spectra = [&](const std::string& what) {
        return InputError("output", path, "a rocksweep spectra file to resume; it is " + what);
    };
    std::optional<h5::File> opened;  // the file, or a message about what it is
    try {
        opened.emplace(h5::File::open_read_only(path));
    } catch (const Hdf5Error&) {
        throw not_spectra("not an HDF5 file");
    }
    const h5::File& f = *opened;
    if (f.exists("theta") && f.exists("t")) throw not_spectra("a history written by rocksweep simulate");
    if (!f.has_attribute("format_version") || !f.exists("spectra"))
        throw not_spectra("an HDF5 file that rocksweep sweep did not write");
    if (const std::int64_t v = h5::read_int64_attribute(f, "format_version"); v != format_version)
        throw InputError("output", path,
                         "a spectra file of format version " + std::to_string(format_version) +
                             " to resume; it is of version " + std::to_string(v) +
                             (v < format_version ? " (an older layout, axes in /axes)" : " (a newer rocksweep's)") +
                             ", which this rocksweep does not continue: sweep again with --overwrite");
    try {
        read_contents(path, f, spec, settings, r);
        return std::move(*opened);
    } catch (const Hdf5Error& e) {
        // A missing attribute or dataset means this is not a file we wrote for this layout.
        throw InputError("spectra file", path,
                         std::string("a rocksweep spectra file (") + e.what() + ")");
    }
}

}  // namespace rocksweep
