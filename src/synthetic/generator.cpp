#include "rocksweep/synthetic/generator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/synthetic/normal_stream.hpp"

namespace rocksweep::synthetic {
namespace {

// The filter's line at the impulse time t [Hz]: omega(tau) / (2 pi) = f_mid + f' (tau - t_mid).
double filter_line_hz(const ModelParameters& p, double t_s, bool drift) {
    return drift ? p.f_mid_hz + p.f_slope_hz_s * (t_s - p.tmid_s) : p.f_mid_hz;
}

// The frequency the filter takes at t: the line, held within [the floor, `ceiling_hz`]. Below
// the ceiling wherever the envelope carries the motion (the constructor refuses it otherwise).
double filter_frequency_hz(const ModelParameters& p, double t_s, bool drift, double ceiling_hz) {
    return std::clamp(filter_line_hz(p, t_s, drift), filter_frequency_floor_hz, ceiling_hz);
}

// z <- z r: the impulse response one sample further (complex, the response its imaginary part).
inline void advance(double& zr, double& zi, double rr, double ri) {
    const double nr = zr * rr - zi * ri;
    zi = zr * ri + zi * rr;
    zr = nr;
}

// `p` once it and the sampling are checked: before any member is made of them.
const ModelParameters& checked(const ModelParameters& p, double dt_s, double duration_s) {
    check(p);
    require_closed("dt", dt_s, record_dt_min_s, 0.1, "a sampling interval in [1e-5, 0.1] s");
    require_closed("motion-duration", duration_s, p.tmid_s, 1e5,
                   "a motion length in [t_mid, 1e5] s (t_mid = " + format_short(p.tmid_s, 4) + " s)");
    return p;
}

}  // namespace

Generator::Generator(const ModelParameters& params, double dt_s, double duration_s, Stages stages)
    : params_(checked(params, dt_s, duration_s)), dt_s_(dt_s), stages_(stages), high_pass_(params.fc_hz, dt_s) {
    const Modulation q = modulation(params);
    const std::size_t n = static_cast<std::size_t>(std::floor(duration_s / dt_s + 0.5)) + 1;
    // The line is straight: its highest value over the envelope's window is at one end of it.
    const Modulation::Window window = q.carrying_window();
    const double t_from = std::min(window.from_s, (n - 1) * dt_s), t_to = std::min(window.to_s, (n - 1) * dt_s);
    const double f_top = std::max({filter_line_hz(params, t_from, stages.drift), filter_line_hz(params, t_to, stages.drift),
                                   filter_frequency_floor_hz});
    if (!(f_top * dt_s < 0.25))
        throw InputError("dt", format_short(dt_s),
                         "the filter's highest frequency where the envelope carries the motion (" + format_short(t_from, 4) + " to " +
                             format_short(t_to, 4) + " s), " + format_short(f_top, 4) +
                             " Hz, must stay below a quarter of the sampling rate: dt < " + format_short(0.25 / f_top, 4) + " s");
    // Before and after, where the envelope holds 1e-4 of I_a, the line is held just below the
    // limit: a line that stays below it throughout (all a version before the window accepted)
    // is never held, so its motions are bitwise what they were.
    const double ceiling = std::nextafter(0.25 / dt_s, 0.0);

    const double zeta = params.zeta_f, root = std::sqrt(1.0 - zeta * zeta);
    amplitude_.resize(n);
    rotation_re_.resize(n);
    rotation_im_.resize(n);
    length_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double omega = 2.0 * M_PI * filter_frequency_hz(params, i * dt_s, stages.drift, ceiling);
        // h(t - tau) = omega / sqrt(1 - zeta^2) exp(-zeta omega (t - tau)) sin(omega sqrt(1 - zeta^2) (t - tau))
        amplitude_[i] = omega / root;
        const double decay = std::exp(-zeta * omega * dt_s);
        rotation_re_[i] = decay * std::cos(omega * root * dt_s);
        rotation_im_[i] = decay * std::sin(omega * root * dt_s);
        const double reach = std::ceil(impulse_cut / (zeta * omega * dt_s));
        length_[i] = static_cast<std::uint32_t>(std::min<double>(reach, static_cast<double>(n - 1 - i)));
    }
    // sigma_f^2(t_k) = sum over the impulses before t_k of h(t_k - t_i)^2: the noise sum's variance.
    std::vector<double> variance(n, 0.0);
    superpose<true>(std::vector<double>(n, 1.0), variance);
    const std::size_t k_mid = std::min(n - 1, static_cast<std::size_t>(std::floor(params.tmid_s / dt_s + 0.5)));
    envelope_.assign(n, 0.0);
    for (std::size_t k = 1; k < n; ++k) {
        const double sigma = std::sqrt(stages.normalise ? variance[k] : variance[k_mid]);
        envelope_[k] = q(k * dt_s) / sigma / standard_gravity;
    }
    // The high-pass takes the filter's low-frequency plateau, a share of I_a that grows with
    // zeta_f f_c / f_mid; one gain for the whole motion gives it back, so that the motions' mean
    // I_a = pi / (2 g) sum a_k^2 dt (the fit's measure) is the parameter exactly, and keeps their
    // residual velocity and displacement the oscillator's (a gain per sample would not).
    if (stages.high_pass && stages.keep_arias) {
        const double target = params.arias_m_s * 2.0 / (M_PI * standard_gravity * dt_s);  // sum of a_k^2 [g^2]
        const double gain = std::sqrt(target / expected_energy_after_high_pass());
        for (double& e : envelope_) e *= gain;
    }
}

