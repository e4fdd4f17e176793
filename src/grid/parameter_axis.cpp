#include "rocksweep/grid/parameter_axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/physics/block.hpp"
#include "rocksweep/physics/pulse_library.hpp"

namespace rocksweep {

namespace {

// The ranges of the single-value options (--phase, --vertical-amplitude, --restitution, ...),
// so that an axis accepts what the option accepts. Combinations (e above Housner's value of a
// reshaped block) are checked when the cells are built.
constexpr double two_pi = 2.0 * M_PI;
constexpr ParameterInfo table[] = {
    {Parameter::phase, "phase_rad", "rad", "phase psi of the pulse", -two_pi, two_pi, false},
    {Parameter::vertical_g, "vertical_g", "1", "a_v0 / g of the vertical pulse", -0.99, 0.99, false},
    {Parameter::vertical_phase, "vertical_phase_rad", "rad", "phase psi_v of the vertical pulse", -two_pi, two_pi, false},
    {Parameter::restitution, "restitution", "1", "angular-velocity ratio e at impact", 0.0, 1.0, true},
    {Parameter::radius, "radius_m", "m", "block size R (pivot to centre of mass)", 1e-3, 1e3, false},
    {Parameter::alpha, "alpha_rad", "rad", "slenderness alpha = atan(b / h)", min_alpha_rad, M_PI / 2, false},
    {Parameter::strength_ratio, "strength_ratio", "1", "anchorage strength F_u / (m g)", 0.0, 1e3, true},
    {Parameter::theta_f_ratio, "theta_f_ratio", "1", "fracture angle theta_f / alpha of the (K_max) spring", 1e-3, 1e3, false},
    {Parameter::kmin_ratio, "kmin_ratio", "1", "K_min / K_max of the adaptive anchorage", 1e-6, 1.0, false},
    {Parameter::stiffness, "stiffness_n_m", "N/m", "spring stiffness K (K_max of the adaptive anchorage)", 0.0, 1e12, true},
    {Parameter::pulse_family, "pulse_family", "1", "pulse family (code, named by flag_meanings)", 0.0, 0.0, false},
};

std::string range_text(const ParameterInfo& i) {
    std::string s = i.open_lo ? "(" : "[";
    s += format_short(i.lo, 6);
    s += ", ";
    s += format_short(i.hi, 6);
    s += "]";
    if (std::string_view(i.units) != "1") {
        s += " ";
        s += i.units;
    }
    return s;
}

bool parse_number(const std::string& s, double& x) {
    if (s.empty()) return false;
    char* end = nullptr;
    x = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && std::isfinite(x);
}

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> parts;
    std::size_t from = 0;
    for (std::size_t at; (at = s.find(sep, from)) != std::string::npos; from = at + 1) parts.push_back(s.substr(from, at - from));
    parts.push_back(s.substr(from));
    return parts;
}

}  // namespace

const ParameterInfo& parameter_info(Parameter p) {
    for (const ParameterInfo& i : table)
        if (i.parameter == p) return i;
    return table[0];  // not reached: every parameter has its row
}

std::string parameter_names() {
    std::string s;
    for (const ParameterInfo& i : table) s += (s.empty() ? "" : ", ") + std::string(i.name);
    return s;
}

ParameterAxis parse_parameter_axis(const std::string& option, const std::string& text) {
    const std::string forms = "NAME=LO:HI:POINTS or NAME=V1,V2,... with NAME one of " + parameter_names();
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) throw InputError(option, text, forms);
    std::string name = text.substr(0, eq);
    std::replace(name.begin(), name.end(), '-', '_');
    const ParameterInfo* info = nullptr;
    for (const ParameterInfo& i : table)
        if (name == i.name) info = &i;
    if (!info) throw InputError(option, text, "an axis named one of " + parameter_names());
    const std::string rest = text.substr(eq + 1);
    const std::string allowed = std::string(info->name) + " values in " + range_text(*info);

    ParameterAxis axis{info->parameter, {}, text};
    if (info->parameter == Parameter::pulse_family) {
        const std::vector<std::string>& names = pulse_family_names();
        for (const std::string& v : split(rest, ',')) {
            const auto it = std::find(names.begin(), names.end(), v);
            std::string all;
            for (const std::string& n : names) all += (all.empty() ? "" : ", ") + n;
            if (it == names.end()) throw InputError(option, text, "pulse_family=NAME,NAME,... with NAME one of " + all);
            const double code = static_cast<double>(it - names.begin());
            if (std::find(axis.values.begin(), axis.values.end(), code) != axis.values.end())
                throw InputError(option, text, "each family once (" + v + " is listed twice)");
            axis.values.push_back(code);
        }
        return axis;
    }
    const std::vector<std::string> range = split(rest, ':');
    if (range.size() == 3) {
        double lo, hi, n;
        if (!parse_number(range[0], lo) || !parse_number(range[1], hi) || !parse_number(range[2], n) ||
            n != std::floor(n) || n < 2 || n > 1e5)
            throw InputError(option, text, "NAME=LO:HI:POINTS with LO < HI and 2 to 100000 POINTS");
        if (!(lo < hi)) throw InputError(option, text, "LO < HI (the axis is reversed or empty)");
        const auto points = static_cast<std::size_t>(n);
        for (std::size_t i = 0; i < points; ++i)  // both ends exactly as written
            axis.values.push_back(i + 1 == points ? hi : lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(points - 1));
    } else if (range.size() == 1) {
        for (const std::string& v : split(rest, ',')) {
            double x;
            if (!parse_number(v, x)) throw InputError(option, text, forms);
            if (!axis.values.empty() && !(x > axis.values.back()))
                throw InputError(option, text, "strictly increasing values (a value is repeated or out of order)");
            axis.values.push_back(x);
        }
    } else {
        throw InputError(option, text, forms);
    }
    for (double x : axis.values) {
        const bool ok = (info->open_lo ? x > info->lo : x >= info->lo) && x <= info->hi;
        if (!ok) throw InputError(option, text, allowed);
    }
    return axis;
}

std::string flag_meanings(const ParameterAxis& axis) {
    if (axis.parameter != Parameter::pulse_family) return "";
    std::string s;
    for (double code : axis.values) s += (s.empty() ? "" : " ") + pulse_family_names().at(static_cast<std::size_t>(code));
    return s;
}

}  // namespace rocksweep
