#pragma once
/// N motions of the model fitted to each record of a suite (`suite --synthetic-per-record N`):
/// one ModelMotions per record, each drawn with its own seed derived from the suite's seed and
/// the record's place, so that motion i of record k is the same bits whatever N, the rank
/// count, the chunking or a resume. docs/synthetic.md, "Motions fitted to each record".
#include <cstdint>
#include <string>
#include <vector>

#include "rocksweep/records/suite_sweep.hpp"
#include "rocksweep/synthetic/model_motions.hpp"

namespace rocksweep::synthetic {

/// The seed of the motions of record `record` (0-based, in the suite's order) under the suite's
/// `seed`: SplitMix64(SplitMix64(SplitMix64(seed) xor record)) / 4. Every bit of both enters
/// every bit of it (seed + record would give record 1 of seed 1 the motions of record 0 of
/// seed 2); one round more than a motion's own stream (normal_stream.hpp); 62 bits, so that
/// `synth --seed` takes it and writes the same motions.
std::uint64_t record_seed(std::uint64_t seed, std::size_t record);

/// A record's fitted model: the record's name in the suite and the generator of its motions.
struct FittedRecord {
    std::string name;
    Generator generator;
};

class FittedSuiteMotions : public MotionSource {
public:
    /// `per_record` (> 0) motions of each record's model, records in the suite's order.
    FittedSuiteMotions(std::vector<FittedRecord> records, std::uint64_t seed, std::size_t per_record);

    /// Motion j is motion j % per_record of record j / per_record.
    std::size_t size() const override { return models_.size() * per_record_; }
    /// "<record>_s<index, 6 digits>".
    std::string name(std::size_t j) const override;
    /// Path "synthetic:<record's seed>:<index>:<record>".
    Record motion(std::size_t j) const override;
    Record described(std::size_t j) const override;
    std::string describe() const override;

    std::size_t records() const { return models_.size(); }
    std::size_t per_record() const { return per_record_; }
    std::size_t record_of(std::size_t j) const { return j / per_record_; }

private:
    std::vector<std::string> names_;
    std::vector<ModelMotions> models_;  ///< record k's: per_record motions of record_seed(seed, k)
    std::uint64_t seed_;
    std::size_t per_record_;
};

}  // namespace rocksweep::synthetic
