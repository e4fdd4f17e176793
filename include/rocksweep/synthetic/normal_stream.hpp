#pragma once
/// Standard normal numbers for motion (seed, index): the same sequence on every rank, whatever
/// rank draws it and in which order motions are drawn. std::mt19937_64 is specified bit for bit
/// by the C++ standard, its seed here a hash of (seed, index); the normal transform is ours
/// (Box-Muller), since std::normal_distribution differs between standard libraries. Only
/// std::log, std::sqrt, std::cos and std::sin of the platform's libm enter: the same binary
/// gives the same bits everywhere; another libm may differ in the last bit.
#include <cstdint>
#include <random>

namespace rocksweep::synthetic {

/// SplitMix64's finaliser: a bijection of 64-bit words that mixes every input bit into every
/// output bit (Steele, Lea & Flood 2014), so that neighbouring (seed, index) give unrelated seeds.
std::uint64_t mix64(std::uint64_t x);

class NormalStream {
public:
    NormalStream(std::uint64_t seed, std::uint64_t index);
    double next();

private:
    std::mt19937_64 engine_;
    double spare_ = 0.0;
    bool has_spare_ = false;
};

}  // namespace rocksweep::synthetic
