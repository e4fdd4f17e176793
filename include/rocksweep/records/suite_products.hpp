#pragma once
/// What a finished suite sweep answers, read off its results (docs/suite.md): the
/// overturning-acceleration spectrum of each record, and the fragility curves of each
/// anchorage. The IDA curves are the results themselves (max_rotation against the level).
/// A run that did not converge (outcome 255) is no observation: it is left out of both.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rocksweep/grid/sweep.hpp"
#include "rocksweep/records/fragility.hpp"
#include "rocksweep/records/stripe_clusters.hpp"
#include "rocksweep/records/suite_sweep.hpp"

namespace rocksweep {

/// Per record and block, [record, alpha, radius] in C order. Overturning is not monotonic in the
/// scale: `safe_above` says whether a level above the first overturning one leaves the block up.
struct OverturningSpectrum {
    std::vector<double> first_intensity;  ///< lowest level that overturns; NaN if none does
    std::vector<double> first_pga_g;      ///< the record's PGA at that level [standard g]; NaN if none
    std::vector<double> below_intensity;  ///< the level before it; NaN if none or first is the lowest
    std::vector<std::uint8_t> safe_above;
};

/// Of scenario `s` of a complete sweep (`r` holds spec.cell_count() cells).
OverturningSpectrum overturning_spectrum(const SuiteSpec& spec, const SweepResults& r, std::size_t s);

/// Per damage state, block (alpha, size) and level: the stripes over the records, and a
/// lognormal fit per state and block.
struct SuiteFragility {
    std::vector<DamageState> states;
    std::vector<std::int32_t> exceed, total;  ///< [state, alpha, radius, level]: runs reaching it, converged runs
    std::vector<FragilityFit> fits;           ///< [state, alpha, radius]
    /// [state, alpha, radius]: the converged runs of each fit flagged sensitive (all 0 without
    /// --check-sensitivity)
    std::vector<std::int32_t> sensitive;
};

/// Of scenario `s` of a complete sweep.
SuiteFragility suite_fragility(const SuiteSpec& spec, const SweepResults& r, std::size_t s,
                               const std::vector<DamageState>& states);

/// Both products of one scenario, gathered a slab of records at a time, so that whoever reads
/// the results (from a file, say) never holds more than a slab: the overturning spectrum needs
/// each record's own levels, the fragility only counts per [state, alpha, radius, level].
/// Two passes over the records: add() them all, fit(), then add_errors() them all again for
/// the fits' standard errors, clustered by record (records/stripe_clusters.hpp: a record's runs
/// at every level are not independent trials), then fragility().
class SuiteProducts {
public:
    /// Keeps a reference to `spec`, which must outlive it.
    SuiteProducts(const SuiteSpec& spec, std::size_t scenario, std::vector<DamageState> states);
    /// Records [first_record, first_record + records) of the scenario, every one of their
    /// cells ([record, alpha, radius, level] in C order) in `r` from entry `offset` on.
    /// Each record once.
    void add(const SweepResults& r, std::size_t offset, std::size_t first_record, std::size_t records);
    /// Of the records added: complete once every record is.
    const OverturningSpectrum& overturning() const { return overturning_; }
    /// Fits the stripes of the records added, per state and block.
    void fit();
    /// The second pass: `records` records of `r` from entry `offset` (their cells as for add()),
    /// every record added once more, slab by slab in any order.
    void add_errors(const SweepResults& r, std::size_t offset, std::size_t records);
    /// The stripes, and the fits with their record-clustered errors (the records given to
    /// add_errors). Throws std::logic_error before fit().
    SuiteFragility fragility() const;

private:
    std::vector<Stripe> stripes(std::size_t state, std::size_t block) const;

    const SuiteSpec& spec_;
    std::size_t scenario_;
    OverturningSpectrum overturning_;
    SuiteFragility counts_;  // exceed, total and sensitive; no fits
    std::vector<FragilityFit> fits_;        // [state, alpha, radius], after fit()
    std::vector<StripeClusters> clusters_;  // the same, gathering each record's score
};

}  // namespace rocksweep
