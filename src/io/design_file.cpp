#include "rocksweep/io/design_file.hpp"

#include <cmath>
#include <span>
#include <stdexcept>

#include "result_columns.hpp"
#include "rocksweep/io/hdf5.hpp"

namespace rocksweep {

namespace {

constexpr std::int64_t format_version = 2;  // 2: round -> search_round

const char* const criterion_words =
    "fraction of the hazard (a pulse region: its area, trapezoid weights over the grid nodes; a record suite: "
    "its runs, every record at every level counting once) where the block does not "
    "overturn, its max |theta| / alpha is within max_rotation_ratio and its peak anchorage force within "
    "object_force_N (0: no such limit)";

void check_curve(const char* name, const DesignCurve& c) {
    const std::size_t n = c.variable.size();
    const bool theta_ok = c.theta_f_ratio.empty() || c.theta_f_ratio.size() == n;
    const bool rates_ok = c.rate.size() == c.standing_rate.size() && (c.rate.empty() || c.rate.size() == n);
    if (n == 0 || c.acceptable.size() != n || c.standing.size() != n || c.round.size() != n || !theta_ok || !rates_ok)
        throw std::invalid_argument(std::string("write_design: the columns of ") + name + " differ in length or are empty");
    if (c.optimum >= n || c.near_lo > c.optimum || c.near_hi < c.optimum || c.near_hi >= n)
        throw std::invalid_argument(std::string("write_design: the optimum of ") + name + " or its near-optimal run is out of range");
}

h5::Dataset write_scale(const h5::Group& g, const char* name, const std::vector<double>& v, const char* units,
                        const char* long_name) {
    h5::Dataset ds = h5::write_1d<double>(g, name, v);
    h5::write_attribute(ds, "units", units);
    h5::write_attribute(ds, "long_name", long_name);
    h5::make_scale(ds, name);
    return ds;
}

template <h5::Element T>
void write_column(const h5::Group& g, const char* name, const std::vector<T>& v, const h5::Dataset& scale,
                  const char* units, const char* long_name) {
    const h5::Dataset ds = h5::write_1d<T>(g, name, v);
    h5::write_attribute(ds, "units", units);
    h5::write_attribute(ds, "long_name", long_name);
    h5::attach_scale(ds, scale, 0);
}

/// The columns both curves share, against their variable's scale.
void write_curve(const h5::Group& g, const DesignCurve& c, const h5::Dataset& scale, bool risk) {
    write_column(g, "safe_fraction", c.acceptable, scale, "1", "the criterion: acceptable share of the hazard region");
    write_column(g, "standing_fraction", c.standing, scale, "1", "share of the hazard region where the block does not overturn");
    // Not `round`: a variable of that name is hidden by numpy's and xarray's .round().
    write_column(g, "search_round", c.round, scale, "1", "search round that evaluated the value (0: the coarse one)");
    if (risk) {
        write_column(g, "annual_rate", c.rate, scale, "1/yr", "annual rate of the unacceptable state at the site (what the design minimises)");
        write_column(g, "annual_rate_overturning", c.standing_rate, scale, "1/yr", "annual rate of overturning at the site, limits ignored");
    }
    h5::write_attribute(g, "optimum_index", c.optimum);
    h5::write_attribute(g, "optimum_safe_fraction", c.acceptable[c.optimum]);
    const double near[2] = {c.variable[c.near_lo], c.variable[c.near_hi]};
    h5::write_attribute(g, "near_optimal_range", std::span<const double>(near));
}

/// The search as the user set it: its range in the variable's own terms, the rest as given.
void write_search(const h5::Group& g, const SearchSettings& s, const char* range_name) {
    const double range[2] = {std::pow(10.0, s.lo), std::pow(10.0, s.hi)};
    h5::write_attribute(g, range_name, std::span<const double>(range));
    h5::write_attribute(g, "coarse_points", s.coarse_points);
    h5::write_attribute(g, "points_per_side", s.points_per_side);
    h5::write_attribute(g, "max_rounds", s.max_rounds);
    h5::write_attribute(g, "tolerance_log10", s.tolerance);
}

void write_root(const h5::File& f, const DesignReport& r) {
    const Block& b = r.hazard.block;
    h5::write_attribute(f, "title", "rocksweep anchorage design");
    h5::write_attribute(f, "Conventions", h5::cf_conventions);
    h5::write_attribute(f, "format_version", format_version);
    h5::write_attribute(f, "criterion", criterion_words);
    h5::write_attribute(f, "half_width_m", b.half_width_m());
    h5::write_attribute(f, "alpha_rad", b.alpha_rad);
    h5::write_attribute(f, "p_rad_s", b.p());
    h5::write_attribute(f, "mass_kg", b.mass_kg);
    h5::write_attribute(f, "gravity_m_s2", b.gravity);
    h5::write_attribute(f, "strength_N", r.strength_n);
    h5::write_attribute(f, "object_force_N", r.object_force_n);
    h5::write_attribute(f, "max_force_ratio", r.constraints.max_force_ratio);
    h5::write_attribute(f, "max_rotation_ratio", r.constraints.max_rotation_ratio);
    if (r.suite) {
        const SuiteHazard& h = *r.suite;
        h5::write_attribute(f, "hazard", "the records of a suite, each scaled to every level of " + h.measure +
                                             " (every run counts equally)");
        h5::write_attribute(f, "suite_file", h.suite_path);
        h5::write_attribute(f, "records", h.records);
        h5::write_attribute(f, "intensity_measure", h.measure);
        h5::write_attribute(f, "intensity_units", h.units);
        const double levels[2] = {h.levels.lo, h.levels.hi};
        h5::write_attribute(f, "intensity_range", std::span<const double>(levels));
        h5::write_attribute(f, "intensity_points", h.levels.points);
    } else {
        h5::write_attribute(f, "hazard", "one-sine pulses over a rectangle of omega_p / p x a_p0 / (alpha g)");
        const double omega[2] = {r.hazard.omega_ratio.lo, r.hazard.omega_ratio.hi};
        const double amp[2] = {r.hazard.amplitude_ratio.lo, r.hazard.amplitude_ratio.hi};
        h5::write_attribute(f, "omega_ratio_range", std::span<const double>(omega));
        h5::write_attribute(f, "omega_ratio_points", r.hazard.omega_ratio.points);
        h5::write_attribute(f, "amplitude_ratio_range", std::span<const double>(amp));
        h5::write_attribute(f, "amplitude_ratio_points", r.hazard.amplitude_ratio.points);
        h5::write_attribute(f, "phase_rad", r.hazard.phase);
        h5::write_attribute(f, "vertical_g", r.hazard.vertical_g);
    }
    h5::write_attribute(f, "refine_stride", r.refine_stride);
    h5::write_attribute(f, "near_optimal", r.near_optimal);
    h5::write_attribute(f, "free_safe_fraction", r.free.acceptable);
    h5::write_attribute(f, "free_standing_fraction", r.free.standing);
    if (r.risk) {
        h5::write_attribute(f, "criterion", std::string("exp(-rate t): the probability that the block stays acceptable through the "
                                                        "exposure time at the site, rate = the annual rate (docs/risk.md, empirical fractions) "
                                                        "of the runs not acceptable by the ") + criterion_words);
        h5::write_attribute(f, "hazard_curve_file", r.risk->path);
        h5::write_attribute(f, "hazard_measure", r.risk->measure);
        h5::write_attribute(f, "exposure_years", r.risk->exposure_years);
        h5::write_attribute(f, "free_annual_rate", r.free_rate);
        h5::write_attribute(f, "free_annual_rate_overturning", r.free_standing_rate);
    }
}

void write_contents(const h5::File& f, const DesignReport& r, const Provenance& prov) {
    write_root(f, r);
    h5::write_attribute(f, "rocksweep_version", prov.version);
    {
        const DesignCurve& c = r.constant;
        const h5::Group g = f.create_group("constant");
        const h5::Dataset k = write_scale(g, "stiffness", c.variable, "N/m", "anchorage stiffness K");
        write_curve(g, c, k, r.risk.has_value());
        write_column(g, "theta_f_ratio", c.theta_f_ratio, k, "1", "fracture angle theta_f / alpha at F_u");
        h5::write_attribute(g, "optimum_stiffness_N_per_m", c.variable[c.optimum]);
        h5::write_attribute(g, "optimum_theta_f_ratio", c.theta_f_ratio[c.optimum]);
        write_search(g, r.stiffness_search, "stiffness_range_N_per_m");
    }
    {
        const DesignCurve& c = r.adaptive;
        const h5::Group g = f.create_group("adaptive");
        const h5::Dataset rho = write_scale(g, "kmin_ratio", c.variable, "1", "K_min / K_max");
        write_curve(g, c, rho, r.risk.has_value());
        h5::write_attribute(g, "k_max_N_per_m", r.k_max_n_per_m);
        h5::write_attribute(g, "k_max_theta_f_ratio", r.k_max_theta_f_ratio);
        h5::write_attribute(g, "optimum_kmin_ratio", c.variable[c.optimum]);
        h5::write_attribute(g, "optimum_k_min_N_per_m", c.variable[c.optimum] * r.k_max_n_per_m);
        write_search(g, r.kmin_search, "kmin_ratio_range");
    }
    h5::write_attribute(io::write_provenance(f, prov), "ranks", prov.ranks);
}

}  // namespace

void write_design(const std::string& path, const DesignReport& report, const Provenance& prov) {
    check_curve("constant", report.constant);
    check_curve("adaptive", report.adaptive);
    if (report.constant.theta_f_ratio.size() != report.constant.variable.size())
        throw std::invalid_argument("write_design: every constant K needs its theta_f / alpha");
    h5::publish_h5_atomically(path, [&](const h5::File& f) { write_contents(f, report, prov); });
}

}  // namespace rocksweep
