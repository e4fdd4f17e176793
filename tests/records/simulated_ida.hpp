#pragma once
// Simulated incremental dynamic analyses for the fragility tests: records whose capacities are
// lognormal, each run at the 30 levels 0.05..1.5 of the README's suites, reaching the state at
// and above its capacity; fitted pooled (every run a trial) and clustered by record.
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "rocksweep/records/fragility.hpp"
#include "rocksweep/records/stripe_clusters.hpp"

namespace rocksweep::simulated {

inline std::vector<double> ida_levels() {
    std::vector<double> x;
    for (int l = 1; l <= 30; ++l) x.push_back(0.05 * l);
    return x;
}

struct Ida {
    FragilityFit pooled, clustered;
};

/// `independent`: a fresh capacity for every run instead, as if every run were another record.
inline Ida ida(std::mt19937_64& rng, int records, double median, double beta, bool independent = false) {
    const std::vector<double> x = ida_levels();
    std::normal_distribution<double> normal;
    std::vector<std::vector<std::int8_t>> outcome(records, std::vector<std::int8_t>(x.size()));
    std::vector<Stripe> stripes;
    for (double xl : x) stripes.push_back({xl, 0, records});
    for (auto& rec : outcome) {
        double capacity = median * std::exp(beta * normal(rng));
        for (std::size_t l = 0; l < x.size(); ++l) {
            if (independent) capacity = median * std::exp(beta * normal(rng));
            rec[l] = x[l] >= capacity ? 1 : 0;
            stripes[l].exceed += rec[l];
        }
    }
    Ida out;
    out.pooled = fit_stripes(stripes);
    StripeClusters clusters(out.pooled, x);
    for (const auto& rec : outcome) clusters.add(rec);
    out.clustered = clusters.corrected(stripes);
    return out;
}

}  // namespace rocksweep::simulated
