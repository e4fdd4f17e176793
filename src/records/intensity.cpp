#include "rocksweep/records/intensity.hpp"

#include <cmath>
#include <limits>

namespace rocksweep {

namespace {

// Integral of a^2 over the first tau of a segment from a0 to a1 of length dt (a cubic in tau).
double square_integral(double a0, double a1, double dt, double tau) {
    const double s = (a1 - a0) / dt;
    return tau * (a0 * a0 + a0 * s * tau + s * s * tau * tau / 3.0);
}

// The time at which the running integral of a^2 reaches `target`: the segment by its sums,
// then the point inside it by bisection of the exact cubic (monotone in tau).
double time_of_square_integral(const std::vector<double>& a, double dt, double target) {
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < a.size(); ++i) {
        const double seg = square_integral(a[i], a[i + 1], dt, dt);
        if (sum + seg >= target && seg > 0.0) {
            double lo = 0.0, hi = dt;
            for (int k = 0; k < 60; ++k) {
                const double mid = 0.5 * (lo + hi);
                (sum + square_integral(a[i], a[i + 1], dt, mid) < target ? lo : hi) = mid;
            }
            return static_cast<double>(i) * dt + 0.5 * (lo + hi);
        }
        sum += seg;
    }
    return static_cast<double>(a.size() - 1) * dt;
}

}  // namespace

IntensityMeasures intensity_measures(const Record& r) {
    const std::vector<double>& a = r.ax_g;
    const double dt = r.dt_s, g = standard_gravity;
    IntensityMeasures m;
    m.duration_s = r.duration_s();
    double v = 0.0, squares = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::abs(a[i]) > m.pga_g) {
            m.pga_g = std::abs(a[i]);
            m.pga_time_s = static_cast<double>(i) * dt;
        }
        if (i + 1 == a.size()) break;
        // v is quadratic within a segment: its extreme inside lies where a crosses zero,
        // at tau = dt a0 / (a0 - a1), where v = v0 + a0 tau / 2.
        if ((a[i] > 0.0 && a[i + 1] < 0.0) || (a[i] < 0.0 && a[i + 1] > 0.0)) {
            const double tau = dt * a[i] / (a[i] - a[i + 1]);
            const double vz = v + 0.5 * a[i] * tau * g;
            if (std::abs(vz) > m.pgv_m_s) {
                m.pgv_m_s = std::abs(vz);
                m.pgv_time_s = static_cast<double>(i) * dt + tau;
            }
        }
        v += 0.5 * (a[i] + a[i + 1]) * dt * g;  // trapezoid: exact for a linear segment
        if (std::abs(v) > m.pgv_m_s) {
            m.pgv_m_s = std::abs(v);
            m.pgv_time_s = static_cast<double>(i + 1) * dt;
        }
        squares += square_integral(a[i], a[i + 1], dt, dt);
    }
    m.residual_velocity_m_s = v;
    m.arias_m_s = M_PI / (2.0 * g) * squares * g * g;
    m.significant_duration_s =
        squares > 0.0 ? time_of_square_integral(a, dt, 0.95 * squares) - time_of_square_integral(a, dt, 0.05 * squares) : 0.0;
    m.pga_vertical_g = r.ay_g.empty() ? std::numeric_limits<double>::quiet_NaN() : 0.0;
    for (double x : r.ay_g) m.pga_vertical_g = std::max(m.pga_vertical_g, std::abs(x));
    return m;
}

double pga_over_g_tan_alpha(double pga_g, double alpha_rad, double gravity) {
    return pga_g * standard_gravity / (gravity * std::tan(alpha_rad));
}

}  // namespace rocksweep
