#include "rocksweep/grid/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/grid/block_family.hpp"
#include "rocksweep/physics/integrator.hpp"

namespace rocksweep {

double Axis::at(std::size_t i) const {
    if (points <= 1) return lo;
    if (i + 1 == points) return hi;  // both ends exactly as given
    return lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(points - 1);
}

std::vector<double> Axis::values() const {
    std::vector<double> v(points);
    for (std::size_t i = 0; i < points; ++i) v[i] = at(i);
    return v;
}

std::size_t SweepSpec::planes_per_scenario() const {
    std::size_t n = 1;
    for (const ParameterAxis& a : axes) n *= a.values.size();
    return n;
}

std::vector<std::string> SweepSpec::axis_names() const {
    std::vector<std::string> names;
    for (const ParameterAxis& a : axes) names.push_back(parameter_info(a.parameter).name);
    names.push_back(amplitude_axis == AmplitudeAxis::pga_g ? "pga_g" : "amplitude_ratio");
    names.push_back(frequency_axis == FrequencyAxis::period_s ? "period_s" : "omega_ratio");
    return names;
}

std::vector<std::size_t> SweepSpec::axis_sizes() const {
    std::vector<std::size_t> sizes;
    for (const ParameterAxis& a : axes) sizes.push_back(a.values.size());
    sizes.insert(sizes.end(), {amplitude_ratio.points, omega_ratio.points});
    return sizes;
}

SweepSpec::Plane SweepSpec::plane(std::size_t plane_index) const {
    Plane p{block, pulse_shape(), {}, false, std::vector<std::size_t>(axes.size())};
    for (std::size_t k = axes.size(); k-- > 0;) {
        p.at[k] = plane_index % axes[k].values.size();
        plane_index /= axes[k].values.size();
    }
    double alpha = block.alpha_rad, radius = block.radius_m;
    std::optional<double> e;
    for (std::size_t k = 0; k < axes.size(); ++k) {
        const double x = axes[k].values[p.at[k]];
        switch (axes[k].parameter) {
            case Parameter::phase: p.shape.phase = x; break;
            case Parameter::vertical_g: p.shape.vertical_g = x; break;
            case Parameter::vertical_phase: p.shape.vertical_phase = x; break;
            case Parameter::restitution: e = x; break;
            case Parameter::radius: radius = x; break;
            case Parameter::alpha: alpha = x; break;
            case Parameter::strength_ratio: p.anchorage.strength_ratio = x; break;
            case Parameter::theta_f_ratio: p.anchorage.theta_f_ratio = x; break;
            case Parameter::kmin_ratio: p.anchorage.kmin_ratio = x; break;
            case Parameter::stiffness: p.anchorage.stiffness_n_m = x; break;
            case Parameter::pulse_family: p.shape.family = static_cast<PulseFamily>(static_cast<int>(x)); break;
        }
    }
    p.reshaped = alpha != block.alpha_rad || radius != block.radius_m;
    if (p.reshaped) p.block = reshaped_block(block, alpha, radius);
    if (e) {
        const Block& b = p.block;  // equivalent_block checks e against this block's Housner value
        p.block.e = equivalent_block(b.radius_m, b.alpha_rad, b.inertia_ratio, b.mass_kg, b.gravity, *e).e;
    }
    return p;
}

CellModel SweepSpec::cell(std::size_t index) const {
    const std::size_t per = cells_per_scenario();
    const Scenario& sc = scenarios.at(index / per);
    const std::size_t in = index % per;
    const std::size_t on_plane = in % plane_cells();
    const double w_value = omega_ratio.at(on_plane % omega_ratio.points);
    const double a_value = amplitude_ratio.at(on_plane / omega_ratio.points);
    // The ratios are the block's own: a_p / g = (a_p / (alpha g)) alpha, omega_p = (omega_p / p) p;
    // a period or a PGA is the pulse's whatever the block.
    const auto a_g = [&](const Block& b) { return amplitude_axis == AmplitudeAxis::pga_g ? a_value : a_value * b.alpha_rad; };
    const auto omega = [&](const Block& b) { return frequency_axis == FrequencyAxis::period_s ? 2.0 * M_PI / w_value : w_value * b.p(); };
    if (axes.empty()) return make_cell_model(block, sc.anchorage, make_pulse(pulse_shape(), a_g(block), omega(block)), equations, impact_threshold);
    // The anchorage keeps the scenario's where the block and F_u are unchanged.
    const Plane p = plane(in / plane_cells());
    const Anchorage a = p.reshaped || p.anchorage.any() ? anchorage_on(sc, block, p.block, p.anchorage) : sc.anchorage;
    return make_cell_model(p.block, a, make_pulse(p.shape, a_g(p.block), omega(p.block)), equations, impact_threshold);
}

void SweepResults::resize(std::size_t n) {
    outcome.assign(n, 0);
    max_rotation.assign(n, NAN);
    impacts.assign(n, 0);
    impacts_total.assign(n, 0);
    t_overturn.assign(n, NAN);
    peak_force_ratio.assign(n, NAN);
    broken.assign(n, 0);
    mu_required.assign(n, NAN);
    pivot_uplift.assign(n, 0);
    sensitive.assign(n, 0);
    done.assign(n, 0);
}

void SweepResults::store(std::size_t i, const CellResult& r) {
    outcome[i] = static_cast<std::uint8_t>(r.outcome);
    max_rotation[i] = r.max_rotation;
    impacts[i] = r.impacts;
    impacts_total[i] = r.impacts_total;
    t_overturn[i] = r.t_overturn_s;
    peak_force_ratio[i] = r.peak_force_ratio;
    broken[i] = r.broken;
    mu_required[i] = r.mu_required;
    pivot_uplift[i] = r.pivot_uplift;
    sensitive[i] = r.sensitive;
    done[i] = 1;
}

std::size_t SweepResults::done_count() const {
    return static_cast<std::size_t>(std::count_if(done.begin(), done.end(), [](std::uint8_t d) { return d != 0; }));
}

void compute_cells(const SweepSpec& spec, const IntegratorSettings& settings, std::size_t first,
                   std::size_t count, CellResult* out, int lanes) {
    std::vector<CellModel> cells(count);
    for (std::size_t i = 0; i < count; ++i) cells[i] = spec.cell(first + i);
    integrate_cells(cells, std::span<CellResult>(out, count), settings, lanes);
}

}  // namespace rocksweep
