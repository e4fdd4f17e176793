#include "rocksweep/app/option_combinations.hpp"

#include <algorithm>
#include <cstdlib>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/physics/pulse_library.hpp"

namespace rocksweep {

namespace {

/// Lookup of an option of the app or of any subcommand, and of where its value came from.
class Given {
public:
    Given(const CLI::App& app, const std::vector<std::string>& args) : app_(app), args_(args) {}

    const CLI::Option* option(const std::string& name) const {
        if (const CLI::Option* o = app_.get_option_no_throw(name)) return o;
        // The command's own first: sweep and simulate each have a --pulse.
        for (bool parsed : {true, false})
            for (const CLI::App* sub : app_.get_subcommands([](const CLI::App*) { return true; }))
                if (sub->parsed() == parsed)
                    if (const CLI::Option* o = sub->get_option_no_throw(name)) return o;
        return nullptr;
    }
    Source source(const std::string& name) const {
        const CLI::Option* o = option(name);
        if (!o || o->count() == 0) return Source::unset;
        const bool typed = std::any_of(args_.begin(), args_.end(),
                                       [&](const std::string& a) { return a == name || a.rfind(name + "=", 0) == 0; });
        return typed ? Source::command_line : Source::config;
    }
    bool operator()(const std::string& name) const { return source(name) != Source::unset; }
    /// Set in a config to the value it has anyway: a config that spells out every default (the
    /// /provenance/config of every output) must not conflict with itself.
    bool config_default(const std::string& name) const {
        return source(name) == Source::config && at_default(*option(name));
    }
    /// Set, wherever, to the value it has anyway: ignoring it loses nothing the user meant
    /// (scripts pass --kmin-ratio 0.5 to every anchorage in a loop).
    bool at_default_value(const std::string& name) const { return (*this)(name) && at_default(*option(name)); }
    /// The value as given: the option's results, space-separated.
    std::string value(const std::string& name) const {
        std::string out;
        if (const CLI::Option* o = option(name))
            for (const std::string& r : o->results()) out += (out.empty() ? "" : " ") + r;
        return out;
    }

private:
    static bool at_default(const CLI::Option& o) {
        const std::vector<std::string>& r = o.results();
        const std::string& d = o.get_default_str();
        if (r.size() != 1 || d.empty()) return false;
        if (r[0] == d) return true;
        char *end_r = nullptr, *end_d = nullptr;
        const double x = std::strtod(r[0].c_str(), &end_r), y = std::strtod(d.c_str(), &end_d);
        return *end_r == '\0' && *end_d == '\0' && x == y;
    }

