#include "rocksweep/synthetic/normal_stream.hpp"

#include <cmath>

namespace rocksweep::synthetic {

std::uint64_t mix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

NormalStream::NormalStream(std::uint64_t seed, std::uint64_t index) : engine_(mix64(mix64(seed) ^ index)) {}

double NormalStream::next() {
    if (has_spare_) {
        has_spare_ = false;
        return spare_;
    }
    // 53-bit uniforms: u1 in (0, 1] so that the logarithm is finite, u2 in [0, 1).
    constexpr double ulp = 1.0 / 9007199254740992.0;  // 2^-53
    const double u1 = static_cast<double>((engine_() >> 11) + 1) * ulp;
    const double u2 = static_cast<double>(engine_() >> 11) * ulp;
    const double r = std::sqrt(-2.0 * std::log(u1));
    const double phase = 2.0 * M_PI * u2;
    spare_ = r * std::sin(phase);
    has_spare_ = true;
    return r * std::cos(phase);
}

}  // namespace rocksweep::synthetic
