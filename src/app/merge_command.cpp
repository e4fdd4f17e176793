// `rocksweep merge`: join the part files of a sweep split over a job array into one file,
// refusing files that are not parts of the same sweep.
#include <cstring>
#include <iostream>
#include <optional>

#include "rocksweep/app/cli.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/app/options.hpp"
#include "rocksweep/io/output_claim.hpp"
#include "rocksweep/io/spectra_file.hpp"
#include "rocksweep/grid/sweep.hpp"


namespace rocksweep {

namespace {

/// Calls f(column of a, same column of b) for every result column, `done` last.
template <class F>
void for_each_column(SweepResults& a, const SweepResults& b, F f) {
    f(a.outcome, b.outcome);
    f(a.max_rotation, b.max_rotation);
    f(a.impacts, b.impacts);
    f(a.impacts_total, b.impacts_total);
    f(a.t_overturn, b.t_overturn);
    f(a.peak_force_ratio, b.peak_force_ratio);
    f(a.broken, b.broken);
    f(a.mu_required, b.mu_required);
    f(a.pivot_uplift, b.pivot_uplift);
    f(a.done, b.done);
}

/// Bitwise: a cell computed twice by the same sweep is the same bits (NaN included); anything
/// else means the files were not computed by one sweep.
bool same_cell(SweepResults& a, const SweepResults& b, std::size_t i) {
    bool same = true;
    for_each_column(a, b, [&](auto& x, const auto& y) {
        same = same && std::memcmp(&x[i], &y[i], sizeof x[i]) == 0;
    });
    return same;
}

void copy_cell(SweepResults& a, const SweepResults& b, std::size_t i) {
    for_each_column(a, b, [&](auto& x, const auto& y) { x[i] = y[i]; });
}

/// "scenario free, a_p0/(alpha g) = 3, omega_p/p = 2.5": where cell i sits on the grid.
std::string describe_cell(const SweepSpec& spec, std::size_t i) {
    const std::size_t per = spec.cells_per_scenario(), n_omega = spec.omega_ratio.points;
    const std::size_t s = i / per, k = i % per;
    return "scenario " + spec.scenarios[s].name + ", a_p0/(alpha g) = " +
           format_short(spec.amplitude_ratio.at(k / n_omega)) + ", omega_p/p = " +
           format_short(spec.omega_ratio.at(k % n_omega));
}

/// read_spectra_results, its refusals of the file itself told as refusals of this part.
SweepResults read_part(const std::string& part, const SweepSpec& spec, const IntegratorSettings& settings) {
    try {
        return read_spectra_results(part, spec, settings);
    } catch (const InputError& e) {
        if (e.value() != part) throw;
        std::string allowed = e.allowed();
        if (const auto at = allowed.find("a rocksweep spectra file"); at == 0) allowed.replace(0, 24, "a rocksweep part file");
        throw InputError("part file", part, allowed);
    }
}

}  // namespace

int run_merge(const Options& opts, const MergeCommand& cmd, const std::string& config_text) {
    // Refinement is not a merge option: the parts' is their first's (and must be the others').
    const SweepSpec spec =
        cmd.parts.empty() ? make_sweep_spec(opts) : with_recorded_refinement(cmd.parts[0], make_sweep_spec(opts));
    const IntegratorSettings settings = make_settings(opts.numerics);
    // A part as the output is refused by the claim: the parts are the run's inputs (run_inputs.hpp).
    OutputClaim claim("output", cmd.output);
    if (claim.exists() && !cmd.overwrite)
        throw InputError("output", cmd.output, "a new file; it exists: pass --overwrite to replace it");

    const std::size_t total = spec.cell_count();
    SweepResults merged;
    merged.resize(total);
    std::vector<std::uint32_t> from(total, 0);  // 1 + the part a cell came from
    std::vector<std::string> warnings;           // printed once nothing can refuse the merge any more
    for (std::size_t p = 0; p < cmd.parts.size(); ++p) {
        // Throws naming the file when its grid, scenarios, block, pulse or settings differ.
        SweepResults part = read_part(cmd.parts[p], spec, settings);
        // Throws naming the part if its data changed since its run stored their checksum.
        const std::vector<std::string> unverified = verify_results_checksums(cmd.parts[p], spec, part);
        if (!unverified.empty())
            warnings.push_back("warning: " + cmd.parts[p] + " stores no checksum of the results of " +
                               (unverified.size() == spec.scenarios.size() ? std::string("its scenarios")
                                                                            : "scenario " + unverified.front()) +
                               " (written before rocksweep stored one, or killed before it finished): merged unverified\n");
        for (std::size_t i = 0; i < total; ++i) {
            if (!part.done[i]) continue;
            if (!merged.done[i]) {
                copy_cell(merged, part, i);
                from[i] = static_cast<std::uint32_t>(p + 1);
            } else if (!same_cell(merged, part, i)) {
                throw InputError("part file", cmd.parts[p],
                                 "a part of one sweep with " + cmd.parts[from[i] - 1] + "; the two differ at " +
                                     describe_cell(spec, i));
            }
        }
    }
    Provenance prov;
    prov.version = ROCKSWEEP_VERSION;
    prov.config_text = config_text;
    prov.ranks = 1;
    write_spectra(cmd.output, spec, merged, prov, settings);
    for (const std::string& w : warnings) std::cerr << w;  // even with --quiet: the data were not verified
    const std::size_t done = merged.done_count();
    if (!cmd.quiet) {
        std::cerr << "merged " << cmd.parts.size() << " file(s): " << done << " of " << total << " cells -> "
                  << cmd.output << "\n";
        if (done < total)
            std::cerr << total - done << " cells are in none of them: compute them with rocksweep sweep --resume -o "
                      << cmd.output << " and the same configuration\n";
    }
    return 0;
}

}  // namespace rocksweep