    const CLI::App& app_;
    const std::vector<std::string>& args_;
};

/// `option` must not be given beside `other`.
void excludes(const Given& given, const std::string& option, const std::string& other, const std::string& why) {
    if (!(given(option) && given(other))) return;
    const bool from_config = given.source(option) == Source::config && given.source(other) == Source::config;
    if (from_config && (given.config_default(option) || given.config_default(other))) return;
    throw InputError(option.substr(2), given.value(option), "not together with " + other + " " + given.value(other) + " (" + why + ")");
}

/// `option` must not be given unless `condition` holds (or at its default, which changes
/// nothing); `needed` says what would make it hold.
void only_if(const Given& given, const std::string& option, bool condition, const std::string& needed) {
    if (given(option) && !condition && !given.at_default_value(option)) throw InputError(option.substr(2), given.value(option), "only with " + needed);
}

void check_block(const Given& given) {
    const std::string two_blocks = "the block is rectangular (--half-width --half-height) or equivalent (--radius --alpha), not both";
    for (const char* eq : {"--radius", "--alpha", "--inertia-ratio", "--frequency-parameter"})
        for (const char* rect : {"--half-width", "--half-height"}) excludes(given, eq, rect, two_blocks);
    excludes(given, "--frequency-parameter", "--inertia-ratio", "p fixes I0/(m R^2) = g / (p^2 R)");
    only_if(given, "--radius", given("--alpha"), "--alpha (an equivalent block needs R and alpha)");
    only_if(given, "--alpha", given("--radius"), "--radius (an equivalent block needs R and alpha)");
    for (const char* opt : {"--inertia-ratio", "--frequency-parameter"})
        only_if(given, opt, given("--radius"), "--radius and --alpha (a rectangular block's I0/(m R^2) is 4/3)");
}

/// --cycles, --phase and the vertical component only where the pulse `name` (given as `shown`)
/// takes them; "sine" is the one-sine, "constant" takes none.
void check_pulse_parts(const Given& given, const std::string& name, const std::string& shown) {
    const bool family = name != "sine" && name != "constant";
    const PulseFamily f = family ? parse_pulse_family("pulse", name) : PulseFamily::one_sine;
    const bool phased = name == "sine" || (family && takes_phase(f));
    only_if(given, "--cycles", family && takes_cycles(f), "--pulse n-sine or cycloidal-c (here " + shown + ")");
    for (const char* opt : {"--phase", "--vertical-amplitude", "--vertical-phase"})
        only_if(given, opt, phased, "--pulse one-sine or n-sine (here " + shown + ")");
}

void check_simulate(const Given& given, const Options& o) {
    const SingleOptions& s = o.single;
    const std::string a = "--anchorage " + s.anchorage;
    for (const char* opt : {"--pulse", "--omega-ratio", "--amplitude-ratio", "--duration", "--phase", "--vertical-amplitude", "--vertical-phase"})
        excludes(given, opt, "--record", "a recorded ground motion replaces the pulse");
    for (const char* opt : {"--record-units", "--record-scale", "--record-format", "--record-dt", "--record-column",
                            "--record-vertical", "--record-vertical-column", "--floor"})
        only_if(given, opt, given("--record"), "--record");
    const bool constant_pulse = s.pulse == "constant" && s.record.empty();
    for (const char* opt : {"--omega-ratio", "--phase", "--vertical-amplitude", "--vertical-phase"})
        only_if(given, opt, !constant_pulse, "a sine pulse (here --pulse constant)");
    if (s.record.empty()) check_pulse_parts(given, s.pulse, "--pulse " + s.pulse);
    only_if(given, "--duration", constant_pulse || !s.record.empty(), "--pulse constant (a sine pulse lasts one period 2 pi / omega_p)");
    excludes(given, "--stiffness", "--theta-f-ratio", "K fixes theta_f = 2 atan(F_u / (4 b K))");
    only_if(given, "--stiffness", s.anchorage == "constant", "--anchorage constant (here " + a + ")");
    only_if(given, "--theta-f-ratio", s.anchorage != "free", "--anchorage constant or adaptive (here " + a + ")");
    only_if(given, "--kmin-ratio", s.anchorage == "adaptive", "--anchorage adaptive (here " + a + ")");
    // Sweep-only options typed for a history would be ignored; from a shared config they are not.
    for (const char* opt : {"--omega-ratio-range", "--omega-ratio-points", "--amplitude-ratio-range", "--amplitude-ratio-points",
                            "--anchorages", "--theta-f-ratios", "--kmin-ratios", "--adaptive-theta-f-ratio", "--scenario", "--axis",
                            "--period-range", "--period-points", "--pga-range", "--pga-points"})
        if (given.source(opt) == Source::command_line)
            throw InputError(std::string(opt).substr(2), given.value(opt),
                             "an option of sweep and info only; simulate takes --omega-ratio, --amplitude-ratio, --anchorage, "
                             "--theta-f-ratio, --kmin-ratio");
    for (const char* opt : {"--adaptive-break", "--adaptive-law"})
        if (given.source(opt) == Source::command_line)
            only_if(given, opt, s.anchorage == "adaptive", "--anchorage adaptive (here " + a + ")");
}

/// A sweep's per-kind options need their kind among --anchorages, unless --anchorages on the
/// command line narrowed a config that lists them.
void check_sweep_kinds(const Given& given, const Options& o) {
    const auto& kinds = o.grid.anchorages;
    const bool narrowed = given.source("--anchorages") == Source::command_line;
    auto check = [&](const char* opt, const char* kind) {
        const bool has = std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
        if (narrowed && given.source(opt) == Source::config) return;
        only_if(given, opt, has, std::string("'") + kind + "' among --anchorages (here --anchorages " + given.value("--anchorages") + ")");
    };
    check("--theta-f-ratios", "constant");
    check("--kmin-ratios", "adaptive");
    check("--adaptive-theta-f-ratio", "adaptive");
    check("--adaptive-break", "adaptive");
    check("--adaptive-law", "adaptive");
}

/// A parameter axis replaces the option that sets the same parameter: both would leave one
/// of them silently unused.
void check_axes(const Given& given, const std::string& subcommand, const Options& o) {
    if (subcommand == "suite" || subcommand == "design" || subcommand == "basin")
        for (const char* opt : {"--axis", "--period-range", "--period-points", "--pga-range", "--pga-points"})
            only_if(given, opt, false, "sweep, info and merge (" + subcommand + " has axes of its own)");
    // The spectrum's axes in physical terms replace the ratios: both typed is a contradiction.
    const std::pair<const char*, const char*> units[] = {
        {"--period-range", "--omega-ratio-range"}, {"--period-range", "--omega-ratio-points"},
        {"--pga-range", "--amplitude-ratio-range"}, {"--pga-range", "--amplitude-ratio-points"}};
    for (const auto& [physical, ratio] : units)
        if (given(physical) && given.source(ratio) == Source::command_line)
            throw InputError(std::string(ratio).substr(2), given.value(ratio),
                             std::string("not together with ") + physical + " " + given.value(physical) + " (it replaces the ratio axis)");
    const std::pair<const char*, const char*> replaced[] = {
        {"phase_rad", "--phase"}, {"vertical_g", "--vertical-amplitude"}, {"vertical_phase_rad", "--vertical-phase"},
        {"restitution", "--restitution"}};
    // Lists of scenarios: a config's list gives way to the axis (its scenarios become one); a list
    // typed beside the axis is a contradiction.
    const std::pair<const char*, const char*> typed_lists[] = {
        {"theta_f_ratio", "--theta-f-ratios"}, {"theta_f_ratio", "--adaptive-theta-f-ratio"},
        {"stiffness_n_m", "--theta-f-ratios"}, {"stiffness_n_m", "--adaptive-theta-f-ratio"},
        {"kmin_ratio", "--kmin-ratios"}, {"strength_ratio", "--strength-ratio"}, {"pulse_family", "--pulse"}};
    for (std::string text : o.grid.axes) {
        std::string name = text.substr(0, text.find('='));
        std::replace(name.begin(), name.end(), '-', '_');
        auto refuse = [&](const char* option, const char* axis) {
            throw InputError(std::string(option).substr(2), given.value(option),
                             "not together with --axis " + text + " (the axis sets " + axis + " in every cell)");
        };
        for (const auto& [axis, option] : replaced)
            if (name == axis && given(option) && !given.at_default_value(option)) refuse(option, axis);
        for (const auto& [axis, option] : typed_lists)
            if (name == axis && given.source(option) == Source::command_line) refuse(option, axis);
    }
}

}  // namespace

void check_combinations(const CLI::App& app, const std::string& subcommand, const Options& o, const std::vector<std::string>& args) {
    const Given given(app, args);
    check_block(given);
    only_if(given, "--paper-dt", o.numerics.method == "paper", "--method paper (the events method chooses its own step)");
    check_axes(given, subcommand, o);
    if (subcommand == "simulate") check_simulate(given, o);
    else {
        check_sweep_kinds(given, o);
        check_pulse_parts(given, o.pulse.family, "--pulse " + o.pulse.family);
    }
}

}  // namespace rocksweep
