#pragma once
// The velocity and displacement at the end of an acceleration read linear between its samples
// (as the engine reads a motion), from rest, each over its peak: what a high-pass must bring to 0.
#include <algorithm>
#include <cmath>
#include <vector>

namespace rocksweep::testing {

inline double residual_over_peak(const std::vector<double>& a, double dt) {
    double v = 0.0, d = 0.0, v_peak = 0.0, d_peak = 0.0;
    for (std::size_t k = 1; k < a.size(); ++k) {
        d += dt * v + dt * dt / 6.0 * (2.0 * a[k - 1] + a[k]);  // exact integrals of the linear pieces
        v += 0.5 * dt * (a[k - 1] + a[k]);
        v_peak = std::max(v_peak, std::abs(v));
        d_peak = std::max(d_peak, std::abs(d));
    }
    return std::max(std::abs(v) / v_peak, std::abs(d) / d_peak);
}

}  // namespace rocksweep::testing
