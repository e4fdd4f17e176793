// The --axis options of a sweep (grid/parameter_axis.hpp), checked against the rest of the
// options: which scenario lists an axis replaces, which pulse families take which axes, and
// that every point of the axes makes a block and anchorages.
#include "rocksweep/app/axis_options.hpp"

#include <algorithm>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/grid/block_family.hpp"
#include "rocksweep/physics/pulse_library.hpp"

namespace rocksweep {

namespace {

/// An axis of theta_f / alpha or K makes the constant scenarios of a list one scenario,
/// "constant", and an axis of K_min / K_max the adaptive ones one "adaptive" (with its law's
/// suffix): the axis, not the list, then sets the value, and one group holds the spectra over it.
void collapse_anchorage_scenarios(SweepSpec& spec) {
    const ParameterAxis* by_kind[3] = {};  // the axis that sets constant, adaptive's theta_f, adaptive's rho
    for (const ParameterAxis& a : spec.axes) {
        if (a.parameter == Parameter::theta_f_ratio || a.parameter == Parameter::stiffness) {
            if (by_kind[0])
                throw InputError("axis", a.text, "not together with --axis " + by_kind[0]->text +
                                                     " (K fixes theta_f = 2 atan(F_u / (4 b K)))");
            by_kind[0] = by_kind[1] = &a;
        }
        if (a.parameter == Parameter::kmin_ratio) by_kind[2] = &a;
    }
    auto kind_of = [](const Scenario& s) { return s.anchorage.kind; };
    for (const ParameterAxis* a : {by_kind[0], by_kind[2]}) {
        if (!a) continue;
        const bool adaptive_only = a->parameter == Parameter::kmin_ratio;
        const bool any = std::any_of(spec.scenarios.begin(), spec.scenarios.end(), [&](const Scenario& s) {
            return adaptive_only ? kind_of(s) == AnchorageKind::adaptive : kind_of(s) != AnchorageKind::free;
        });
        if (!any)
            throw InputError("axis", a->text, adaptive_only ? "an adaptive anchorage among --anchorages (K_min / K_max is its)"
                                                            : "a constant or adaptive anchorage among --anchorages (the axis sets its spring)");
    }
    std::vector<Scenario> kept;
    bool constant_kept = false, adaptive_kept = false;
    for (Scenario s : spec.scenarios) {
        if (by_kind[0] && kind_of(s) == AnchorageKind::constant) {
            if (constant_kept) continue;
            s.name = "constant", constant_kept = true;
        }
        if (by_kind[2] && kind_of(s) == AnchorageKind::adaptive) {
            if (adaptive_kept) continue;
            const AdaptiveLaw law = s.anchorage.law;
            s.name = "adaptive" + (law == AdaptiveLaw::paper ? std::string() : "_" + to_string(law)), adaptive_kept = true;
        }
        kept.push_back(std::move(s));
    }
    spec.scenarios = std::move(kept);
}

/// A pulse-family axis: every family on it must take what the sweep sets of the pulse (a phase,
/// a vertical pulse, from the options or another axis), and --cycles reaches the families that
/// take it.
void check_family_axis(const Options& o, SweepSpec& spec) {
    const auto family_axis = std::find_if(spec.axes.begin(), spec.axes.end(),
                                          [](const ParameterAxis& a) { return a.parameter == Parameter::pulse_family; });
    if (family_axis == spec.axes.end()) return;
    std::string shaped;  // what of the pulse only the phased families take
    for (const ParameterAxis& a : spec.axes)
        if (a.parameter == Parameter::phase || a.parameter == Parameter::vertical_g || a.parameter == Parameter::vertical_phase)
            shaped = "--axis " + a.text;
    if (shaped.empty() && (o.pulse.phase != 0.0 || o.pulse.vertical_g != 0.0 || o.pulse.vertical_phase != 0.0))
        shaped = "--phase or --vertical-amplitude";
    for (double code : family_axis->values) {
        const auto f = static_cast<PulseFamily>(static_cast<int>(code));
        if (!shaped.empty() && !takes_phase(f))
            throw InputError("axis", family_axis->text, "families that take a phase and a vertical pulse (one-sine, n-sine) with " +
                                                            shaped + " (" + to_string(f) + " does not)");
        if (takes_cycles(f)) spec.pulse_cycles = o.pulse.cycles;
    }
}

}  // namespace

/// The --axis options into spec.axes, in the order given (the first varies slowest).
void add_parameter_axes(const Options& o, SweepSpec& spec) {
    for (const std::string& text : o.grid.axes) {
        ParameterAxis axis = parse_parameter_axis("axis", text);
        const Parameter p = axis.parameter;
        const std::string name = parameter_info(p).name;
        for (const ParameterAxis& a : spec.axes)
            if (a.parameter == p) throw InputError("axis", text, "one axis per parameter (" + name + " is given twice)");
        const bool pulse_part = p == Parameter::phase || p == Parameter::vertical_g || p == Parameter::vertical_phase;
        if (pulse_part && !takes_phase(spec.pulse_family))
            throw InputError("axis", text, name + " only with --pulse one-sine or n-sine (here " + to_string(spec.pulse_family) + ")");
        spec.axes.push_back(std::move(axis));
    }
    check_family_axis(o, spec);
    collapse_anchorage_scenarios(spec);
}

/// Every plane's block and anchorages, built once here so that a combination that makes none
/// (e above Housner's value of a reshaped block) is refused before any work, with its point.
void check_planes(const SweepSpec& spec) {
    for (std::size_t j = 0; j < spec.planes_per_scenario(); ++j) {
        try {
            const SweepSpec::Plane plane = spec.plane(j);
            if (plane.reshaped || plane.anchorage.any())
                for (const Scenario& s : spec.scenarios) anchorage_on(s, spec.block, plane.block, plane.anchorage);
        } catch (const InputError& e) {
            std::string axes, where;
            std::size_t rest = j;
            std::vector<std::string> coords(spec.axes.size());
            for (std::size_t k = spec.axes.size(); k-- > 0;) {
                const ParameterAxis& a = spec.axes[k];
                coords[k] = std::string(parameter_info(a.parameter).name) + " = " + format_short(a.values[rest % a.values.size()]);
                rest /= a.values.size();
            }
            for (std::size_t k = 0; k < spec.axes.size(); ++k) {
                axes += (axes.empty() ? "" : " ") + spec.axes[k].text;
                where += (where.empty() ? "" : ", ") + coords[k];
            }
            throw InputError("axis", axes, e.allowed() + " (at " + where + ")");
        }
    }
}

}  // namespace rocksweep
