#include "rocksweep/app/options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/app/axis_options.hpp"
#include "rocksweep/app/memory_budget.hpp"
#include "rocksweep/records/record.hpp"
#include "rocksweep/records/suite_sweep.hpp"

namespace rocksweep {

namespace {

/// How a physics field id reads on the command line: the option the user wrote, its value as
/// given there, and the allowed range in the option's own terms when the physics words it in
/// other quantities (empty: keep the physics' value or wording).
struct Shown {
    std::string option, value, allowed;
};
using OptionNames = std::map<std::string, Shown>;

/// Runs `build`; an InputError carrying a physics field id ("block.mass") is rethrown against
/// the option that set it, so that `--mass 1e308` is never reported as some derived quantity.
template <class Build>
auto naming_options(const OptionNames& names, Build&& build) -> decltype(build()) {
    try {
        return build();
    } catch (const InputError& e) {
        const auto it = names.find(e.field());
        if (it == names.end()) throw;
        const Shown& s = it->second;
        throw InputError(s.option, s.value.empty() ? e.value() : s.value, s.allowed.empty() ? e.allowed() : s.allowed);
    }
}

/// A history's nine columns (t, theta, theta_dot, two stiffnesses, ground acceleration, two
/// works, switch energy: history.hpp), all double, are held until the file is written.
constexpr double history_bytes_per_sample = 9 * sizeof(double);

bool is_equivalent(const BlockOptions& o) { return o.radius_m > 0.0 || o.alpha_rad > 0.0; }

OptionNames block_names(const BlockOptions& o) {
    OptionNames n{{"block.mass", {"mass", format_short(o.mass_kg), ""}},
                  {"block.gravity", {"gravity", format_short(o.gravity), ""}},
                  {"block.restitution", {"restitution", format_short(o.restitution), ""}}};
    if (!is_equivalent(o)) {
        // The physics' values already say which other size they were judged with.
        n["block.half_width"] = {"half-width", "", ""};
        n["block.half_height"] = {"half-height", "", ""};
        n["block.alpha"] = {"half-width", format_short(o.half_width_m) + " (with h = " + format_short(o.half_height_m) + " m)", ""};
        return n;
    }
    n["block.radius"] = {"radius", format_short(o.radius_m), ""};
    n["block.alpha"] = {"alpha", format_short(o.alpha_rad), ""};
    if (o.p > 0.0) {
        // p fixes I0/(m R^2) = g / (p^2 R); its bounds [1, max] become bounds on p.
        const double hi = std::sqrt(o.gravity / o.radius_m), lo = std::sqrt(o.gravity / (max_inertia_ratio * o.radius_m));
        const std::string range = "p in [" + format_short(lo) + ", " + format_short(hi) +
                                  "] rad/s for this R and g (1 <= I0/(m R^2) = g/(p^2 R) <= 1e4)";
        n["block.p"] = {"frequency-parameter", format_short(o.p), range};
        n["block.inertia_ratio"] = {"frequency-parameter", format_short(o.p), range};
    } else {
        n["block.inertia_ratio"] = {"inertia-ratio", format_short(o.inertia_ratio), ""};
    }
    return n;
}

/// Names for an anchorage built from a theta_f / alpha ratio given as `ratio_option`.
OptionNames anchorage_names(const Block& b, double strength_ratio, const std::string& ratio_option, double ratio,
                            const std::string& kmin_option, double kmin) {
    return {{"anchorage.strength", {"strength-ratio", format_short(strength_ratio), ""}},
            {"anchorage.theta_f",
             {ratio_option, format_short(ratio),
              "0 < theta_f / alpha < pi / alpha = " + format_short(M_PI / b.alpha_rad, 4) + " for this block (theta_f below pi rad)"}},
            {"anchorage.kmin_ratio", {kmin_option, format_short(kmin), ""}}};
}

BreakRule parse_break_rule(const std::string& s) {
    if (s == "angle") return BreakRule::angle;
    if (s == "force") return BreakRule::force;
    throw InputError("adaptive-break", s, "one of angle, force");
}

AdaptiveLaw parse_adaptive_law(const std::string& s) {
    if (s == "paper") return AdaptiveLaw::paper;
    if (s == "passive") return AdaptiveLaw::passive;
    throw InputError("adaptive-law", s, "one of paper, passive");
}

std::string tidy(double x, int digits) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    return buf;
}

/// Scenario names' numbers: 6 significant digits (the names of earlier files), more only where
/// two different values would otherwise read the same (0.1 and 0.1000001).
std::vector<std::string> distinct_tidy(const std::vector<double>& v) {
    for (int digits = 6;; ++digits) {
        std::vector<std::string> names;
        for (double x : v) names.push_back(tidy(x, digits));
        bool clash = false;
        for (std::size_t i = 0; i < v.size() && !clash; ++i)
            for (std::size_t j = 0; j < i && !clash; ++j) clash = v[i] != v[j] && names[i] == names[j];
        if (!clash || digits >= 17) return names;
    }
}

}  // namespace

