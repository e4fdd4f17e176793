// The products of a finished suite file (docs/suite.md): each scenario's overturning spectrum
// and fragility, written once the results are complete (suite_stream.cpp).
#include <cmath>

#include "result_columns.hpp"
#include "rocksweep/io/grid_layout.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "suite_layout.hpp"

namespace rocksweep::suite_detail {

namespace {

void write_overturning(const h5::Group& scenario, const SuiteSpec& spec, const OverturningSpectrum& o) {
    const h5::Group g = scenario.create_group("overturning");
    const std::vector<GridAxis> all = result_axes(spec);
    const GridAxis axes[] = {all[0], all[1], all[2]};
    const GridGroup grid(g, axes);
    const char* units = intensity_units(spec.measure);
    write_measure_on(grid, "first_intensity", o.first_intensity, {"record", "alpha_rad", "radius_m"}, units,
                     "lowest intensity level that overturns the block (NaN: none does)");
    write_measure_on(grid, "first_pga_g", o.first_pga_g, {"record", "alpha_rad", "radius_m"}, "1",
                     "PGA / standard gravity of the record at that level");
    write_measure_on(grid, "below_intensity", o.below_intensity, {"record", "alpha_rad", "radius_m"}, units,
                     "the level before it, which does not overturn the block (NaN: none)");
    const h5::Dataset ds = grid.write<std::uint8_t>("safe_above", o.safe_above);
    const std::uint8_t flags[] = {0, 1};
    h5::write_attribute(ds, "long_name", "a level above the first overturning one leaves the block standing");
    h5::write_attribute(ds, "flag_values", std::span<const std::uint8_t>(flags));
    h5::write_attribute(ds, "flag_meanings", "overturns_at_every_higher_level stands_at_some_higher_level");
}

void write_fragility(const h5::Group& scenario, const SuiteSpec& spec, const SuiteFragility& fr) {
    const h5::Group g = scenario.create_group("fragility");
    std::vector<double> index, ratios;
    std::string meanings;
    for (std::size_t d = 0; d < fr.states.size(); ++d) {
        index.push_back(static_cast<double>(d));
        ratios.push_back(fr.states[d].overturning ? NAN : fr.states[d].rotation_ratio);
        meanings += (meanings.empty() ? "" : " ") + fr.states[d].name();
    }
    const std::vector<GridAxis> all = result_axes(spec);
    const GridAxis axes[] = {{"damage_state", "1", "damage state (names: its flag_meanings)", index}, all[1], all[2], all[3]};
    const GridGroup grid(g, axes);
    const h5::Dataset state = g.open_dataset("damage_state");
    h5::write_attribute(state, "flag_values", std::span<const double>(index));
    h5::write_attribute(state, "flag_meanings", meanings);
    h5::write_attribute(state, "rotation_ratios", std::span<const double>(ratios));

    std::vector<double> fraction(fr.exceed.size()), lo(fr.exceed.size()), hi(fr.exceed.size());
    for (std::size_t k = 0; k < fr.exceed.size(); ++k) {
        if (fr.total[k] == 0) {
            fraction[k] = lo[k] = hi[k] = NAN;
            continue;
        }
        const Stripe s{1.0, fr.exceed[k], fr.total[k]};
        fraction[k] = s.fraction();
        wilson_interval(s, lo[k], hi[k]);
    }
    const h5::Dataset f = grid.write<double>("fraction", fraction);
    h5::write_attribute(f, "units", "1");
    h5::write_attribute(f, "long_name", "fraction of the records that reach the damage state (empirical)");
    h5::write_attribute(grid.write<double>("fraction_lo", lo), "long_name", "Wilson 95 % interval of fraction: low end");
    h5::write_attribute(grid.write<double>("fraction_hi", hi), "long_name", "Wilson 95 % interval of fraction: high end");
    h5::write_attribute(grid.write<std::int32_t>("exceed", fr.exceed), "long_name", "records that reach the damage state");
    h5::write_attribute(grid.write<std::int32_t>("total", fr.total), "long_name", "records whose run converged");

    struct FitColumn {
        const char* name;
        double (*get)(const FragilityFit&);
        const char* units;
        const char* long_name;
    };
    const char* units = intensity_units(spec.measure);
    const FitColumn columns[] = {
        // Not `median`: xarray's Dataset.median() would hide a variable of that name (fr.median).
        {"median_intensity", [](const FragilityFit& x) { return x.curve.median; }, units, "lognormal fit: median intensity"},
        {"beta", [](const FragilityFit& x) { return x.curve.beta; }, "1", "lognormal fit: dispersion (log standard deviation)"},
        {"median_intensity_lo", [](const FragilityFit& x) { return x.median_lo; }, units, "95 % interval of the median: low end"},
        {"median_intensity_hi", [](const FragilityFit& x) { return x.median_hi; }, units, "95 % interval of the median: high end"},
        {"beta_lo", [](const FragilityFit& x) { return x.beta_lo; }, "1", "95 % interval of beta: low end"},
        {"beta_hi", [](const FragilityFit& x) { return x.beta_hi; }, "1", "95 % interval of beta: high end"},
        {"se_ln_median", [](const FragilityFit& x) { return x.se_ln_median; }, "1", "standard error of ln(median)"},
        {"se_beta", [](const FragilityFit& x) { return x.se_beta; }, "1", "standard error of beta"},
        {"cov_ln_median_beta", [](const FragilityFit& x) { return x.cov_ln_median_beta; }, "1",
         "covariance of ln(median) and beta (of the fit's estimates)"},
    };
    for (const FitColumn& c : columns) {
        std::vector<double> v;
        for (const FragilityFit& fit : fr.fits) v.push_back(c.get(fit));
        write_measure_on(grid, c.name, v, {"damage_state", "alpha_rad", "radius_m"}, c.units, c.long_name);
    }
    if (spec.sensitivity.on) {
        const h5::Dataset ds = grid.write_on<std::int32_t>("sensitive_runs", fr.sensitive, {"damage_state", "alpha_rad", "radius_m"});
        h5::write_attribute(ds, "units", "1");
        h5::write_attribute(ds, "long_name", "runs of the fit (converged) flagged sensitive");
    }
    std::vector<std::uint8_t> status;
    for (const FragilityFit& fit : fr.fits) status.push_back(static_cast<std::uint8_t>(fit.status));
    const h5::Dataset ds = grid.write_on<std::uint8_t>("fit_status", status, {"damage_state", "alpha_rad", "radius_m"});
    io::write_fit_status_flags(ds, "how the lognormal fit ended (docs/fragility.md)");
}

}  // namespace

void write_products(const h5::Group& scenario, const SuiteSpec& spec, const OverturningSpectrum& o, const SuiteFragility& fr) {
    write_overturning(scenario, spec, o);
    write_fragility(scenario, spec, fr);
}

}  // namespace rocksweep::suite_detail
