#pragma once
/// Motions of the stochastic ground-motion model (ground_model.hpp), each defined by (seed,
/// index) alone: any rank, order or chunking draws the same bits. Everything that does not
/// depend on the noise (envelope, the filter's impulse responses and the variance that
/// normalises them) is computed once per parameter set; a motion costs one pass of its noise
/// through the filter and the high-pass oscillator. Definitions: docs/synthetic.md.
#include <cstdint>
#include <vector>

#include "rocksweep/motion/high_pass.hpp"
#include "rocksweep/records/record.hpp"
#include "rocksweep/synthetic/ground_model.hpp"

namespace rocksweep::synthetic {

/// Stages of the model that tests switch off to show each matters; every user path keeps all on.
struct Stages {
    bool drift = true;      ///< off: the filter keeps f_mid throughout (no omega')
    bool normalise = true;  ///< off: divided by the filter's standard deviation at t_mid, not at each t
    bool high_pass = true;  ///< off: no high-pass oscillator (residual velocity and displacement remain)
    /// off: the high-pass keeps the share of I_a it takes (RDK10 as published: 3 zeta_f f_c / f_mid
    /// of it, 42 % for Kocaeli's fit); on: the motion is scaled to give it back (docs/synthetic.md)
    bool keep_arias = true;
};

/// A filter impulse's response h(t - tau) is followed until exp(-zeta omega (t - tau)) falls
/// below this (1e-9 of its start): what is cut is below the double rounding of the sum.
inline constexpr double impulse_cut = 20.72326583694641;  // -ln(1e-9)

class Generator {
public:
    /// Motions of `params` (checked) sampled at `dt_s` over [0, duration_s]. Throws InputError
    /// ("dt") when the filter's highest frequency is not below a quarter of the sampling rate,
    /// and ("motion-duration", the option's name) when the motion would end before t_mid.
    Generator(const ModelParameters& params, double dt_s, double duration_s, Stages stages = {});

    const ModelParameters& parameters() const { return params_; }
    double dt_s() const { return dt_s_; }
    std::size_t samples() const { return envelope_.size(); }

    /// Ground acceleration of motion (seed, index) in units of standard gravity, one value per
    /// sample from t = 0 (where it is 0), into `ax_g` (resized).
    void generate(std::uint64_t seed, std::uint64_t index, std::vector<double>& ax_g) const;

    /// The same motion as a Record (horizontal only, path "synthetic:SEED:INDEX", units "g").
    Record record(std::uint64_t seed, std::uint64_t index) const;
    /// record(seed, index) without its samples (ax_g empty), made without making the motion.
    Record described(std::uint64_t seed, std::uint64_t index) const;

private:
    /// out_k += sum over i < k of weights_i h_i(t_k - t_i) (or its square, for the variance).
    template <bool Square>
    void superpose(const std::vector<double>& weights, std::vector<double>& out) const;
    /// E[sum over k of a_k^2] of the motions after the high-pass (a_k in g), exactly: each
    /// impulse's response, enveloped, through the oscillator, squared and summed.
    double expected_energy_after_high_pass() const;

    ModelParameters params_;
    double dt_s_;
    Stages stages_;
    std::vector<double> envelope_;  ///< q(t_k) / sigma_f(t_k) / g: noise sum -> acceleration [g]
    // Impulse i's response at lag j is Im(amplitude_i rotation_i^j), j = 1..length_i.
    std::vector<double> amplitude_, rotation_re_, rotation_im_;
    std::vector<std::uint32_t> length_;
    motion::HighPass high_pass_;  ///< the critically damped oscillator of corner f_c
};

}  // namespace rocksweep::synthetic
