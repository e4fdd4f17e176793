#include "rocksweep/synthetic/fitted_suite_motions.hpp"

#include <cstdio>
#include <stdexcept>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/synthetic/normal_stream.hpp"

namespace rocksweep::synthetic {

std::uint64_t record_seed(std::uint64_t seed, std::size_t record) {
    return mix64(mix64(mix64(seed) ^ static_cast<std::uint64_t>(record))) >> 2;
}

FittedSuiteMotions::FittedSuiteMotions(std::vector<FittedRecord> records, std::uint64_t seed, std::size_t per_record)
    : seed_(seed), per_record_(per_record) {
    if (per_record == 0 || records.empty()) throw std::invalid_argument("FittedSuiteMotions: no records or no motions per record");
    for (std::size_t k = 0; k < records.size(); ++k) {
        names_.push_back(std::move(records[k].name));
        models_.emplace_back(std::move(records[k].generator), record_seed(seed, k), per_record);
    }
}

std::string FittedSuiteMotions::name(std::size_t j) const {
    char index[32];
    std::snprintf(index, sizeof index, "_s%06zu", j % per_record_);
    return names_.at(record_of(j)) + index;
}

Record FittedSuiteMotions::motion(std::size_t j) const {
    Record r = described(j);
    const ModelMotions& model = models_[record_of(j)];
    model.generator().generate(model.seed(), j % per_record_, r.ax_g);
    return r;
}

Record FittedSuiteMotions::described(std::size_t j) const {
    const std::size_t k = record_of(j);
    Record r = models_.at(k).described(j % per_record_);
    r.path += ":" + names_[k];  // synthetic:SEED:INDEX, SEED the record's own: synth --seed SEED writes it
    return r;
}

std::string FittedSuiteMotions::describe() const {
    std::string text = "Rezaeian & Der Kiureghian model (docs/synthetic.md) fitted to each of " + std::to_string(models_.size()) +
                       " records, motions 0 to " + std::to_string(per_record_ - 1) + " of each, seed " + std::to_string(seed_);
    for (std::size_t k = 0; k < models_.size(); ++k) {
        const Generator& g = models_[k].generator();
        text += "; " + names_[k] + ": " + synthetic::describe(g.parameters()) + ", seed " + std::to_string(models_[k].seed()) +
                ", dt " + format_short(g.dt_s()) + " s, " + std::to_string(g.samples()) + " samples";
    }
    return text;
}

}  // namespace rocksweep::synthetic
