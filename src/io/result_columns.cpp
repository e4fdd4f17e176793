#include "result_columns.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/records/fragility.hpp"

namespace rocksweep::io {

namespace {

bool same_number(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

/// The empty dataset of one result column, filled later by its writer (`chunk`: see
/// write_result_columns).
struct EmptyColumns {
    const GridGroup& grid;
    std::span<const hsize_t> chunk;
};

/// A measured quantity: the grid with its units, long_name and, where there is one, comment.
template <h5::Element T>
void write_measure(const EmptyColumns& c, const char* name, const char* units, const char* long_name,
                   const char* comment = nullptr) {
    const h5::Dataset ds = c.grid.create<T>(name, c.chunk);
    h5::write_attribute(ds, "units", units);
    h5::write_attribute(ds, "long_name", long_name);
    if (comment) h5::write_attribute(ds, "comment", comment);
}

/// A code: the grid with its long_name and the CF flag attributes, and a comment where there is one.
void write_code(const EmptyColumns& c, const char* name, const char* long_name, const char* flag_kind,
                std::span<const std::uint8_t> flags, const char* meanings, const char* comment = nullptr) {
    const h5::Dataset ds = c.grid.create<std::uint8_t>(name, c.chunk);
    h5::write_attribute(ds, "long_name", long_name);
    h5::write_attribute(ds, flag_kind, flags);
    h5::write_attribute(ds, "flag_meanings", meanings);
    if (comment) h5::write_attribute(ds, "comment", comment);
}

template <h5::Element T>
void read_column(const h5::Group& g, const char* name, std::span<const GridAxis> axes, std::vector<T>& column,
                 std::size_t first, const Mismatch& mismatch) {
    const std::vector<hsize_t> expected = grid_dims(axes);
    const h5::ArrayN<T> a = h5::read_array<T>(g, name);
    if (a.dims != expected)
        mismatch(g.name() + "/" + name + " is " + dims_text(a.dims) + ", the config needs " + dims_text(expected));
    std::copy(a.values.begin(), a.values.end(), column.begin() + static_cast<std::ptrdiff_t>(first));
}

}  // namespace

std::vector<NamedNumber> block_numbers(const Block& b) {
    return {
        {"half_width_m", b.half_width_m()}, {"half_height_m", b.half_height_m()}, {"radius_m", b.radius_m},
        {"alpha_rad", b.alpha_rad},         {"p_rad_s", b.p()},                   {"e", b.e},
        {"inertia_ratio", b.inertia_ratio}, {"mass_kg", b.mass_kg},               {"gravity_m_s2", b.gravity},
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

std::vector<NamedText> scenario_texts(const Scenario& s) {
    return {{"anchorage", to_string(s.anchorage.kind)},
            {"break_rule", to_string(s.anchorage.break_rule)},
            {"adaptive_law", to_string(s.anchorage.law)}};
}

std::vector<Setting> numerics_settings(const IntegratorSettings& s, double impact_threshold, Equations equations) {
    auto num = [](const char* attr, const char* option, double x, std::string shown) {
        return Setting{attr, option, std::move(shown), x, false};
    };
    // The method is compared first; of the two step settings only the method's own shapes results.
    const bool paper = s.method == Method::paper;
    return {
        {"method", "method", to_string(s.method), 0.0, true},
        paper ? num("paper_dt_s", "paper-dt", s.paper_dt_s, format_number(s.paper_dt_s))
              : num("steps_per_period", "steps-per-period", s.steps_per_period, format_number(s.steps_per_period)),
        // Files from before --tolerance had fixed steps under records too.
        {"tolerance", "tolerance", format_number(s.tolerance), s.tolerance, false, "0"},
        num("max_steps", "max-steps", static_cast<double>(s.max_steps), std::to_string(s.max_steps)),
        // 1: a safe block is decided by energy after the excitation; 0: --no-energy-stop.
        num("energy_stop", "no-energy-stop", s.energy_stop ? 1.0 : 0.0, s.energy_stop ? "not given" : "given"),
        num("impact_threshold", "impact-threshold", impact_threshold, format_number(impact_threshold)),
        {"equations", "equations", to_string(equations), 0.0, true},
        // Files from before --record-steps have no attribute: their samples ended steps.
        {"record_steps", "record-steps", s.steps_end_at_samples ? "samples" : "cross", 0.0, true, "samples"},
    };
}

void write_numbers(const h5::Object& obj, std::span<const NamedNumber> numbers) {
    for (const NamedNumber& n : numbers) h5::write_attribute(obj, n.name, n.value);
}

void write_settings(const h5::Object& obj, std::span<const Setting> settings) {
    // Numbers that are integers in meaning (max_steps, energy_stop) stay float64 like the
    // rest: read back as double they compare exactly (max_steps <= 1e9 < 2^53).
    for (const Setting& x : settings) {
        if (x.is_text) h5::write_attribute(obj, x.attribute, x.text);
        else h5::write_attribute(obj, x.attribute, x.number);
    }
}

void compare_numbers(const h5::Object& obj, std::span<const NamedNumber> numbers, const Mismatch& mismatch) {
    for (const NamedNumber& n : numbers) {
        const double in_file = h5::read_double_attribute(obj, n.name);
        if (!same_number(in_file, n.value))
            mismatch(obj.name() + " attribute " + n.name + " is " + format_number(in_file) + " in the file, " +
                     format_number(n.value) + " in the config");
    }
}

void compare_texts(const h5::Object& obj, std::span<const NamedText> texts, const Mismatch& mismatch) {
    for (const NamedText& t : texts) {
        const std::string in_file = h5::read_string_attribute(obj, t.name);
        if (in_file != t.value)
            mismatch(obj.name() + " attribute " + t.name + " is '" + in_file + "' in the file, '" + t.value + "' in the config");
    }
}

void compare_settings(const std::string& path, const h5::Object& obj, std::span<const Setting> settings) {
    for (const Setting& x : settings) {
        std::string in_file;
        if (x.absent && !obj.has_attribute(x.attribute)) {
            if (*x.absent == '\0' || x.text == x.absent) continue;
            in_file = x.absent;
        } else if (x.is_text) {
            in_file = h5::read_string_attribute(obj, x.attribute);
            if (in_file == x.text) continue;
        } else {
            const double value = h5::read_double_attribute(obj, x.attribute);
            if (value == x.number) continue;
            const std::string option = x.option;
            in_file = option == "no-energy-stop" ? (value != 0.0 ? "not given" : "given")
                      : option == "refine" && value == 0.0 ? "not given"
                                                           : format_number(value);
        }
        throw InputError(x.option, x.text,
                         in_file + ", as " + path + " was computed with (--resume continues a file only with the settings "
                                                    "that shaped its results)");
    }
}

void write_scenario_attributes(const h5::Group& g, std::size_t index, const Scenario& s) {
    h5::write_attribute(g, "index", index);  // position in the config: group listings sort by name
    for (const NamedText& t : scenario_texts(s)) h5::write_attribute(g, t.name, t.value);
    write_numbers(g, scenario_numbers(s));
}

void write_result_columns(const GridGroup& grid, std::span<const hsize_t> chunk, bool sensitive) {
    const EmptyColumns c{grid, chunk};
    const std::uint8_t outcomes[] = {0, 1, 2, 255};
    write_code(c, "outcome", "outcome of the run", "flag_values", outcomes,
               "safe overturned_with_impact overturned_without_impact not_converged");
    write_measure<double>(c, "max_rotation", "1", "max |theta| / alpha");
    write_measure<std::int32_t>(c, "impacts", "1", "impacts with approach speed above the threshold");
    write_measure<std::int32_t>(c, "impacts_total", "1", "impacts, the settling one included",
                                "the first impact slower than impact_threshold p alpha puts the block at rest "
                                "(the rest would pile up in finite time); it counts here, not in impacts");
    write_measure<double>(c, "t_overturn", "s", "time at which |theta| reached pi/2", "NaN when the block did not overturn");
    write_measure<double>(c, "peak_force_ratio", "1", "peak anchorage force / F_u", "NaN for a free-standing block");
    const std::uint8_t masks[] = {broken_left, broken_right};
    write_code(c, "broken", "restrainers broken during the run", "flag_masks", masks,
               "left_spring_broken right_spring_broken",
               "bit 1: left spring (works for theta > 0); bit 2: right spring (works for theta < 0)");
    write_measure<double>(c, "mu_required", "1", "friction coefficient needed to rock without sliding, max |f_x / f_y|",
                          "base reactions from the motion of the centre of mass (Eq. 16-18); where it exceeds the "
                          "interface's static friction coefficient the block would slide and this cell's "
                          "pure-rocking result does not hold");
    const std::uint8_t uplift[] = {0, 1};
    write_code(c, "pivot_uplift", "vertical reaction at the pivot went negative", "flag_values", uplift,
               "pivot_stays_down pivot_lifts", "1: the block would jump; the rocking model does not hold there");
    const std::uint8_t done[] = {0, 1, 2};
    write_code(c, "done", "cell computed", "flag_values", done, "pending computed inferred",
               "the other datasets are meaningful only where done = 1; done = 2: outcome inferred by "
               "boundary refinement from a uniform square of computed cells (other datasets NaN/0)");
    if (!sensitive) return;
    const std::uint8_t flags[] = {0, 1};
    write_code(c, "sensitive", "outcome or damage state changed by a perturbed, tighter rerun", "flag_values", flags,
               "robust sensitive",
               "--check-sensitivity: rerun with the record's scale times (1 + 1e-9) at the tolerance / 100; meaningful "
               "where done = 1 (docs/suite.md, Sensitive runs)");
}

void read_sensitive_column(const h5::Group& g, std::span<const GridAxis> axes, SweepResults& r, std::size_t first,
                           const Mismatch& mismatch) {
    read_column(g, "sensitive", axes, r.sensitive, first, mismatch);
}

void read_result_columns(const h5::Group& g, std::span<const GridAxis> axes, SweepResults& r, std::size_t first,
                         const Mismatch& mismatch) {
    read_column(g, "outcome", axes, r.outcome, first, mismatch);
    read_column(g, "max_rotation", axes, r.max_rotation, first, mismatch);
    read_column(g, "impacts", axes, r.impacts, first, mismatch);
    read_column(g, "t_overturn", axes, r.t_overturn, first, mismatch);
    read_column(g, "peak_force_ratio", axes, r.peak_force_ratio, first, mismatch);
    read_column(g, "broken", axes, r.broken, first, mismatch);
    read_column(g, "impacts_total", axes, r.impacts_total, first, mismatch);
    read_column(g, "mu_required", axes, r.mu_required, first, mismatch);
    read_column(g, "pivot_uplift", axes, r.pivot_uplift, first, mismatch);
    read_column(g, "done", axes, r.done, first, mismatch);
}

h5::Group write_provenance(const h5::File& f, const Provenance& prov) {
    h5::Group g = f.create_group("provenance");
    h5::write_attribute(g, "version", prov.version);
    h5::write_attribute(g, "config", prov.config_text);
    h5::write_attribute(g, "created_utc", prov.created_utc);
    h5::write_attribute(g, "wall_s", prov.wall_s);
    return g;
}

h5::Group write_provenance(const h5::File& f, const Provenance& prov, const IntegratorSettings& settings) {
    h5::Group g = write_provenance(f, prov);
    h5::write_attribute(g, "method", to_string(settings.method));
    h5::write_attribute(g, "steps_per_period", settings.steps_per_period);
    h5::write_attribute(g, "paper_dt_s", settings.paper_dt_s);
    h5::write_attribute(g, "ranks", prov.ranks);
    return g;
}

void write_fit_status_flags(const h5::Dataset& ds, const std::string& long_name) {
    std::vector<std::uint8_t> codes;
    std::string names;
    for (auto s = FitStatus::ok; s <= FitStatus::decreasing; s = static_cast<FitStatus>(static_cast<int>(s) + 1)) {
        codes.push_back(static_cast<std::uint8_t>(s));
        names += (names.empty() ? "" : " ") + to_string(s);
    }
    h5::write_attribute(ds, "long_name", long_name);
    h5::write_attribute(ds, "flag_values", std::span<const std::uint8_t>(codes));
    h5::write_attribute(ds, "flag_meanings", names);
}

void write_progress(const h5::Object& obj, const SweepResults& r) {
    const auto n_done = static_cast<std::int64_t>(r.done_count());
    const auto n_cells = static_cast<std::int64_t>(r.size());
    h5::write_attribute(obj, "n_cells", n_cells);
    h5::write_attribute(obj, "n_done", n_done);
    h5::write_attribute(obj, "complete", std::int64_t{n_done == n_cells ? 1 : 0});
}

}  // namespace rocksweep::io
