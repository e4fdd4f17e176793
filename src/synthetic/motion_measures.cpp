#include "rocksweep/synthetic/motion_measures.hpp"

#include <algorithm>
#include <cmath>

#include "rocksweep/records/record.hpp"

namespace rocksweep::synthetic {

AriasTimes arias_times(const std::vector<double>& a, double dt) {
    // Cumulative sum of a_k^2 dt, the model's own measure (docs/synthetic.md): the integral over
    // linear segments would be lower by (1 - rho) / 3 for neighbouring samples of correlation rho.
    std::vector<double> cumulative(a.size(), 0.0);
    for (std::size_t k = 1; k < a.size(); ++k) cumulative[k] = cumulative[k - 1] + dt * a[k] * a[k];
    const double total = cumulative.back();
    // Landmarks by linear interpolation of the cumulative curve between samples.
    const auto time_of = [&](double fraction) {
        const double target = fraction * total;
        const auto it = std::lower_bound(cumulative.begin(), cumulative.end(), target);
        const std::size_t k = static_cast<std::size_t>(it - cumulative.begin());
        if (k == 0) return 0.0;
        const double c0 = cumulative[k - 1], c1 = cumulative[k];
        return dt * ((k - 1) + (c1 > c0 ? (target - c0) / (c1 - c0) : 0.0));
    };
    const double g = standard_gravity;
    AriasTimes m;
    m.arias_m_s = M_PI / (2.0 * g) * total * g * g;
    m.t05_s = time_of(0.05);
    m.t45_s = time_of(0.45);
    m.t95_s = time_of(0.95);
    return m;
}

std::vector<double> upcrossing_times(const std::vector<double>& a, double dt) {
    std::vector<double> times;
    for (std::size_t k = 1; k < a.size(); ++k)
        if (a[k - 1] <= 0.0 && a[k] > 0.0) times.push_back(dt * ((k - 1) + a[k - 1] / (a[k - 1] - a[k])));
    return times;
}

std::size_t count_positive_minima_negative_maxima(const std::vector<double>& a, double dt, double t0, double t1) {
    const std::size_t first = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(t0 / dt)));
    const std::size_t last = std::min(a.size() - 1, static_cast<std::size_t>(std::floor(t1 / dt)) + 1);
    std::size_t count = 0;
    for (std::size_t k = first; k < last; ++k) {
        const bool positive_minimum = a[k] > 0.0 && a[k] < a[k - 1] && a[k] < a[k + 1];
        const bool negative_maximum = a[k] < 0.0 && a[k] > a[k - 1] && a[k] > a[k + 1];
        count += positive_minimum || negative_maximum;
    }
    return count;
}

double upcrossing_rate_hz(const std::vector<double>& a, double dt, double t0, double t1) {
    const std::vector<double> times = upcrossing_times(a, dt);
    const auto count = std::count_if(times.begin(), times.end(), [&](double t) { return t >= t0 && t < t1; });
    return static_cast<double>(count) / (t1 - t0);
}

}  // namespace rocksweep::synthetic