Axis make_axis(const std::string& name, const std::vector<double>& range, std::size_t points) {
    if (range.size() != 2) throw InputError(name + "-range", std::to_string(range.size()) + " values", "two values LO HI");
    const double lo = range[0], hi = range[1];
    const std::string shown = format_short(lo) + " " + format_short(hi);
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo > 0.0))
        throw InputError(name + "-range", shown, "finite LO HI with 0 < LO <= HI");
    if (hi < lo) throw InputError(name + "-range", shown, "LO <= HI (the grid is reversed)");
    if (points < 1) throw InputError(name + "-points", std::to_string(points), "an integer >= 1");
    if (hi == lo && points > 1)
        throw InputError(name + "-range", shown, "LO < HI when " + name + "-points > 1 (the grid is empty)");
    // A one-point axis would silently drop HI: the user meant something else.
    if (hi != lo && points == 1)
        throw InputError(name + "-range", shown, "LO = HI when --" + name + "-points is 1 (one point has no HI)");
    return Axis{lo, hi, points};
}

Equations parse_equations(const std::string& s) {
    if (s == "nonlinear") return Equations::nonlinear;
    if (s == "linearised" || s == "linearized") return Equations::linearised;
    throw InputError("equations", s, "one of nonlinear, linearised");
}

Block make_block(const BlockOptions& o) {
    return naming_options(block_names(o), [&] {
        const std::optional<double> e = o.restitution > 0.0 ? std::optional<double>(o.restitution) : std::nullopt;
        if (is_equivalent(o)) {
            if (!(o.radius_m > 0.0)) throw InputError("radius", "(missing)", "a length R > 0 m given with --alpha");
            if (!(o.alpha_rad > 0.0)) throw InputError("alpha", "(missing)", "an angle given with --radius");
            double ratio = o.inertia_ratio;
            if (o.p > 0.0) ratio = inertia_ratio_from_p(o.p, o.radius_m, o.gravity);
            if (!(ratio > 0.0)) ratio = 4.0 / 3.0;  // a uniform rectangle's
            return equivalent_block(o.radius_m, o.alpha_rad, ratio, o.mass_kg, o.gravity, e);
        }
        return rectangular_block(o.half_width_m, o.half_height_m, o.mass_kg, o.gravity, e);
    });
}

IntegratorSettings make_settings(const NumericsOptions& o) {
    IntegratorSettings s;
    if (o.method == "events") s.method = Method::events;
    else if (o.method == "paper") s.method = Method::paper;
    else throw InputError("method", o.method, "one of events, paper");
    s.steps_per_period = o.steps_per_period;
    s.tolerance = o.tolerance;
    s.paper_dt_s = o.paper_dt_s;
    s.max_steps = o.max_steps;
    s.energy_stop = !o.no_energy_stop;
    if (o.record_steps == "samples") s.steps_end_at_samples = true;
    else if (o.record_steps == "cross") s.steps_end_at_samples = false;
    else throw InputError("record-steps", o.record_steps, "one of samples, cross");
    return s;
}

