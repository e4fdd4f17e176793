#pragma once
/// A numeric parameter of the cells swept as an axis of a spectra grid, beside the two axes a
/// spectrum is drawn on (a_p0/(alpha g) and omega_p/p): the pulse's phase, the vertical pulse,
/// the restitution, the block's size or slenderness, the anchorage's strength, fracture angle,
/// stiffness or K_min / K_max. Every value of an
/// axis gives each scenario one more 2-D spectrum (docs/hdf5.md, "Parameter axes").
#include <string>
#include <vector>

namespace rocksweep {

enum class Parameter {
    phase,           ///< psi [rad] of the one-sine and n-sine pulses
    vertical_g,      ///< a_v0 / g of the vertical pulse
    vertical_phase,  ///< psi_v [rad]
    restitution,     ///< e, at most Housner's value of the cell's block
    radius,          ///< block size R [m] at the block's alpha and density
    alpha,           ///< slenderness alpha [rad] at the block's R and density
    strength_ratio,  ///< F_u / (m g) of every anchorage
    theta_f_ratio,   ///< theta_f / alpha of the constant spring and of the adaptive K_max spring
    kmin_ratio,      ///< K_min / K_max of the adaptive anchorage
    stiffness,       ///< K [N/m] of the constant spring, K_max of the adaptive (theta_f from F_u)
    pulse_family,    ///< categorical: the values are PulseFamily codes, named by flag_meanings
};

/// What a parameter is called in options and files, its units and its range.
struct ParameterInfo {
    Parameter parameter;
    const char* name;       ///< the axis's dataset name, e.g. "phase_rad"
    const char* units;      ///< CF units ("1" for a ratio)
    const char* long_name;  ///< the quantity in words
    double lo, hi;          ///< allowed values (closed bounds unless open_lo)
    bool open_lo;
};
const ParameterInfo& parameter_info(Parameter p);
/// "phase_rad, vertical_g, ...": the names, for --help and messages.
std::string parameter_names();

/// One parameter axis as the user wrote it: NAME=LO:HI:POINTS (evenly spaced, both ends
/// included) or NAME=V1,V2,... (the values as listed, strictly increasing); the pulse family
/// takes names, pulse_family=one-sine,ricker, and holds their codes in the order given.
struct ParameterAxis {
    Parameter parameter;
    std::vector<double> values;
    std::string text;  ///< as written, for messages
};

/// Parses `text`; dashes in NAME read as underscores (phase-rad = phase_rad). Throws
/// InputError(option, text, allowed) naming what is wrong: the name, the form, a value outside
/// the parameter's range, a reversed or repeated value.
ParameterAxis parse_parameter_axis(const std::string& option, const std::string& text);

/// The names of a categorical axis's codes, space-separated in the order of its values (CF
/// flag_meanings: "one-sine ricker"); "" for a numeric axis.
std::string flag_meanings(const ParameterAxis& axis);

}  // namespace rocksweep
