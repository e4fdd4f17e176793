#include "rocksweep/synthetic/fit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/synthetic/generator.hpp"

namespace rocksweep::synthetic {
namespace {

// Least squares of the cumulative up-crossing count N(t) over [t5, t95] against
// c + f_mid (t - t_mid) + f'/2 (t - t_mid)^2, the integral of the filter's frequency line.
void fit_frequency(const std::vector<double>& crossings, const AriasTimes& m, ModelParameters& p) {
    double s[5] = {0, 0, 0, 0, 0}, r[3] = {0, 0, 0};  // sums of x^0..x^4 and of N x^0..x^2
    std::size_t count = 0;
    for (const double t : crossings) {
        if (t < m.t05_s || t > m.t95_s) continue;
        const double x = t - m.t45_s, n = static_cast<double>(++count);
        double power = 1.0;
        for (int e = 0; e < 5; ++e, power *= x) {
            s[e] += power;
            if (e < 3) r[e] += n * power;
        }
    }
    if (count < 10)
        throw InputError("record", std::to_string(count) + " zero up-crossings between t5 and t95",
                         "at least 10 to fit the filter's frequency");
    // Normal equations [s0 s1 s2; s1 s2 s3; s2 s3 s4] (c, b, a) = r, by Cramer's rule.
    const auto det3 = [](double a, double b, double c, double d, double e, double f, double g, double h, double i) {
        return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    };
    const double d = det3(s[0], s[1], s[2], s[1], s[2], s[3], s[2], s[3], s[4]);
    const double b = det3(s[0], r[0], s[2], s[1], r[1], s[3], s[2], r[2], s[4]) / d;
    const double a = det3(s[0], s[1], r[0], s[1], s[2], r[1], s[2], s[3], r[2]) / d;
    p.f_mid_hz = std::clamp(b, filter_frequency_floor_hz, 50.0);
    p.f_slope_hz_s = std::clamp(2.0 * a, -10.0, 10.0);
}

// Mean count of positive minima and negative maxima over [t5, t95] of `realisations` motions.
double simulated_extrema(const ModelParameters& p, double dt, double duration, const AriasTimes& m,
                         const FitSettings& settings) {
    // A gain does not move an extremum: the high-pass's share is not given back here (Stages).
    const Generator generator(p, dt, duration, Stages{.keep_arias = false});
    std::vector<double> a;
    double total = 0.0;
    for (int i = 0; i < settings.realisations; ++i) {
        generator.generate(settings.seed, static_cast<std::uint64_t>(i), a);
        total += static_cast<double>(count_positive_minima_negative_maxima(a, dt, m.t05_s, m.t95_s));
    }
    return total / settings.realisations;
}

}  // namespace

FitResult fit_model(const std::vector<double>& a_g, double dt_s, const FitSettings& settings) {
    FitResult fit;
    fit.record = arias_times(a_g, dt_s);
    const AriasTimes& m = fit.record;
    if (!(fit.record.arias_m_s > 0.0)) throw InputError("record", "an acceleration that is zero throughout", "a ground motion");
    ModelParameters& p = fit.params;
    p.arias_m_s = m.arias_m_s;
    p.d595_s = m.d595_s();
    p.tmid_s = m.t45_s;
    p.fc_hz = settings.fc_hz;
    const Modulation q = [&] {
        try {
            return modulation(p);
        } catch (const InputError& e) {  // the record's landmarks, not an option the user gave, fit no envelope
            throw InputError("record", "D5-95 = " + format_short(p.d595_s, 4) + " s after t_mid = " + format_short(p.tmid_s, 4) + " s",
                             "a record the model can fit: " + e.allowed());
        }
    }();
    fit_frequency(upcrossing_times(a_g, dt_s), m, p);
    // The filter may not run past a quarter of the record's sampling rate (Generator).
    p.f_mid_hz = std::min(p.f_mid_hz, 0.2 / dt_s);
    fit.record_extrema = count_positive_minima_negative_maxima(a_g, dt_s, m.t05_s, m.t95_s);
    // The drift must not carry the filter above the sampling limit while the motion lasts either
    // (the envelope's window, filter_window_fraction; not the record's quiet lead-in or tail).
    const auto [t_from, t_to] = q.carrying_window();
    const double f_end = p.f_mid_hz + p.f_slope_hz_s * (t_to - p.tmid_s);
    const double f_start = p.f_mid_hz - p.f_slope_hz_s * (p.tmid_s - t_from);
    const double f_cap = 0.24 / dt_s;
    if (f_end > f_cap) p.f_slope_hz_s = (f_cap - p.f_mid_hz) / (t_to - p.tmid_s);
    if (f_start > f_cap) p.f_slope_hz_s = (p.f_mid_hz - f_cap) / (p.tmid_s - t_from);
    // The damping: more bandwidth, more extrema between crossings. The count rises with
    // zeta_f (the same noise at every zeta: a smooth curve), so bisect for the record's count.
    // Every stage is causal: motions counted up to t95 need be made no further.
    const double duration = m.t95_s + 2.0 * dt_s;
    double lo = 0.02, hi = 0.95;
    const auto count_at = [&](double zeta) {
        ModelParameters trial = p;
        trial.zeta_f = zeta;
        return simulated_extrema(trial, dt_s, duration, m, settings);
    };
    const double target = static_cast<double>(fit.record_extrema);
    double c_lo = count_at(lo), c_hi = count_at(hi);
    if (target <= c_lo) {
        p.zeta_f = lo;
        fit.simulated_extrema = c_lo;
    } else if (target >= c_hi) {
        p.zeta_f = hi;
        fit.simulated_extrema = c_hi;
    } else {
        for (int i = 0; i < 8; ++i) {
            const double mid = 0.5 * (lo + hi), c = count_at(mid);
            if (c < target) {
                lo = mid;
                c_lo = c;
            } else {
                hi = mid;
                c_hi = c;
            }
        }
        // Linear between the last bracket's counts.
        p.zeta_f = lo + (hi - lo) * (target - c_lo) / (c_hi - c_lo);
        fit.simulated_extrema = count_at(p.zeta_f);
    }
    return fit;
}

}  // namespace rocksweep::synthetic
