// `rocksweep synth`: motions of the stochastic model, given or fitted to a record, as files.
#include "rocksweep/app/synth_command.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "rocksweep/app/option_checks.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/records/record.hpp"
#include "rocksweep/synthetic/fit.hpp"
#include "rocksweep/synthetic/generator.hpp"
#include "rocksweep/synthetic/model_motions.hpp"

namespace rocksweep {
namespace {

// The options that give the model's parameters directly, with their fields.
struct ParameterOption {
    const char* name;
    double synthetic::ModelParameters::*field;
    const char* help;
    double lo, hi;
    const char* unit;
};

const ParameterOption parameter_options[] = {
    {"--arias", &synthetic::ModelParameters::arias_m_s, "I_a: expected Arias intensity [m/s]", 1e-8, 100, "m/s"},
    {"--d595", &synthetic::ModelParameters::d595_s, "D5-95: significant duration [s]", 0.1, 1000, "s"},
    {"--tmid", &synthetic::ModelParameters::tmid_s, "t_mid: time of 45 % of I_a [s]", 0.05, 1000, "s"},
    {"--f-mid", &synthetic::ModelParameters::f_mid_hz, "Filter frequency at t_mid, omega_mid / 2 pi [Hz]", 0.1, 50, "Hz"},
    {"--f-slope", &synthetic::ModelParameters::f_slope_hz_s, "Its drift, omega' / 2 pi [Hz/s]", -10, 10, "Hz/s"},
    {"--zeta", &synthetic::ModelParameters::zeta_f, "Filter damping ratio zeta_f", 0.01, 0.99, ""},
};

}  // namespace

void add_synthetic_options(CLI::App& sub, SyntheticSource& s) {
    for (const ParameterOption& o : parameter_options)
        sub.add_option(o.name, s.params.*o.field, o.help)->check(number_in(o.lo, o.hi, o.unit));
    sub.add_option("--fc", s.params.fc_hz, "Corner of the high-pass oscillator [Hz] (Rezaeian & Der Kiureghian 2010)")
        ->check(number_in(0.01, 10, "Hz"))->capture_default_str();
    sub.add_option("--dt", s.dt_s, "Sampling interval of the motions [s] (default: the record's, or 0.01 s)")
        ->check(number_in(1e-5, 0.1, "s"));
    sub.add_option("--motion-duration", s.duration_s,
                   "Length of each motion [s] (default: 99.99 % of I_a plus 3 / f_c for the high-pass to settle)")
        ->check(number_in(0.05, 1e5, "s"));
    sub.add_option("--seed", s.seed, "Seed: motion i of seed S is the same on any machine and rank count")
        ->check(integer_in(0, (1LL << 62)))->capture_default_str();
    sub.add_option("--record", s.record.record, "Fit the model to this record (docs/synthetic.md) instead of giving it")
        ->check(existing_file("a ground-motion record"));
    sub.add_option("--record-format", s.record.record_format, "auto | time_accel | accel_only | at2, as for simulate")
        ->check(one_of({"auto", "time_accel", "accel_only", "at2"}))->capture_default_str();
    sub.add_option("--record-units", s.record.record_units, "g, m/s^2 or cm/s^2 (not for .AT2)")
        ->check(one_of({"g", "m/s^2", "cm/s^2"}));
    sub.add_option("--record-dt", s.record.record_dt_s, "Sampling interval of an accel_only record [s]")
        ->check(number_in(1e-5, 1, "s"));
    sub.add_option("--record-column", s.record.record_column, "Column of the acceleration, counting the time column")
        ->check(integer_in(1, 1000));
}

void check_synthetic_options(const CLI::App& sub, const SyntheticSource& s) {
    std::string given, missing;
    for (const ParameterOption& o : parameter_options) {
        std::string& list = sub.count(o.name) > 0 ? given : missing;
        list += (list.empty() ? "" : ", ") + std::string(o.name);
    }
    if (s.fitted() && !given.empty())
        throw InputError("record", s.record.record, "either a record to fit or the model's parameters (" + given + " given too)");
    if (!s.fitted() && !missing.empty())
        throw InputError(missing.substr(2, missing.find(',') == std::string::npos ? std::string::npos : missing.find(',') - 2),
                         "(not given)", "required without --record (missing: " + missing + ")");
}

ResolvedSource fit_to_record(const Record& rec, const SyntheticSource& s, std::ostream* log) {
    synthetic::FitSettings fs;
    fs.fc_hz = s.params.fc_hz;
    const synthetic::FitResult fit = synthetic::fit_model(rec.ax_g, rec.dt_s, fs);
    ResolvedSource r;
    r.params = fit.params;
    r.dt_s = s.dt_s > 0 ? s.dt_s : rec.dt_s;
    r.duration_s = s.duration_s > 0 ? s.duration_s : synthetic::default_duration_s(r.params);
    if (log)
        *log << "record " << rec.path << ": I_a = " << format_short(fit.record.arias_m_s, 4)
             << " m/s, D5-95 = " << format_short(fit.record.d595_s(), 4) << " s, t_mid = " << format_short(fit.record.t45_s, 4)
             << " s, " << fit.record_extrema << " positive minima and negative maxima (model: "
             << format_short(fit.simulated_extrema, 4) << ")\nfitted: " << synthetic::describe(fit.params) << "\n";
    return r;
}

ResolvedSource resolve(const SyntheticSource& s, std::ostream* log) {
    if (s.fitted()) {
        const Record rec = read_record(record_source(s.record));
        // A record in the wrong unit would give motions 100x too strong or weak (synth) or a
        // model of another record's kind; the same refusal as simulate --record's.
        if (!s.any_pga && !plausible_pga(rec))
            throw InputError("record", s.record.record, implausible_pga(rec, "pass --record-any-pga to fit it"));
        return fit_to_record(rec, s, log);
    }
    ResolvedSource r;
    r.params = s.params;
    synthetic::check(r.params);
    r.dt_s = s.dt_s > 0 ? s.dt_s : 0.01;
    r.duration_s = s.duration_s > 0 ? s.duration_s : synthetic::default_duration_s(r.params);
    return r;
}

CLI::App* add_synth_command(CLI::App& app, SynthCommand& cmd) {
    CLI::App* s = app.add_subcommand("synth", "Synthetic ground motions (Rezaeian & Der Kiureghian), given or fitted to a "
                                              "record, as records and a suite CSV");
    s->fallthrough();
    add_synthetic_options(*s, cmd.source);
    cmd.source.count = 1;
    s->add_option("--count", cmd.source.count, "Motions to write")->check(integer_in(1, 1000000))->capture_default_str();
    s->add_option("--first", cmd.first, "Index of the first motion")->check(integer_in(0, 1LL << 40))->capture_default_str();
    s->add_option("-o,--output", cmd.output, "Output folder: one NAME.txt per motion and suite.csv")->required();
    s->add_flag("--overwrite", cmd.overwrite, "Replace the folder's suite.csv and motions");
    s->add_flag("-q,--quiet", cmd.quiet, "Print nothing on success");
    return s;
}

int run_synth(const SynthCommand& cmd) {
    namespace fs = std::filesystem;
    const fs::path dir(cmd.output);
    const fs::path csv = dir / "suite.csv";
    if (fs::exists(dir) && !fs::is_directory(dir)) throw InputError("output", cmd.output, "a folder; it is a file");
    if (fs::exists(csv) && !cmd.overwrite)
        throw InputError("output", cmd.output, "a folder without a suite.csv; it has one: pass --overwrite to replace it");
    std::ostringstream fit_log;
    const ResolvedSource r = resolve(cmd.source, &fit_log);
    const synthetic::Generator gen(r.params, r.dt_s, r.duration_s);
    if (!cmd.quiet) std::cout << fit_log.str();
    fs::create_directories(dir);
    std::ofstream list(csv);
    list << "# rocksweep synth: " << synthetic::describe(r.params) << "; seed " << cmd.source.seed << ", dt " << r.dt_s
         << " s, " << format_short(r.duration_s, 6) << " s (docs/synthetic.md)\n"
         << "name,file,format,units,dt,column,scale,vertical_file,vertical_column,seed,index\n";
    std::vector<double> a;
    char line[64];
    for (std::size_t i = cmd.first; i < cmd.first + cmd.source.count; ++i) {
        gen.generate(cmd.source.seed, i, a);
        const std::string name = synthetic::motion_name(cmd.source.seed, i);
        std::ofstream out(dir / (name + ".txt"));
        out << "# time [s], ground acceleration [g]: motion " << i << " of seed " << cmd.source.seed << ", "
            << synthetic::describe(r.params) << "\n";
        // 17 digits: the file reads back to the generator's bits.
        for (std::size_t k = 0; k < a.size(); ++k) {
            std::snprintf(line, sizeof line, "%.10g %.17g\n", k * r.dt_s, a[k]);
            out << line;
        }
        if (!out) throw std::runtime_error("cannot write " + (dir / (name + ".txt")).string());
        list << name << "," << name << ".txt,time_accel,g,,,1,,," << cmd.source.seed << "," << i << "\n";
    }
    if (!list) throw std::runtime_error("cannot write " + csv.string());
    if (!cmd.quiet)
        std::cout << "wrote " << cmd.source.count << " motion(s) of " << gen.samples() << " samples (dt " << r.dt_s << " s) to "
                  << cmd.output << ", listed in " << csv.string() << "\n";
    return 0;
}

}  // namespace rocksweep
