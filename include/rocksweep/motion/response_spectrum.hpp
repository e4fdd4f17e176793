#pragma once
/// Spectral (pseudo-)acceleration of a sampled acceleration read linear between samples, as
/// the engine reads a record: Sa(T, zeta) = w^2 max_t |u(t)|, u the relative displacement of the
/// oscillator (T, zeta) on that base, from rest at t = 0 over the record's length. The samples
/// are stepped exactly (oscillator.hpp) and the peak is searched between samples too, from the
/// closed-form response within a step, so Sa is exact for the record as read.
#include <span>
#include <vector>

#include "rocksweep/motion/oscillator.hpp"

namespace rocksweep::motion {

/// Sa of `a` (samples at t = i dt, at least two) for oscillator `o`, in the unit of `a`.
/// Throws std::invalid_argument for T <= 0, zeta outside [0, 1) or dt <= 0.
double spectral_acceleration(std::span<const double> a, double dt_s, const Oscillator& o);

/// Sa at each of `periods_s`, all at damping `zeta`: a response spectrum.
std::vector<double> response_spectrum(std::span<const double> a, double dt_s, std::span<const double> periods_s,
                                      double zeta);

/// The periods the floor response spectra are stored at: 0.02 s to 5 s, 60 points evenly
/// spaced in log T (the range of buildings, display cases and of rocking blocks' own scales).
std::vector<double> floor_spectrum_periods();

}  // namespace rocksweep::motion
