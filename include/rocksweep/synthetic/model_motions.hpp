#pragma once
/// Motions 0 .. count - 1 of one seed of the model, as a suite's MotionSource: the suite keeps
/// their measures and makes each again where its cells are integrated.
#include <cstdint>
#include <string>

#include "rocksweep/records/suite_sweep.hpp"
#include "rocksweep/synthetic/generator.hpp"

namespace rocksweep::synthetic {

/// "synthetic_s<seed>_<index, 6 digits>": the name of motion (seed, index) in files and suites.
std::string motion_name(std::uint64_t seed, std::size_t index);

class ModelMotions : public MotionSource {
public:
    ModelMotions(Generator generator, std::uint64_t seed, std::size_t count)
        : generator_(std::move(generator)), seed_(seed), count_(count) {}
    std::size_t size() const override { return count_; }
    std::string name(std::size_t i) const override { return motion_name(seed_, i); }
    Record motion(std::size_t i) const override { return generator_.record(seed_, i); }
    Record described(std::size_t i) const override { return generator_.described(seed_, i); }
    std::string describe() const override;

    const Generator& generator() const { return generator_; }
    std::uint64_t seed() const { return seed_; }

private:
    Generator generator_;
    std::uint64_t seed_;
    std::size_t count_;
};

}  // namespace rocksweep::synthetic
