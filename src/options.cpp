#include "rocksweep/options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rocksweep/errors.hpp"
#include "rocksweep/record.hpp"

namespace rocksweep {

namespace {

BreakRule parse_break_rule(const std::string& s) {
    if (s == "angle") return BreakRule::angle;
    if (s == "force") return BreakRule::force;
    throw InputError("adaptive-break", s, "one of angle, force");
}

Axis make_axis(const std::string& name, const std::vector<double>& range, std::size_t points) {
    if (range.size() != 2) throw InputError(name + "-range", std::to_string(range.size()) + " values", "two values LO HI");
    const double lo = range[0], hi = range[1];
    const std::string shown = format_number(lo) + " " + format_number(hi);
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo > 0.0))
        throw InputError(name + "-range", shown, "finite LO HI with 0 < LO <= HI");
    if (hi < lo) throw InputError(name + "-range", shown, "LO <= HI (the grid is reversed)");
    if (points < 1) throw InputError(name + "-points", std::to_string(points), "an integer >= 1");
    if (hi == lo && points > 1)
        throw InputError(name + "-range", shown, "LO < HI when " + name + "-points > 1 (the grid is empty)");
    return Axis{lo, hi, points};
}

std::string tidy(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}

}  // namespace

Equations parse_equations(const std::string& s) {
    if (s == "nonlinear") return Equations::nonlinear;
    if (s == "linearised" || s == "linearized") return Equations::linearised;
    throw InputError("equations", s, "one of nonlinear, linearised");
}

Block make_block(const BlockOptions& o) {
    const std::optional<double> e = o.restitution > 0.0 ? std::optional<double>(o.restitution) : std::nullopt;
    if (o.radius_m > 0.0 || o.alpha_rad > 0.0) {
        double ratio = o.inertia_ratio;
        if (o.p > 0.0) ratio = inertia_ratio_from_p(o.p, o.radius_m, o.gravity);
        if (!(ratio > 0.0)) ratio = 4.0 / 3.0;  // a uniform rectangle's
        return equivalent_block(o.radius_m, o.alpha_rad, ratio, o.mass_kg, o.gravity, e);
    }
    return rectangular_block(o.half_width_m, o.half_height_m, o.mass_kg, o.gravity, e);
}

IntegratorSettings make_settings(const NumericsOptions& o) {
    IntegratorSettings s;
    if (o.method == "events") s.method = Method::events;
    else if (o.method == "paper") s.method = Method::paper;
    else throw InputError("method", o.method, "one of events, paper");
    s.steps_per_period = o.steps_per_period;
    s.paper_dt_s = o.paper_dt_s;
    s.max_steps = o.max_steps;
    s.energy_stop = !o.no_energy_stop;
    return s;
}

SweepSpec make_sweep_spec(const Options& o) {
    SweepSpec spec;
    spec.block = make_block(o.block);
    spec.equations = parse_equations(o.block.equations);
    spec.impact_threshold = o.numerics.impact_threshold;
    spec.phase = o.pulse.phase;
    spec.vertical_g = o.pulse.vertical_g;
    spec.vertical_phase = o.pulse.vertical_phase;
    spec.friction = o.base.friction;
    spec.omega_ratio = make_axis("omega-ratio", o.grid.omega_range, o.grid.omega_points);
    spec.amplitude_ratio = make_axis("amplitude-ratio", o.grid.amplitude_range, o.grid.amplitude_points);
    const Block& b = spec.block;
    const double strength = o.anchorage.strength_ratio * b.mass_kg * b.gravity;
    const BreakRule rule = parse_break_rule(o.anchorage.break_rule);
    for (const std::string& kind : o.grid.anchorages) {
        if (kind == "free") {
            spec.scenarios.push_back({"free", free_anchorage(), 0.0, 1.0});
        } else if (kind == "constant") {
            for (double r : o.grid.theta_f_ratios)
                spec.scenarios.push_back({"constant_tf" + tidy(r), constant_anchorage(b, strength, r * b.alpha_rad), r, 1.0});
        } else if (kind == "adaptive") {
            const double r = o.grid.adaptive_theta_f_ratio;
            for (double rho : o.grid.kmin_ratios)
                spec.scenarios.push_back({"adaptive_rho" + tidy(rho), adaptive_anchorage(b, strength, r * b.alpha_rad, rho, rule), r, rho});
        } else {
            throw InputError("anchorages", kind, "each one of free, constant, adaptive");
        }
    }
    if (!o.grid.only.empty()) {
        std::vector<Scenario> kept;
        std::string names;
        for (const Scenario& s : spec.scenarios) names += (names.empty() ? "" : ", ") + s.name;
        for (const std::string& want : o.grid.only) {
            auto it = std::find_if(spec.scenarios.begin(), spec.scenarios.end(), [&](const Scenario& s) { return s.name == want; });
            if (it == spec.scenarios.end()) throw InputError("scenario", want, "one of the config's scenarios: " + names);
            if (std::none_of(kept.begin(), kept.end(), [&](const Scenario& s) { return s.name == want; })) kept.push_back(*it);
        }
        spec.scenarios = kept;
    }
    if (spec.scenarios.empty()) throw InputError("anchorages", "(none)", "at least one scenario");
    for (std::size_t i = 0; i < spec.scenarios.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (spec.scenarios[i].name == spec.scenarios[j].name)
                throw InputError("theta-f-ratios/kmin-ratios", spec.scenarios[i].name, "distinct values (a scenario is listed twice)");
    return spec;
}

CellModel make_single_cell(const Options& o) {
    const Block b = make_block(o.block);
    const SingleOptions& s = o.single;
    Pulse pulse;
    pulse.ax_g = s.amplitude_ratio * b.alpha_rad;
    if (!s.record.empty()) {
        if (s.record_units.empty())
            throw InputError("record-units", "(missing)", "the unit of the record's second column, g or m/s^2");
        pulse = read_record(s.record, s.record_units, s.record_scale, b.gravity);
    } else if (s.pulse == "sine") {
        pulse.kind = PulseKind::sine;
        pulse.omega = s.omega_ratio * b.p();
        pulse.phase = o.pulse.phase;
        pulse.ay_g = o.pulse.vertical_g;
        pulse.phase_y = o.pulse.vertical_phase;
    } else if (s.pulse == "constant") {
        pulse.kind = PulseKind::constant;
        require_open("duration", s.duration_s, 0.0, INFINITY, "a pulse length > 0 s (needed by --pulse constant)");
        pulse.duration_s = s.duration_s;
    } else {
        throw InputError("pulse", s.pulse, "one of sine, constant");
    }
    const double strength = o.anchorage.strength_ratio * b.mass_kg * b.gravity;
    Anchorage a;
    if (s.anchorage == "free") a = free_anchorage();
    else if (s.anchorage == "constant")
        a = s.stiffness > 0.0 ? constant_anchorage_k(b, strength, s.stiffness)
                              : constant_anchorage(b, strength, s.theta_f_ratio * b.alpha_rad);
    else if (s.anchorage == "adaptive")
        a = adaptive_anchorage(b, strength, s.theta_f_ratio * b.alpha_rad, s.kmin_ratio, parse_break_rule(o.anchorage.break_rule));
    else throw InputError("anchorage", s.anchorage, "one of free, constant, adaptive");
    return make_cell_model(b, a, pulse, parse_equations(o.block.equations), o.numerics.impact_threshold);
}

double default_t_end(const CellModel& m) { return m.pulse.end_time() + 10.0 * 2.0 * M_PI / m.p(); }

}  // namespace rocksweep
