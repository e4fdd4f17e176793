// The risk file, and the suite file's fragility read back for it.
#include "rocksweep/io/risk_file.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "result_columns.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/grid_layout.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/risk/hazard_curve.hpp"

namespace rocksweep {

namespace {

constexpr std::int64_t format_version = 1;

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

SuiteFragilityTable read_table(const h5::File& f, const std::string& path) {
    SuiteFragilityTable t;
    t.measure = h5::read_string_attribute(f, "intensity_measure");
    // A spectral measure records its period beside it (docs/risk.md).
    if (f.has_attribute("intensity_period_s")) t.period_s = h5::read_double_attribute(f, "intensity_period_s");
    // ... and its damping beside each record's Sa (files before Sa have neither).
    if (t.measure == "sa_g") t.damping = h5::read_double_attribute(f.open_group("records").open_dataset("sa_g"), "damping");
    const h5::Group suite = f.open_group("suite");
    // HDF5 lists groups by name; the suite's order (its index attribute) is the one its
    // readers and figures show (free, constant, adaptive; on the ground, then upstairs).
    std::vector<std::pair<std::int64_t, std::string>> order;
    for (const std::string& name : suite.children()) {
        const h5::Group g = suite.open_group(name);
        order.emplace_back(g.has_attribute("index") ? h5::read_int64_attribute(g, "index") : 0, name);
    }
    std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [index, name] : order) {
        const h5::Group g = suite.open_group(name);
        if (!g.exists("fragility"))
            throw InputError("suite-file", path, "a complete suite file; its sweep is partial (no fragility in " + g.name() + ")");
        const h5::Group fr = g.open_group("fragility");
        if (t.scenarios.empty()) {
            t.states = words(h5::read_string_attribute(fr.open_dataset("damage_state"), "flag_meanings"));
            t.alphas = h5::read_1d<double>(fr, "alpha_rad");
            t.radii = h5::read_1d<double>(fr, "radius_m");
            t.levels = h5::read_1d<double>(fr, "intensity");
        }
        ScenarioFragility s;
        s.name = name;
        s.index = index;
        if (g.has_attribute("floor")) s.floor = h5::read_string_attribute(g, "floor");
        const auto read = [&](const char* n) { return h5::read_array<double>(fr, n).values; };
        s.fraction = read("fraction"), s.fraction_lo = read("fraction_lo"), s.fraction_hi = read("fraction_hi");
        // Suite files of format 3 on name the fitted median median_intensity (xarray's
        // Dataset.median hid `median`); those of formats 1 and 2 are read too.
        const std::string median = fr.exists("median_intensity") ? "median_intensity" : "median";
        s.median = read(median.c_str()), s.median_lo = read((median + "_lo").c_str());
        s.median_hi = read((median + "_hi").c_str()), s.beta = read("beta");
        s.beta_lo = read("beta_lo"), s.beta_hi = read("beta_hi");
        // The covariance came after the errors: a file without it gets the box range.
        if (fr.exists("cov_ln_median_beta"))
            s.se_ln_median = read("se_ln_median"), s.se_beta = read("se_beta"), s.cov_ln_median_beta = read("cov_ln_median_beta");
        s.fit_status = h5::read_array<std::uint8_t>(fr, "fit_status").values;
        const std::size_t blocks = t.blocks();
        if (s.median.size() != blocks || s.fit_status.size() != blocks || s.fraction.size() != blocks * t.levels.size())
            throw InputError("suite-file", path, "a suite file whose scenarios share one grid (" + g.name() + " differs)");
        t.scenarios.push_back(std::move(s));
    }
    if (t.scenarios.empty()) throw InputError("suite-file", path, "a suite file with at least one scenario");
    return t;
}

GridAxis state_axis(const SuiteFragilityTable& t) {
    std::vector<double> index;
    std::string meanings;
    for (std::size_t d = 0; d < t.states.size(); ++d) {
        index.push_back(static_cast<double>(d));
        meanings += (meanings.empty() ? "" : " ") + t.states[d];
    }
    return {"damage_state", "1", "damage state (names: its flag_meanings)", index, meanings};
}

void write_hazard(const h5::File& f, const RiskReport& r) {
    const HazardCurve& h = r.hazard.curve;
    const h5::Group g = f.create_group("hazard");
    const GridAxis axes[] = {{"intensity", hazard_measure_units(h.measure()), "intensity of the hazard curve's points", h.intensity()}};
    const GridGroup grid(g, axes);
    const h5::Dataset ds = grid.write<double>("rate", h.rate());
    h5::write_attribute(ds, "units", "1/yr");
    h5::write_attribute(ds, "long_name", "mean annual rate of exceedance (log-log between points, extrapolated with the end slopes)");
}

void write_scenario(const h5::Group& parent, const RiskReport& r, const ScenarioFragility& fr, const ScenarioRisk& s) {
    const SuiteFragilityTable& t = r.fragility;
    const h5::Group g = parent.create_group(s.name);
    h5::write_attribute(g, "index", fr.index);
    h5::write_attribute(g, "floor", fr.floor);
    const char* units = hazard_measure_units(r.hazard.curve.measure());
    const GridAxis axes[] = {state_axis(t),
                             {"alpha_rad", "rad", "slenderness angle alpha = atan(b/h) of the block", t.alphas},
                             {"radius_m", "m", "block size R (corner to centre of mass)", t.radii},
                             {"intensity", units, "intensity of the deaggregation", r.risk.deaggregation_intensity},
                             {"level", units, "the suite's intensity levels", t.levels}};
    const GridGroup grid(g, axes);
    const std::initializer_list<std::string_view> block{"damage_state", "alpha_rad", "radius_m"};
    const auto put = [&](const char* name, const std::vector<double>& v, const char* u, const std::string& long_name) {
        const h5::Dataset ds = grid.write_on<double>(name, v, block);
        h5::write_attribute(ds, "units", u);
        h5::write_attribute(ds, "long_name", long_name);
    };
    const double years = r.exposure_years;
    const std::string in_t = " in " + format_short(years) + " years, 1 - exp(-rate t)";
    struct Source {
        const char* tag;
        const char* what;
        const std::vector<double> *rate, *lo, *hi, *below, *above;
    };
    const Source sources[] = {
        {"fit", "lognormal fit", &s.rate_fit, &s.rate_fit_lo, &s.rate_fit_hi, &s.below_fit, &s.above_fit},
        {"empirical", "empirical fractions", &s.rate_empirical, &s.rate_empirical_lo, &s.rate_empirical_hi, &s.below_empirical,
         &s.above_empirical},
    };
    for (const Source& src : sources) {
        const std::string tag = src.tag, what = src.what;
        std::vector<double> p, period, share_below, share_above;
        for (std::size_t b = 0; b < src.rate->size(); ++b) {
            const double rate = (*src.rate)[b];
            p.push_back(probability_in(rate, years));
            period.push_back(1.0 / rate);
            share_below.push_back(rate > 0 ? (*src.below)[b] / rate : NAN);
            share_above.push_back(rate > 0 ? (*src.above)[b] / rate : NAN);
        }
        put(("rate_" + tag).c_str(), *src.rate, "1/yr", "mean annual rate of the damage state (" + what + ")");
        // The fit's range: the delta method with the fit's covariance, or, for a suite file
        // without it, the box of the marginal intervals (docs/risk.md, "From the fit").
        const bool delta = r.fragility.covariance();
        put(("rate_" + tag + "_lo").c_str(), *src.lo, "1/yr",
            tag != "fit" ? "low end: the rate of Wilson's low 95 % bounds of every fraction"
            : delta      ? "low end of the 95 % range: delta method on ln(rate) with the fit's covariance of ln(median) and beta"
                         : "low end: least rate over the corners of the 95 % intervals of median and beta (file without the fit's covariance)");
        put(("rate_" + tag + "_hi").c_str(), *src.hi, "1/yr",
            tag != "fit" ? "high end: the rate of Wilson's high 95 % bounds of every fraction"
            : delta      ? "high end of the 95 % range: delta method on ln(rate) with the fit's covariance of ln(median) and beta"
                         : "high end: greatest rate over the corners of the 95 % intervals of median and beta (file without the fit's covariance)");
        put(("probability_" + tag).c_str(), p, "1", "probability of the damage state" + in_t + " (" + what + ")");
        put(("return_period_" + tag).c_str(), period, "yr", "return period 1 / rate (" + what + ")");
        put(("share_below_" + tag).c_str(), share_below, "1", "share of the rate from below the hazard curve's first point (extrapolated)");
        put(("share_above_" + tag).c_str(), share_above, "1", "share of the rate from above the hazard curve's last point (extrapolated)");
    }
    const h5::Dataset st = grid.write_on<std::uint8_t>("fit_status", fr.fit_status, block);
    io::write_fit_status_flags(st, "the suite's lognormal fit status (docs/fragility.md); rate_fit is NaN unless ok or zero_dispersion");
    // The suite's fragility beside the rate it gave, for the figure (scripts/plot_risk.py).
    put("median_intensity", fr.median, units, "the suite's lognormal fit: median intensity");
    put("beta", fr.beta, "1", "the suite's lognormal fit: dispersion");
    const h5::Dataset frac = grid.write_on<double>("fraction", fr.fraction, {"damage_state", "alpha_rad", "radius_m", "level"});
    h5::write_attribute(frac, "units", "1");
    h5::write_attribute(frac, "long_name", "the suite's empirical fraction of records reaching the state");
    for (const auto& [name, v] : {std::pair{"deaggregation_fit", &s.density_fit}, std::pair{"deaggregation_empirical", &s.density_empirical}}) {
        const h5::Dataset ds = grid.write_on<double>(name, *v, {"damage_state", "alpha_rad", "radius_m", "intensity"});
        h5::write_attribute(ds, "units", "1/yr");
        h5::write_attribute(ds, "long_name", "deaggregation d rate / d ln(intensity) = P(DS | x) |dH/d ln x|");
    }
}

void write_contents(const h5::File& f, const RiskReport& r, const Provenance& prov) {
    const HazardFile& hz = r.hazard;
    h5::write_attribute(f, "title", "rocksweep seismic risk of a record suite at a site");
    h5::write_attribute(f, "format_version", format_version);
    h5::write_attribute(f, "kind", "risk");
    h5::write_attribute(f, "Conventions", h5::cf_conventions);
    h5::write_attribute(f, "suite_file", r.suite_path);
    h5::write_attribute(f, "hazard_file", r.hazard_path);
    h5::write_attribute(f, "hazard_format", hz.format);
    h5::write_attribute(f, "hazard_measure", hazard_measure_name(hz.curve.measure(), hz.curve.period_s()));
    h5::write_attribute(f, "hazard_units", hazard_measure_units(hz.curve.measure()));
    h5::write_attribute(f, "hazard_period_s", hz.curve.period_s());
    h5::write_attribute(f, "investigation_time_years", hz.investigation_time_years);
    h5::write_attribute(f, "hazard_site", hz.site);
    h5::write_attribute(f, "hazard_points_dropped_low", static_cast<std::int64_t>(hz.dropped_low));
    h5::write_attribute(f, "hazard_points_dropped_high", static_cast<std::int64_t>(hz.dropped_high));
    h5::write_attribute(f, "hazard_tail_rule", "log-log extrapolation with the slope of the end segment on either side");
    h5::write_attribute(f, "intensity_measure", r.intensity_measure);
    h5::write_attribute(f, "intensity_units", r.intensity_units);
    h5::write_attribute(f, "exposure_years", r.exposure_years);
    h5::write_attribute(f, "rocksweep_version", prov.version);
    write_hazard(f, r);
    const h5::Group risk = f.create_group("risk");
    for (std::size_t s = 0; s < r.risk.scenarios.size(); ++s) write_scenario(risk, r, r.fragility.scenarios[s], r.risk.scenarios[s]);
    io::write_provenance(f, prov);  // no ranks: risk runs on one process
}

}  // namespace

SuiteFragilityTable read_suite_fragility(const std::string& path) {
    std::optional<h5::File> opened;
    try {
        opened.emplace(h5::File::open_read_only(path));
    } catch (const Hdf5Error&) {
        throw InputError("suite-file", path, "a rocksweep suite file; it is not an HDF5 file");
    }
    const h5::File& f = *opened;
    if (!f.has_attribute("kind") || h5::read_string_attribute(f, "kind") != "suite" || !f.exists("suite"))
        throw InputError("suite-file", path, "a file that rocksweep suite wrote");
    try {
        return read_table(f, path);
    } catch (const Hdf5Error& e) {
        throw InputError("suite-file", path, std::string("a readable rocksweep suite file (") + e.what() + ")");
    }
}

void write_risk(const std::string& path, const RiskReport& report, const Provenance& prov) {
    h5::publish_h5_atomically(path, [&](const h5::File& f) { write_contents(f, report, prov); });
}

}  // namespace rocksweep