SweepSpec make_sweep_spec(const Options& o) {
    SweepSpec spec;
    spec.block = make_block(o.block);
    spec.equations = parse_equations(o.block.equations);
    spec.impact_threshold = o.numerics.impact_threshold;
    spec.pulse_family = parse_pulse_family("pulse", o.pulse.family);
    spec.pulse_cycles = takes_cycles(spec.pulse_family) ? o.pulse.cycles : 1;
    spec.phase = o.pulse.phase;
    spec.vertical_g = o.pulse.vertical_g;
    spec.vertical_phase = o.pulse.vertical_phase;
    spec.friction = o.base.friction;
    spec.omega_ratio = make_axis("omega-ratio", o.grid.omega_range, o.grid.omega_points);
    spec.amplitude_ratio = make_axis("amplitude-ratio", o.grid.amplitude_range, o.grid.amplitude_points);
    // The spectrum in the pulse's own terms instead (a config's ratio axes give way).
    if (o.grid.period_points != 0 && o.grid.period_range.empty())
        throw InputError("period-points", std::to_string(o.grid.period_points), "only with --period-range LO HI");
    if (o.grid.pga_points != 0 && o.grid.pga_range.empty())
        throw InputError("pga-points", std::to_string(o.grid.pga_points), "only with --pga-range LO HI");
    if (!o.grid.period_range.empty()) {
        spec.omega_ratio = make_axis("period", o.grid.period_range, o.grid.period_points ? o.grid.period_points : o.grid.omega_points);
        spec.frequency_axis = FrequencyAxis::period_s;
    }
    if (!o.grid.pga_range.empty()) {
        spec.amplitude_ratio = make_axis("pga", o.grid.pga_range, o.grid.pga_points ? o.grid.pga_points : o.grid.amplitude_points);
        spec.amplitude_axis = AmplitudeAxis::pga_g;
    }
    const Block& b = spec.block;
    const double strength = o.anchorage.strength_ratio * b.mass_kg * b.gravity;
    const BreakRule rule = parse_break_rule(o.anchorage.break_rule);
    const AdaptiveLaw law = parse_adaptive_law(o.anchorage.law);
    // Another law is another anchorage: its own group, never mistaken for the paper's.
    const std::string law_suffix = law == AdaptiveLaw::paper ? "" : "_" + to_string(law);
    const std::vector<std::string> tf_names = distinct_tidy(o.grid.theta_f_ratios), rho_names = distinct_tidy(o.grid.kmin_ratios);
    for (const std::string& kind : o.grid.anchorages) {
        if (kind == "free") {
            spec.scenarios.push_back({"free", free_anchorage(), 0.0, 1.0});
        } else if (kind == "constant") {
            for (std::size_t i = 0; i < o.grid.theta_f_ratios.size(); ++i) {
                const double r = o.grid.theta_f_ratios[i];
                const OptionNames names = anchorage_names(b, o.anchorage.strength_ratio, "theta-f-ratios", r, "kmin-ratios", 1.0);
                spec.scenarios.push_back({"constant_tf" + tf_names[i],
                                          naming_options(names, [&] { return constant_anchorage(b, strength, r * b.alpha_rad); }), r, 1.0});
            }
        } else if (kind == "adaptive") {
            const double r = o.grid.adaptive_theta_f_ratio;
            for (std::size_t i = 0; i < o.grid.kmin_ratios.size(); ++i) {
                const double rho = o.grid.kmin_ratios[i];
                const OptionNames names = anchorage_names(b, o.anchorage.strength_ratio, "adaptive-theta-f-ratio", r, "kmin-ratios", rho);
                spec.scenarios.push_back({"adaptive_rho" + rho_names[i] + law_suffix,
                                          naming_options(names, [&] { return adaptive_anchorage(b, strength, r * b.alpha_rad, rho, rule, law); }),
                                          r, rho});
            }
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
                throw InputError(spec.scenarios[i].name.rfind("adaptive", 0) == 0 ? "kmin-ratios" : "theta-f-ratios",
                                 spec.scenarios[i].name, "distinct values (a scenario is listed twice)");
    add_parameter_axes(o, spec);
    // Rank 0 holds every cell's results: refuse a grid that cannot fit before allocating it.
    const double cells = static_cast<double>(spec.cell_count());
    require_memory("omega-ratio-points", std::to_string(spec.omega_ratio.points),
                   cells * static_cast<double>(SweepResults::bytes_per_cell()),
                   "with --amplitude-ratio-points " + std::to_string(spec.amplitude_ratio.points) + " and " +
                       std::to_string(spec.scenarios.size()) + " scenario(s), the results of " + format_short(cells) + " cells");
    check_planes(spec);
    return spec;
}

RecordSource record_source(const SingleOptions& s) {
    RecordSource r;
    r.path = s.record;
    const std::string ext = std::filesystem::path(s.record).extension().string();
    const bool at2_name = ext == ".AT2" || ext == ".at2";
    r.format = s.record_format == "auto" ? (at2_name ? RecordFormat::at2 : RecordFormat::time_accel)
                                         : parse_record_format("record-format", s.record_format);
    r.units = s.record_units;
    r.dt_s = s.record_dt_s;
    r.column = s.record_column;
    if (!s.record_vertical.empty() || s.record_vertical_column != 0)
        r.vertical = VerticalSource{s.record_vertical, s.record_vertical_column};
    r.scale = s.record_scale;
    return r;
}

CellModel make_single_cell(const Options& o, Record* record) {
    const Block b = make_block(o.block);
    const SingleOptions& s = o.single;
    Pulse pulse;
    pulse.ax_g = s.amplitude_ratio * b.alpha_rad;
    if (!s.record.empty()) {
        // Checked and shown as read, on the ground: the floor's motion is what the building makes of it.
        const Record ground = read_record(record_source(s));
        if (!o.numerics.record_any_pga && !plausible_pga(ground))
            throw InputError("record", s.record, implausible_pga(ground, "pass --record-any-pga to accept it"));
        pulse = to_pulse(s.floor.empty() ? ground : on_floor(ground, motion::parse_floor("floor", s.floor)), b.gravity);
        if (record) *record = ground;
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
        const PulseShape shape{parse_pulse_family("pulse", s.pulse), o.pulse.cycles, o.pulse.phase, o.pulse.vertical_g,
                               o.pulse.vertical_phase};
        pulse = make_pulse(shape, pulse.ax_g, s.omega_ratio * b.p());
    }
    const double strength = o.anchorage.strength_ratio * b.mass_kg * b.gravity;
    OptionNames names = anchorage_names(b, o.anchorage.strength_ratio, "theta-f-ratio", s.theta_f_ratio, "kmin-ratio", s.kmin_ratio);
    names["anchorage.stiffness"] = {"stiffness", format_short(s.stiffness), ""};
    const Anchorage a = naming_options(names, [&] {
        if (s.anchorage == "free") return free_anchorage();
        if (s.anchorage == "constant")
            return s.stiffness > 0.0 ? constant_anchorage_k(b, strength, s.stiffness)
                                     : constant_anchorage(b, strength, s.theta_f_ratio * b.alpha_rad);
        if (s.anchorage == "adaptive")
            return adaptive_anchorage(b, strength, s.theta_f_ratio * b.alpha_rad, s.kmin_ratio, parse_break_rule(o.anchorage.break_rule),
                                      parse_adaptive_law(o.anchorage.law));
        throw InputError("anchorage", s.anchorage, "one of free, constant, adaptive");
    });
    const CellModel m = make_cell_model(b, a, pulse, parse_equations(o.block.equations), o.numerics.impact_threshold);
    // The history holds every sample in memory before it is written: refuse one that cannot fit.
    const double t_end = s.t_end_s > 0.0 ? s.t_end_s : default_t_end(m);
    const double samples = std::floor(t_end / s.output_dt_s) + 1.0;
    require_memory("output-dt", format_short(s.output_dt_s), samples * history_bytes_per_sample,
                   (s.t_end_s > 0.0 ? "with --t-end " : "with the default t_end of ") + format_short(t_end) + " s, " +
                       "a history of " + format_short(samples) + " samples");
    return m;
}

bool defines_run(const std::string& command, const std::string& name, const Options& o) {
    // Kept out, these would also make a replay overwrite, resume or fall silent.
    static const std::set<std::string> invocation{"output", "resume", "overwrite", "quiet", "keep-rounds"};
    if (invocation.count(name)) return false;
    // A suite's ground motions are its records: the pulse and the spectra grid do not apply.
    static const std::set<std::string> pulse_and_grid{"pulse", "cycles", "phase", "vertical-amplitude", "vertical-phase",
                                                       "omega-ratio-range", "omega-ratio-points", "amplitude-ratio-range",
                                                       "amplitude-ratio-points", "refine"};
    if (command == "suite" && pulse_and_grid.count(name)) return false;
    const bool sweep = command != "simulate";
    const auto& kinds = o.grid.anchorages;
    const auto swept = [&](const char* kind) { return sweep && std::find(kinds.begin(), kinds.end(), kind) != kinds.end(); };
    const SingleOptions& s = o.single;
    const bool record = !s.record.empty(), sine = !record && s.pulse == "sine", rectangular = !is_equivalent(o.block);
    const bool sim_anchored = !sweep && s.anchorage != "free", sim_adaptive = !sweep && s.anchorage == "adaptive";
    const std::map<std::string, bool> rules{
        {"half-width", rectangular},
        {"half-height", rectangular},
        {"phase", sweep || sine},
        {"vertical-amplitude", sweep || sine},
        {"vertical-phase", sweep || sine},
        {"strength-ratio", swept("constant") || swept("adaptive") || sim_anchored},
        {"adaptive-break", swept("adaptive") || sim_adaptive},
        {"adaptive-law", swept("adaptive") || sim_adaptive},
        {"paper-dt", o.numerics.method == "paper"},
        {"omega-ratio-range", sweep},
        {"omega-ratio-points", sweep},
        {"amplitude-ratio-range", sweep},
        {"amplitude-ratio-points", sweep},
        {"anchorages", sweep},
        {"scenario", sweep},
        {"theta-f-ratios", swept("constant")},
        {"kmin-ratios", swept("adaptive")},
        {"adaptive-theta-f-ratio", swept("adaptive")},
        {"pulse", !record},
        {"omega-ratio", sine},
        {"amplitude-ratio", !record},
        {"duration", !record && s.pulse == "constant"},
        {"theta-f-ratio", sim_anchored && !(s.stiffness > 0.0)},
        {"kmin-ratio", sim_adaptive},
        {"stiffness", !sweep && s.anchorage == "constant"},
    };
    const auto it = rules.find(name);
    if (it != rules.end()) return it->second;
    return name.rfind("record", 0) != 0 || record;  // --record-units and the like go with --record
}

double default_t_end(const CellModel& m) { return m.pulse.end_time() + 10.0 * 2.0 * M_PI / m.p(); }

}  // namespace rocksweep
