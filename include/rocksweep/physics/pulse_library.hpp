#pragma once
/// The named pulse families a sweep (or `simulate`) runs, each built from its peak ground
/// acceleration a_p and its omega_p = 2 pi / T_p (docs/physics.md, "Pulse families").
#include <string>
#include <vector>

#include "rocksweep/physics/excitation.hpp"

namespace rocksweep {

enum class PulseFamily {
    one_sine,     ///< a_p sin(omega_p t + psi) on [0, T_p]; Makris-Roussos type A at psi = 0
    n_sine,       ///< a_p sin(omega_p t + psi) on [0, n T_p]
    cycloidal_a,  ///< a_p sin(omega_p t) on [0, T_p]
    cycloidal_b,  ///< a_p cos(omega_p t) on [0, T_p]
    cycloidal_c,  ///< a_p cos(omega_p t + phi_n) on [0, (n + 1/2 - phi_n / pi) T_p]
    rectangle,    ///< Housner's a_p held for T_p / 2 = pi / omega_p
    ricker,       ///< a_p (1 - 2 pi^2 tau^2 / T_p^2) exp(-pi^2 tau^2 / T_p^2), tau = t - 1.5 T_p, on [0, 3 T_p]
};

/// The family's name on the command line and in output files ("one-sine", "n-sine", ...).
std::string to_string(PulseFamily f);
/// The names, in the order of PulseFamily, for --help and messages.
const std::vector<std::string>& pulse_family_names();
/// Each family's name and definition, for --help.
std::string pulse_family_help();
/// Throws InputError(option, text, allowed) for a name that is none of pulse_family_names().
PulseFamily parse_pulse_family(const std::string& option, const std::string& text);
/// Whether the family takes a number of cycles n (n-sine, cycloidal-c), a phase psi and a
/// vertical component (one-sine, n-sine).
bool takes_cycles(PulseFamily f);
bool takes_phase(PulseFamily f);

/// The shape of a sweep's pulses: everything but amplitude and frequency.
struct PulseShape {
    PulseFamily family = PulseFamily::one_sine;
    int cycles = 1;               ///< n of n-sine and cycloidal-c
    double phase = 0.0;           ///< psi [rad] (one-sine, n-sine)
    double vertical_g = 0.0;      ///< a_v0 / g (one-sine, n-sine)
    double vertical_phase = 0.0;  ///< psi_v [rad]
};

/// phi_n of the type C_n pulse: the root in (0, pi/2) of cos phi = sin phi ((2n+1) pi/2 - phi),
/// which brings the ground's velocity and displacement back to zero at the window's end, to
/// machine precision (n >= 1).
double cycloidal_phase(int n);

/// The pulse of `shape` with peak horizontal acceleration a_g [g] at omega [rad/s].
Pulse make_pulse(const PulseShape& shape, double a_g, double omega);

}  // namespace rocksweep
