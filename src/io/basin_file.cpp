#include "rocksweep/io/basin_file.hpp"

#include "rocksweep/io/hdf5.hpp"

namespace rocksweep {

namespace {

constexpr std::int64_t basin_format_version = 1;

struct Axes {
    h5::Dataset theta, theta_dot, curve_theta;
};

void write_map(const h5::Group& g, const char* name, const std::vector<std::uint8_t>& codes, const BasinGrid& grid,
               const Axes& axes, const char* long_name) {
    const h5::Dataset ds = h5::write_2d<std::uint8_t>(g, name, codes, grid.theta_dot_ratio.points, grid.theta_ratio.points);
    const std::uint8_t values[] = {0, 1, 2, 255};
    h5::write_attribute(ds, "long_name", long_name);
    h5::write_attribute(ds, "flag_values", std::span<const std::uint8_t>(values));
    h5::write_attribute(ds, "flag_meanings", "rest overturned_with_impact overturned_without_impact not_converged");
    h5::write_attribute(ds, "dimensions", "theta_dot_ratio theta_ratio");
    h5::attach_scale(ds, axes.theta_dot, 0);
    h5::attach_scale(ds, axes.theta, 1);
    h5::set_dimension_label(ds, 0, "theta_dot_ratio");
    h5::set_dimension_label(ds, 1, "theta_ratio");
}

void write_curve(const h5::Group& g, const char* name, const std::vector<double>& values, const Axes& axes,
                 const char* long_name, const char* comment) {
    const h5::Dataset ds = h5::write_1d<double>(g, name, values);
    h5::write_attribute(ds, "units", "1");
    h5::write_attribute(ds, "long_name", long_name);
    h5::write_attribute(ds, "comment", comment);
    h5::attach_scale(ds, axes.curve_theta, 0);
    h5::set_dimension_label(ds, 0, "curve_theta_ratio");
}

void write_scenario(const h5::Group& basins, const BasinScenario& s, const BasinFile& f, const Axes& axes) {
    const h5::Group g = basins.create_group(s.scenario.name);
    const Anchorage& a = s.scenario.anchorage;
    h5::write_attribute(g, "anchorage", to_string(a.kind));
    h5::write_attribute(g, "theta_f_ratio", s.scenario.theta_f_ratio);
    h5::write_attribute(g, "kmin_ratio", s.scenario.kmin_ratio);
    h5::write_attribute(g, "k_max_N_per_m", a.k_max);
    h5::write_attribute(g, "k_min_N_per_m", a.k_min);
    h5::write_attribute(g, "strength_N", a.strength_n);
    h5::write_attribute(g, "rest_fraction", rest_fraction(s.simulated));
    h5::write_attribute(g, "rest_fraction_predicted", rest_fraction(s.predicted));
    const BasinComparison& c = s.comparison;
    h5::write_attribute(g, "cells_clear", c.clear);
    h5::write_attribute(g, "cells_clear_disagreeing", c.clear_disagree);
    h5::write_attribute(g, "cells_near_boundary", c.near);
    h5::write_attribute(g, "cells_near_boundary_disagreeing", c.near_disagree);
    write_map(g, "outcome", s.simulated, f.grid, axes, "outcome of free rocking from the state, integrated");
    write_map(g, "outcome_predicted", s.predicted, f.grid, axes, "outcome of free rocking from the state, by energy");
    write_curve(g, "no_impact_boundary", s.no_impact, axes, "theta_dot / p",
                "theta > 0: states above overturn without an impact; theta < 0: states below");
    write_curve(g, "impact_boundary", s.impact, axes, "theta_dot / p",
                "theta > 0: states below overturn after one impact; theta < 0: states above");
}

}  // namespace

void write_basin_file(const std::string& path, const BasinFile& f) {
    h5::publish_h5_atomically(path, [&](const h5::File& file) {
        h5::write_attribute(file, "title", "rocksweep basins of attraction");
        h5::write_attribute(file, "Conventions", h5::cf_conventions);
        h5::write_attribute(file, "format", "rocksweep basin");
        h5::write_attribute(file, "format_version", basin_format_version);
        h5::write_attribute(file, "rocksweep_version", f.version);
        const Block& b = f.block;
        h5::write_attribute(file, "p_rad_s", b.p());
        h5::write_attribute(file, "alpha_rad", b.alpha_rad);
        h5::write_attribute(file, "e", b.e);
        h5::write_attribute(file, "radius_m", b.radius_m);
        h5::write_attribute(file, "mass_kg", b.mass_kg);
        h5::write_attribute(file, "gravity_m_s2", b.gravity);
        h5::write_attribute(file, "equations", to_string(f.equations));
        h5::write_attribute(file, "method", to_string(f.settings.method));
        h5::write_attribute(file, "steps_per_period", f.settings.steps_per_period);
        h5::write_attribute(file, "impact_threshold", f.impact_threshold);
        h5::write_attribute(file, "comparison_margin", f.margin);
        h5::write_attribute(file, "comment",
                            "free rocking (ground at rest) from each state theta = theta_ratio alpha, theta_dot = "
                            "theta_dot_ratio p; outcome: the kernel; outcome_predicted: the energy argument "
                            "(physics.md, Basins); a cell is clear when the prediction is the same at comparison_margin "
                            "of each axis's span around it");
        Axes axes;
        {
            // Each axis a dimension scale with its units, so that h5py and MATLAB label the maps.
            const h5::Group g = file.create_group("axes");
            const struct {
                const char* name;
                const Axis& axis;
                const char* long_name;
                h5::Dataset& scale;
            } scales[] = {{"theta_ratio", f.grid.theta_ratio, "theta / alpha", axes.theta},
                          {"theta_dot_ratio", f.grid.theta_dot_ratio, "theta_dot / p", axes.theta_dot},
                          {"curve_theta_ratio", f.curve_theta_ratio, "theta / alpha", axes.curve_theta}};
            for (const auto& a : scales) {
                a.scale = h5::write_1d<double>(g, a.name, a.axis.values());
                h5::write_attribute(a.scale, "units", "1");
                h5::write_attribute(a.scale, "long_name", a.long_name);
                h5::make_scale(a.scale, a.name);
            }
        }
        {
            const h5::Group basins = file.create_group("basins");
            for (std::size_t i = 0; i < f.scenarios.size(); ++i) {
                write_scenario(basins, f.scenarios[i], f, axes);
                h5::write_attribute(basins.open_group(f.scenarios[i].scenario.name), "index", i);
            }
        }
        const h5::Group prov = file.create_group("provenance");
        h5::write_attribute(prov, "version", f.version);
        h5::write_attribute(prov, "config", f.config_text);
    });
}

}  // namespace rocksweep
