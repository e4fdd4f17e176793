// The suite's made motions: one model (--synthetic-count) or fitted to each record (--synthetic-per-record).
#include "rocksweep/app/suite_synthetic.hpp"

#include "rocksweep/app/option_checks.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/synthetic/model_motions.hpp"

namespace rocksweep {
namespace {

const std::vector<std::string> model_parameters{"--arias", "--d595", "--tmid", "--f-mid", "--f-slope", "--zeta"};
const std::vector<std::string> model_record{"--record", "--record-format", "--record-units", "--record-dt", "--record-column"};
const std::vector<std::string> model_sampling{"--fc", "--dt", "--motion-duration", "--seed"};

std::vector<std::string> joined(std::initializer_list<const std::vector<std::string>*> lists) {
    std::vector<std::string> all;
    for (const auto* l : lists) all.insert(all.end(), l->begin(), l->end());
    return all;
}

/// Throws for the first of `options` given (typed or in the config), with its value.
void refuse_given(const CLI::App& suite, const std::vector<std::string>& options, const std::string& why) {
    for (const std::string& name : options) {
        const CLI::Option* o = suite.get_option_no_throw(name);
        if (!o || o->count() == 0) continue;
        std::string value;
        for (const std::string& r : o->results()) value += (value.empty() ? "" : " ") + r;
        throw InputError(name.substr(2), value, why);
    }
}

}  // namespace

void add_suite_synthetic_options(CLI::App& s, SuiteCommand& cmd) {
    add_synthetic_options(s, cmd.synthetic);
    s.add_option("--synthetic-count", cmd.synthetic.count,
                 "Motions of the stochastic model (--arias ... or --record to fit; docs/synthetic.md) beside or "
                 "instead of --suite's records, made on the ranks, never stored")
        ->check(integer_in(0, 100000000))->capture_default_str();
    s.add_option("--synthetic-per-record", cmd.synthetic_per_record,
                 "Motions of the model fitted to each record of --suite (its unit, dt, column and scale), after the "
                 "records, made on the ranks, never stored; --seed S: record k's motions are those of seed "
                 "record_seed(S, k) (docs/synthetic.md)")
        ->check(integer_in(0, 100000000))->capture_default_str();
    s.add_flag("--synthetic-only", cmd.synthetic_only,
               "With --synthetic-per-record: sweep the fitted motions alone, the records serving only to fit the model");
}

void check_suite_synthetic_options(const CLI::App& app, const CLI::App& suite, const std::vector<std::string>& args,
                                   const SuiteCommand& cmd) {
    const std::size_t n = cmd.synthetic_per_record;
    if (cmd.synthetic_only && n == 0)
        throw InputError("synthetic-only", "(given)", "only with --synthetic-per-record N (the records then only fit the model)");
    if (n > 0) {
        if (cmd.synthetic.count > 0)
            throw InputError("synthetic-count", std::to_string(cmd.synthetic.count),
                             "not with --synthetic-per-record (motions of one model, or of the model fitted to each "
                             "record of --suite: one of the two)");
        if (cmd.suite.empty())
            throw InputError("synthetic-per-record", std::to_string(n), "with a --suite, to each of whose records the model is fitted");
        refuse_given(suite, joined({&model_parameters, &model_record}),
                     "not with --synthetic-per-record, which fits the model to each record of --suite");
        return;
    }
    if (cmd.suite.empty() && cmd.synthetic.count == 0)
        throw InputError("suite", "(not given)", "a suite of records (CSV), or --synthetic-count N motions of a model, or both");
    if (cmd.synthetic.count > 0)
        check_synthetic_options(suite, cmd.synthetic);
    else
        refuse_typed(app, args, joined({&model_parameters, &model_sampling, &model_record}),
                     "an option of the synthetic motions, which need --synthetic-count N or --synthetic-per-record N");
}

void check_suite_record_pga(const std::string& suite_path, const SuiteRecord& entry, const Record& record, bool any_pga) {
    if (any_pga || plausible_pga(record)) return;
    throw InputError("suite", suite_path + " line " + std::to_string(entry.line),
                     "record " + entry.name + " (" + record.path + "): " +
                         implausible_pga(record, "pass --record-any-pga to accept every record of the suite"));
}

MadeMotions make_suite_motions(const SuiteCommand& cmd) {
    MadeMotions made;
    if (cmd.synthetic.count > 0) {
        const ResolvedSource r = resolve(cmd.synthetic, nullptr);
        made.source = std::make_shared<synthetic::ModelMotions>(synthetic::Generator(r.params, r.dt_s, r.duration_s),
                                                                cmd.synthetic.seed, cmd.synthetic.count);
    }
    if (cmd.synthetic_per_record == 0) return made;
    made.suite = read_record_suite(cmd.suite);
    std::vector<synthetic::FittedRecord> fitted;
    for (const SuiteRecord& entry : made.suite.records) {
        const Record record = read_suite_record(made.suite, entry);
        check_suite_record_pga(cmd.suite, entry, record, cmd.synthetic.any_pga);
        const std::string where = cmd.suite + " line " + std::to_string(entry.line);
        try {
            const ResolvedSource r = fit_to_record(record, cmd.synthetic, nullptr);
            fitted.push_back({entry.name, synthetic::Generator(r.params, r.dt_s, r.duration_s)});
        } catch (const InputError& e) {
            // The motions' --dt, too coarse for this record's filter: the option is the user's.
            if (e.field() == "dt" && cmd.synthetic.dt_s > 0)
                throw InputError("dt", e.value(), e.allowed() + " (the model fitted to record " + entry.name + ", " + where + ")");
            const std::string what = (e.field() == "record" ? "" : e.field() + " = ") + e.value();
            throw InputError("suite", where,
                             "record " + entry.name + ": the model cannot be fitted to it (--synthetic-per-record): " + what +
                                 "; " + e.allowed());
        }
    }
    made.fitted = std::make_shared<synthetic::FittedSuiteMotions>(std::move(fitted), cmd.synthetic.seed, cmd.synthetic_per_record);
    made.source = made.fitted;
    return made;
}

void label_fitted_motions(SuiteSpec& spec, const SuiteCommand& cmd, const MadeMotions& made) {
    if (!made.fitted) return;
    if (cmd.synthetic_only) {
        spec.suite_path = cmd.suite;
        spec.metadata_columns = made.suite.metadata_columns;
    }
    for (SuiteMember& m : spec.records)
        if (m.motion >= 0) m.entry.metadata = made.suite.records.at(made.fitted->record_of(static_cast<std::size_t>(m.motion))).metadata;
}

}  // namespace rocksweep
