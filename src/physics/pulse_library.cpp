#include "rocksweep/physics/pulse_library.hpp"

#include <cmath>

#include "rocksweep/core/errors.hpp"

namespace rocksweep {

namespace {
/// Name and definition of each family, in the order of PulseFamily.
struct Entry {
    const char* name;
    const char* definition;
};
constexpr Entry kFamilies[] = {
    {"one-sine", "a_p sin(omega_p t + psi) on [0, T_p]"},
    {"n-sine", "a_p sin(omega_p t + psi) on [0, n T_p]"},
    {"cycloidal-a", "a_p sin(omega_p t) on [0, T_p]"},
    {"cycloidal-b", "a_p cos(omega_p t) on [0, T_p]"},
    {"cycloidal-c", "a_p cos(omega_p t + phi_n) on [0, (n + 1/2 - phi_n / pi) T_p], the ground back at rest"},
    {"rectangle", "a_p held for T_p / 2 = pi / omega_p [s]"},
    {"ricker", "a_p (1 - 2 pi^2 tau^2 / T_p^2) exp(-pi^2 tau^2 / T_p^2), tau = t - 1.5 T_p, on [0, 3 T_p]"},
};
}  // namespace

const std::vector<std::string>& pulse_family_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (const Entry& e : kFamilies) v.push_back(e.name);
        return v;
    }();
    return names;
}

std::string pulse_family_help() {
    std::string out;
    for (const Entry& e : kFamilies) out += std::string(out.empty() ? "" : "; ") + e.name + ": " + e.definition;
    return out;
}

std::string to_string(PulseFamily f) { return pulse_family_names().at(static_cast<std::size_t>(f)); }

PulseFamily parse_pulse_family(const std::string& option, const std::string& text) {
    const std::vector<std::string>& names = pulse_family_names();
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (text == names[i]) return static_cast<PulseFamily>(i);
        list += (list.empty() ? "" : ", ") + names[i];
    }
    throw InputError(option, text, "one of " + list);
}

bool takes_cycles(PulseFamily f) { return f == PulseFamily::n_sine || f == PulseFamily::cycloidal_c; }
bool takes_phase(PulseFamily f) { return f == PulseFamily::one_sine || f == PulseFamily::n_sine; }

double cycloidal_phase(int n) {
    // f(phi) = cos phi - sin phi (c - phi), c = (2n+1) pi / 2 > pi/2: f(0) = 1 > 0 and
    // f(pi/2) = -(c - pi/2) < 0, f' = -sin phi - cos phi (c - phi) + sin phi < 0 on (0, pi/2):
    // one root, found by bisection to the last bit.
    const double c = (2.0 * n + 1.0) * M_PI / 2.0;
    double lo = 0.0, hi = M_PI / 2.0;
    for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        (std::cos(mid) - std::sin(mid) * (c - mid) > 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

Pulse make_pulse(const PulseShape& s, double a_g, double omega) {
    Pulse p;
    p.kind = PulseKind::sine;
    p.ax_g = a_g;
    p.omega = omega;
    switch (s.family) {
        case PulseFamily::one_sine:
        case PulseFamily::n_sine:
            p.phase = s.phase;
            p.ay_g = s.vertical_g;
            p.phase_y = s.vertical_phase;
            p.periods = s.family == PulseFamily::n_sine ? s.cycles : 1.0;
            break;
        case PulseFamily::cycloidal_a: break;
        case PulseFamily::cycloidal_b: p.phase = M_PI / 2; break;  // cos x = sin(x + pi/2)
        case PulseFamily::cycloidal_c: {
            const double phi = cycloidal_phase(s.cycles);
            p.phase = phi + M_PI / 2;
            p.periods = s.cycles + 0.5 - phi / M_PI;
            break;
        }
        case PulseFamily::rectangle:
            p.kind = PulseKind::constant;
            p.duration_s = M_PI / omega;
            break;
        case PulseFamily::ricker: p.kind = PulseKind::ricker; break;
    }
    return p;
}

}  // namespace rocksweep