double Generator::expected_energy_after_high_pass() const {
    // Motion k is sum over i of G_ki u_i with u_i independent standard normals, G = HP diag(envelope) H:
    // E[sum_k a_k^2] = sum_i sum_k G_ki^2, column i being impulse i's response through both:
    // followed while the filter's response lasts, then the oscillator's ring-down to the
    // motion's end in closed form.
    const std::size_t n = envelope_.size();
    std::vector<double> column;
    double total = 0.0;
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const std::size_t m = std::min<std::size_t>(n - i, length_[i] + 1);
        column.assign(m, 0.0);  // column[0]: the impulse's own sample, where its response is 0
        double zr = amplitude_[i], zi = 0.0;
        for (std::size_t j = 1; j < m; ++j) {
            advance(zr, zi, rotation_re_[i], rotation_im_[i]);
            column[j] = envelope_[i + j] * zi;
        }
        total += high_pass_.apply_and_ring_down(column, n - i - m);
        for (const double c : column) total += c * c;
    }
    return total;
}

void Generator::generate(std::uint64_t seed, std::uint64_t index, std::vector<double>& ax_g) const {
    const std::size_t n = envelope_.size();
    ax_g.assign(n, 0.0);
    NormalStream noise(seed, index);
    std::vector<double> impulses(n);
    for (double& w : impulses) w = noise.next();
    superpose<false>(impulses, ax_g);
    for (std::size_t k = 0; k < n; ++k) ax_g[k] *= envelope_[k];
    if (stages_.high_pass) high_pass_.apply(ax_g);
}

template <bool Square>
void Generator::superpose(const std::vector<double>& weights, std::vector<double>& out) const {
    // Each sample's impulse w_i h(t - t_i) added to the samples after it, h at lag j being
    // Im(amplitude_i rotation_i^j). Four impulses advance together: their recurrences are
    // independent, so the processor overlaps them (one alone waits on its multiplications).
    const auto add = [&out](std::size_t k, double z) { out[k] += Square ? z * z : z; };
    constexpr std::size_t group = 4;  // 2 and 8 measured 1.5x slower (benchmarks/synthetic_cost)
    const std::size_t n = weights.size();
    std::size_t i = 0;
    for (; i + group <= n; i += group) {
        double zr[group], zi[group] = {}, rr[group], ri[group];
        std::size_t common = length_[i];
        for (std::size_t l = 0; l < group; ++l) {
            zr[l] = amplitude_[i + l] * weights[i + l];
            rr[l] = rotation_re_[i + l];
            ri[l] = rotation_im_[i + l];
            common = std::min<std::size_t>(common, length_[i + l]);
        }
        for (std::size_t j = 1; j <= common; ++j)
            for (std::size_t l = 0; l < group; ++l) {
                advance(zr[l], zi[l], rr[l], ri[l]);
                add(i + l + j, zi[l]);
            }
        for (std::size_t l = 0; l < group; ++l)
            for (std::size_t j = common + 1; j <= length_[i + l]; ++j) {
                advance(zr[l], zi[l], rr[l], ri[l]);
                add(i + l + j, zi[l]);
            }
    }
    for (; i < n; ++i) {
        double zr = amplitude_[i] * weights[i], zi = 0.0;
        for (std::size_t j = 1; j <= length_[i]; ++j) {
            advance(zr, zi, rotation_re_[i], rotation_im_[i]);
            add(i + j, zi);
        }
    }
}

Record Generator::described(std::uint64_t seed, std::uint64_t index) const {
    Record r;
    r.path = "synthetic:" + std::to_string(seed) + ":" + std::to_string(index);
    r.units = "g";
    r.dt_s = dt_s_;
    r.npts = samples();
    return r;
}

Record Generator::record(std::uint64_t seed, std::uint64_t index) const {
    Record r = described(seed, index);
    generate(seed, index, r.ax_g);
    return r;
}

}  // namespace rocksweep::synthetic
