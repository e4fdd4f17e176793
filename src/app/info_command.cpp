// rocksweep info: the derived values of a config, and its grid and scenarios, as a user checks
// them before a long sweep.
#include "rocksweep/app/info_command.hpp"

#include <cmath>
#include <iomanip>
#include <string>

#include "rocksweep/grid/parameter_axis.hpp"
#include "rocksweep/grid/sweep.hpp"

namespace rocksweep {

void print_info(const Options& o, std::ostream& out) {
    const SweepSpec spec = make_sweep_spec(o);
    const Block& b = spec.block;
    out << std::setprecision(6);
    out << "block\n"
        << "  b = " << b.half_width_m() << " m, h = " << b.half_height_m() << " m, R = " << b.radius_m << " m\n"
        << "  alpha = " << b.alpha_rad << " rad (" << b.alpha_rad * 180 / M_PI << " deg)\n"
        << "  p = " << b.p() << " rad/s, I0 = " << b.inertia() << " kg m^2 (I0/(m R^2) = " << b.inertia_ratio << ")\n"
        << "  m = " << b.mass_kg << " kg, g = " << b.gravity << " m/s^2\n"
        << "  e = " << b.e << " (Housner: " << b.housner_e() << "), r = e^2 = " << b.e * b.e << "\n"
        << "  uplift threshold a_p0 / (alpha g) = " << std::tan(b.alpha_rad) / b.alpha_rad << "\n"
        << "  equations: " << to_string(spec.equations) << "\n";
    out << "grid\n"
        << (spec.frequency_axis == FrequencyAxis::period_s ? "  T_p [s]: " : "  omega_p / p: ") << spec.omega_ratio.lo
        << " .. " << spec.omega_ratio.hi << ", " << spec.omega_ratio.points << " points\n"
        << (spec.amplitude_axis == AmplitudeAxis::pga_g ? "  a_p0 / g: " : "  a_p0 / (alpha g): ") << spec.amplitude_ratio.lo
        << " .. " << spec.amplitude_ratio.hi << ", " << spec.amplitude_ratio.points << " points\n";
    for (const ParameterAxis& a : spec.axes) {
        const ParameterInfo& i = parameter_info(a.parameter);
        out << "  " << i.name << " (" << i.long_name << (std::string(i.units) == "1" ? "" : ", " + std::string(i.units)) << "): ";
        if (const std::string names = flag_meanings(a); !names.empty()) out << names;
        else
            for (std::size_t k = 0; k < a.values.size(); ++k) out << (k ? ", " : "") << a.values[k];
        out << "\n";
    }
    out << "  " << spec.scenarios.size() << " scenarios x " << spec.cells_per_scenario() << " = " << spec.cell_count() << " cells\n";
    out << "scenarios\n";
    for (const Scenario& s : spec.scenarios) {
        const Anchorage& a = s.anchorage;
        out << "  " << std::left << std::setw(26) << s.name << std::right << to_string(a.kind);
        if (a.kind != AnchorageKind::free) {
            out << "  F_u = " << a.strength_n << " N, theta_f = " << a.theta_f_rad << " rad (" << s.theta_f_ratio
                << " alpha), K = " << a.k_max << " N/m";
            if (a.kind == AnchorageKind::adaptive) out << ", K_min = " << a.k_min << " N/m (" << s.kmin_ratio << " K_max)";
        }
        out << "\n";
    }
}

}  // namespace rocksweep
