#pragma once
/// The site-based stochastic ground-motion model of Rezaeian & Der Kiureghian (2008, 2010):
/// white noise through a filter whose frequency drifts linearly in time, normalised to unit
/// variance, modulated by a gamma-shaped envelope, then high-pass filtered. This header holds
/// its parameters and the envelope they fix; generator.hpp draws motions from it and fit.hpp
/// fits it to a record. Definitions and sources: docs/synthetic.md.
#include <string>

namespace rocksweep::synthetic {

/// The model's seven parameters. Frequencies in Hz (omega = 2 pi f), as the papers tabulate them.
struct ModelParameters {
    double arias_m_s = 0.0;        ///< I_a, expected Arias intensity, pi/(2 g) * integral of a^2 dt [m/s]
    double d595_s = 0.0;           ///< D5-95: time from 5 % to 95 % of I_a [s]
    double tmid_s = 0.0;           ///< t_mid: time at which 45 % of I_a has arrived [s]
    double f_mid_hz = 0.0;         ///< the filter's frequency at t_mid, omega_mid / (2 pi)
    double f_slope_hz_s = 0.0;     ///< its drift, omega' / (2 pi) [Hz/s]
    double zeta_f = 0.0;           ///< the filter's damping ratio, in (0, 1)
    double fc_hz = 0.2;            ///< corner of the critically damped high-pass oscillator
};

/// The filter's frequency never drops below this [Hz] however far a negative drift runs: the
/// papers' fitted lines stay positive over the strong phase, a long tail need not (our choice).
inline constexpr double filter_frequency_floor_hz = 0.1;

/// The filter's line must stay below the sampling limit (a quarter of the sampling rate) where
/// the envelope carries the motion, from this fraction of I_a to 1 minus it; before and after,
/// it is held just below the limit (our choice: a record's quiet lead-in, where the line
/// extrapolated back would pass the limit, must not bend the line fitted to its strong phase).
inline constexpr double filter_window_fraction = 1e-4;

/// Throws InputError naming the parameter (field names as the `synth` command's options:
/// "arias", "d595", "tmid", "f-mid", "f-slope", "zeta", "fc") for a value outside its range.
void check(const ModelParameters& p);

/// The modulating function q(t) = alpha1 t^(alpha2 - 1) exp(-alpha3 t) [m/s^2], t >= 0: a gamma
/// density in shape, so that its cumulative Arias intensity is a regularised incomplete gamma
/// function P(2 alpha2 - 1, 2 alpha3 t) times I_a.
struct Modulation {
    /// ln alpha1 (alpha1 in m/s^(alpha2 + 1)): a narrow envelope late in its record (t_mid = 65 s,
    /// D5-95 = 6 s) has alpha1 ~ e^-2000, far below the smallest double
    double log_alpha1 = 0.0;
    double alpha2 = 0.0;  ///< > 1/2
    double alpha3 = 0.0;  ///< [1/s]
    double operator()(double t_s) const;
    /// Fraction of I_a arrived by t: P(2 alpha2 - 1, 2 alpha3 t).
    double arias_fraction(double t_s) const;
    /// The time by which `fraction` (in (0, 1)) of I_a has arrived.
    double arias_time(double fraction) const;
    /// Where the envelope carries the motion: from filter_window_fraction of I_a to 1 minus it [s].
    struct Window {
        double from_s = 0.0, to_s = 0.0;
    };
    Window carrying_window() const {
        return {arias_time(filter_window_fraction), arias_time(1.0 - filter_window_fraction)};
    }
};

/// alpha1..3 from (I_a, D5-95, t_mid): the shape k = 2 alpha2 - 1 from D5-95 / t_mid, which
/// depends on k alone, then alpha3 from t_mid and alpha1 from I_a. Throws InputError("d595",
/// ...) when D5-95 / t_mid is outside what a gamma envelope can give (0.033 to 85).
Modulation modulation(const ModelParameters& p);

/// Length of a generated motion [s]: the envelope's 99.99 % Arias time plus 3 / f_c, which the
/// high-pass oscillator needs to come to rest ((1 + 6 pi) e^(-6 pi) = 1.3e-7 of its motion).
/// Shorter, the weak tail's own low-frequency motion leaves a residual displacement of ~1 %
/// of the peak (0.999 and 2 / f_c: 1.8 % at worst over 200 motions; this: 0.11 %).
double default_duration_s(const ModelParameters& p);

/// "I_a = 0.12 m/s, D5-95 = ..." on one line, for printing.
std::string describe(const ModelParameters& p);

}  // namespace rocksweep::synthetic
