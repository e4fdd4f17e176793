#pragma once
// What the motion tests share: the shared records as read, an independent oscillator stepped by
// complex arithmetic (not by the matrix exponential under test), and a sine's amplitude.
#include <cmath>
#include <complex>
#include <vector>

#include "rocksweep/records/record_suite.hpp"

namespace rocksweep::testing {

inline std::vector<Record> shared_records() {
    std::vector<Record> out;
    for (const SuiteRecord& r : read_record_suite(ROCKSWEEP_CONFIGS_DIR "/records_suite.csv").records)
        out.push_back(read_record(r.source));
    return out;
}

// u'' + 2 zeta w u' + w^2 u = -(a0 + s tau) over one step: u = Re(K e^{lambda tau}) + A + B tau
// with lambda = -zeta w + i w_d, the particular part A + B tau of the linear input.
struct ComplexOscillator {
    double w, zeta;
    double u = 0.0, v = 0.0;

    struct Segment {
        std::complex<double> lambda, k;
        double a, b;
        double u(double tau) const { return (k * std::exp(lambda * tau)).real() + a + b * tau; }
        double v(double tau) const { return (lambda * k * std::exp(lambda * tau)).real() + b; }
    };
    Segment segment(double a0, double slope) const {
        const double kk = w * w, c = 2.0 * zeta * w, wd = w * std::sqrt(1.0 - zeta * zeta);
        Segment s;
        s.lambda = {-zeta * w, wd};
        s.b = -slope / kk;
        s.a = (-a0 - c * s.b) / kk;
        const double p = u - s.a, q = -(v - s.b + zeta * w * p) / wd;
        s.k = {p, q};
        return s;
    }
    void step(double a0, double a1, double dt) {
        const Segment s = segment(a0, (a1 - a0) / dt);
        const double u1 = s.u(dt), v1 = s.v(dt);
        u = u1;
        v = v1;
    }
    double absolute_acceleration() const { return -2.0 * zeta * w * v - w * w * u; }
};

// Amplitude of the sinusoid of angular frequency `w` in y sampled at t_i = i dt over whole periods
// [first, first + n): the discrete projections onto sin and cos are exact for a pure sine.
inline double sine_amplitude(const std::vector<double>& y, double dt, double w, std::size_t first, std::size_t n) {
    double s = 0.0, c = 0.0;
    for (std::size_t i = first; i < first + n; ++i) {
        s += y[i] * std::sin(w * i * dt);
        c += y[i] * std::cos(w * i * dt);
    }
    return 2.0 / static_cast<double>(n) * std::hypot(s, c);
}

}  // namespace rocksweep::testing
