// Research prototype (benchmarks/RECORD_STEPS.md, issue 9 "Fast, and measured against what people
// use"): RK4 steps that cross a record's sample times. Not the engine: a standalone scalar
// integrator of the same runs as benchmarks/records_peers (same records, block, scales,
// anchorages, settling threshold 1e-3 p alpha, events and energy decision), to measure how many
// samples one step may span before the error or an outcome moves, and at what speed against the
// paper's method (the engine's Method::paper, called through integrate_cells as records_peers
// does) measured in the same process.
//
// Methods, each with steps of k record samples (a step ends at the k-th sample after its start,
// or at the record's end; events cut it as in the engine):
//   plain  RK4 on (theta, omega), the ground linear between samples: a step that crosses a
//          sample sees a kink in the forcing (local error O(J h^3) per kink, J the slope jump).
//   trans  RK4 on (theta, w), w = omega - v(t) G(theta), v(t) = integral of u from the step's
//          start (piecewise quadratic, C1, exact from the samples): theta' = w + v G,
//          w' = F - v G' (w + v G). The forcing is v, one order smoother (O(J h^4) per kink).
//          v = 0 at the step's start, so w = omega there: impacts and events act on omega as
//          usual; at the step's end omega = w + v(t1) G(theta1).
//   transA as trans, with the step length chosen per step (adaptive k): the largest k <= kmax
//          whose kinks inside the step satisfy sum |J_i| (k dt)^4 <= tol (see --adapt-tol).
//
//   record_steps --ref DIR [--suite S] [--out DIR] [--rounds R] [--min-seconds T]
// DIR holds records_peers_reference{,_check}{,_outcomes}.csv (records_peers histories --out DIR).
// Prints the table (steps, runs/s per core, ratio to the paper's method and to events48,
// max theta error on the non-chaotic runs, max-rotation error, outcomes != reference).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/block.hpp"
#include "rocksweep/physics/energy.hpp"
#include "rocksweep/physics/fastmath.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/physics/model.hpp"
#include "rocksweep/records/record.hpp"
#include "rocksweep/records/record_suite.hpp"

using namespace rocksweep;

namespace {

// ---------------------------------------------------------------- runs (as records_peers.cpp)
struct Run {
    std::string name, record, anchorage;
    double scale = 1.0;
    Pulse pulse;
    Anchorage anch;
    CellModel model, model4;  ///< settling threshold 1e-3 p alpha (sweep), 1e-4 (simulate)
};

Block smatteo() { return rectangular_block(0.30, 1.36, 3361.0, 9.81); }

/// scan non-empty: these scales for every record instead of the suite's column.
std::vector<Run> read_runs(const std::string& suite_path, double threshold, const std::vector<double>& scan = {}) {
    const RecordSuite suite = read_record_suite(suite_path);
    std::size_t col = suite.metadata_columns.size();
    for (std::size_t i = 0; i < suite.metadata_columns.size(); ++i)
        if (suite.metadata_columns[i] == "scales") col = i;
    if (col == suite.metadata_columns.size()) throw std::runtime_error(suite_path + ": no column 'scales'");
    const Block block = smatteo();
    const double strength = 0.4 * block.mass_kg * block.gravity;
    std::vector<Run> runs;
    for (const SuiteRecord& sr : suite.records) {
        std::vector<double> scales = scan;
        if (scales.empty()) {
            std::istringstream in(sr.metadata[col]);
            for (double x; in >> x;) scales.push_back(x);
        }
        for (double scale : scales) {
            RecordSource src = sr.source;
            src.scale = scale;
            const Record rec = read_record(src);
            for (const char* anch : {"free", "constant"}) {
                Run r;
                r.record = sr.name;
                r.anchorage = anch;
                r.scale = scale;
                char buf[64];
                std::snprintf(buf, sizeof buf, "_x%g_", scale);
                r.name = sr.name + buf + anch;
                r.pulse = to_pulse(rec, block.gravity);
                r.anch = std::string(anch) == "free" ? free_anchorage() : constant_anchorage(block, strength, block.alpha_rad);
                r.model = make_cell_model(block, r.anch, r.pulse, Equations::nonlinear, threshold);
                r.model4 = make_cell_model(block, r.anch, r.pulse, Equations::nonlinear, 1e-4);
                runs.push_back(std::move(r));
            }
        }
    }
    return runs;
}

// ---------------------------------------------------------------- the prototype integrator
enum class Scheme { plain, trans, trans_adaptive, moment, rkn, rkn_moment, rkn_moment2 };
const char* name_of(Scheme s) {
    switch (s) {
        case Scheme::plain: return "plain";
        case Scheme::trans: return "trans";
        case Scheme::moment: return "moment";
        case Scheme::rkn: return "rkn";
        case Scheme::rkn_moment: return "rkn-moment";
        case Scheme::rkn_moment2: return "rkn-moment2";
        default: return "transA";
    }
}

/// The ground of one run: u(t) = scale (a_i + x (a_{i+1} - a_i)), as the engine's lane(); its
/// integral V(t) from 0, exact (piecewise quadratic); the slope jumps J_i at the samples.
struct Ground {
    const double* a = nullptr;
    int n = 0;
    double dt = 0.0, scale = 1.0, T = 0.0;
    std::vector<double> V, J;

    explicit Ground(const Pulse& p) {
        a = p.record->data();
        n = static_cast<int>(p.record->size());
        dt = p.record_dt_s;
        scale = p.record_scale;
        T = static_cast<double>(n - 1) * dt;
        V.assign(n, 0.0);
        for (int i = 0; i + 1 < n; ++i) V[i + 1] = V[i] + dt * scale * 0.5 * (a[i] + a[i + 1]);
        J.assign(n, 0.0);
        for (int i = 1; i + 1 < n; ++i) J[i] = std::abs(scale * (a[i + 1] - 2 * a[i] + a[i - 1]) / dt);
    }
    int seg(double t, double& x) const {
        const double xx = t / dt;
        const int i = std::min(std::max(static_cast<int>(xx), 0), n - 2);
        x = xx - i;
        return i;
    }
    double u(double t) const {
        if (t > T) return 0.0;
        double x;
        const int i = seg(t, x);
        return scale * (a[i] + x * (a[i + 1] - a[i]));
    }
    double v(double t) const {
        if (!(t < T)) return V[n - 1];
        double x;
        const int i = seg(t, x);
        return V[i] + dt * scale * x * (a[i] + 0.5 * x * (a[i + 1] - a[i]));
    }
};

struct Outcome3 {
    std::string outcome;
    double t_ot = NAN, max_rot = 0.0;
    int impacts = 0;
    long steps = 0;
    long search = 0, post = 0;  ///< of steps: re-runs of event searches; steps after the record
    long evals = 0;             ///< right-hand side evaluations (each one sincos, + a sine anchored)
};

/// One cell (one run) with steps of k samples. Hist: theta at every record sample (re-run steps
/// from the accepted step's start to each sample inside it, so the dense values carry the
/// method's own error), and the cubic Hermite values beside them.
class Proto {
public:
    /// spp > 0: steps of 2 pi / (omega_max spp) during the record too, across samples (k unused).
    Proto(const CellModel& m, const Ground& g, Scheme scheme, int k, double spp, double adapt_tol, bool newton,
          std::vector<double>* hist, std::vector<double>* hist_hermite)
        : m_(m), g_(g), scheme_(scheme), k_(k), adapt_tol_(adapt_tol), newton_(newton), hist_(hist), hist_h_(hist_hermite) {
        h_free_ = 2.0 * M_PI / (m_.omega_max() * 48.0);  // after the record: the sweep default's step
        if (spp > 0.0) h_fixed_ = 2.0 * M_PI / (m_.omega_max() * spp);
        anchored_ = m_.anchorage != AnchorageKind::free;
        if (hist_) {
            hist_->assign(g_.n, 0.0);
            hist_h_->assign(g_.n, 0.0);
        }
    }

    Outcome3 run() {
        while (!done_) {
            if (side_ == 0) {
                leave_rest();
                continue;
            }
            if (r_.steps >= 100'000) {  // a run of these records takes < 3 000; the engine's cap is 2e6
                finish("not_converged");
                break;
            }
            step();
        }
        if (hist_) {
            hist_->resize(std::min<std::size_t>(hist_->size(), n_hist_));
            hist_h_->resize(hist_->size());
        }
        return r_;
    }

private:
    const CellModel& m_;
    const Ground& g_;
    Scheme scheme_;
    int k_;
    double adapt_tol_;
    bool newton_;
    std::vector<double>*hist_, *hist_h_;
    std::size_t n_hist_ = SIZE_MAX;
    double h_free_, h_fixed_ = 0.0;
    bool anchored_;
    bool broken_[2] = {false, false};
    double t_ = 0.0, th_ = 0.0, om_ = 0.0;
    int side_ = 0, impacts_total_ = 0;
    bool done_ = false;
    double max_phi_ = 0.0;
    mutable Outcome3 r_;

    bool intact(int s) const { return anchored_ && !broken_[s > 0 ? 0 : 1]; }
    double kappa() const { return intact(side_) ? m_.kappa_max : 0.0; }
    bool in_pulse() const { return t_ < g_.T; }

    // theta'' pieces at theta on the current side: F = -p2 sin(s a - th) - s kappa sin(s th / 2),
    // G = -p2 cos(s a - th), G' = dG/dtheta = -p2 sin(s a - th).
    struct Trig {
        double Gp, G, spring;
    };
    Trig trig(double th, double s, double kap) const {
        ++r_.evals;
        double sa, ca;
        fastmath::sincos(s * m_.alpha - th, sa, ca);
        Trig r{-m_.p2 * sa, -m_.p2 * ca, 0.0};
        if (kap != 0.0) r.spring = s * kap * fastmath::sin(0.5 * s * th);
        return r;
    }

    /// One RK4 step of length d from (t0, y0, v0): (y1, v1). The ground is off from the record's
    /// end (t0 >= T: free rocking).
    void rk4(double t0, double y0, double v0, double d, double& y1, double& v1) const {
        const double s = side_, kap = kappa();
        const bool ground = t0 < g_.T;
        auto acc = [&](double u, double y) {
            const Trig q = trig(y, s, kap);
            return q.Gp + u * q.G - q.spring;
        };
        if (scheme_ == Scheme::rkn || scheme_ == Scheme::rkn_moment || scheme_ == Scheme::rkn_moment2) {
            // theta'' = f(t, theta) does not depend on theta': the 3-stage order-4 Runge-Kutta-
            // Nystrom method (Hairer, Norsett, Wanner I, II.14), nodes 0, 1/2, 1 as RK4's, one
            // evaluation fewer.
            double u0 = 0.0, um = 0.0, u1 = 0.0;
            if (ground && scheme_ != Scheme::rkn) moment_nodes(t0, d, u0, um, u1);
            else if (ground) u0 = g_.u(t0), um = g_.u(t0 + 0.5 * d), u1 = g_.u(t0 + d);
            const Trig q0 = trig(y0, s, kap);
            const double k1 = q0.Gp + u0 * q0.G - q0.spring;
            const double k2 = acc(um, y0 + 0.5 * d * v0 + 0.125 * d * d * k1);
            const double k3 = acc(u1, y0 + d * v0 + 0.5 * d * d * k2);
            y1 = y0 + d * v0 + d * d / 6.0 * (k1 + 2.0 * k2);
            v1 = v0 + d / 6.0 * (k1 + 4.0 * k2 + k3);
            if (ground && scheme_ == Scheme::rkn_moment2) {
                // The terms second order in the ground, G'(theta0) G(theta0) times the iterated
                // integrals of u, exact from the record, in place of what the stages make of them.
                double Ew, Et;
                iterated(t0, d, Ew, Et);
                const double gg = q0.Gp * q0.G;
                v1 += gg * (Ew - d * d * d * um * (u0 + u1) / 12.0);
                y1 += gg * (Et - d * d * d * d * um * u0 / 24.0);
            }
            return;
        }
        if (scheme_ == Scheme::plain || scheme_ == Scheme::moment || !ground) {
            double u0 = 0.0, um = 0.0, u1 = 0.0;
            if (ground && scheme_ == Scheme::moment) moment_nodes(t0, d, u0, um, u1);
            else if (ground) u0 = g_.u(t0), um = g_.u(t0 + 0.5 * d), u1 = g_.u(t0 + d);
            const double k1y = v0, k1v = acc(u0, y0);
            const double k2y = v0 + 0.5 * d * k1v, k2v = acc(um, y0 + 0.5 * d * k1y);
            const double k3y = v0 + 0.5 * d * k2v, k3v = acc(um, y0 + 0.5 * d * k2y);
            const double k4y = v0 + d * k3v, k4v = acc(u1, y0 + d * k3y);
            y1 = y0 + d / 6.0 * (k1y + 2 * k2y + 2 * k3y + k4y);
            v1 = v0 + d / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
            return;
        }
        // transformed: w = omega - v G, v from the step's start
        const double V0 = g_.v(t0);
        auto f = [&](double t, double y, double w, double& dy, double& dw) {
            const Trig q = trig(y, s, kap);
            const double v = g_.v(t) - V0;
            const double om = w + v * q.G;
            dy = om;
            dw = q.Gp - q.spring - v * q.Gp * om;
        };
        double k1y, k1w, k2y, k2w, k3y, k3w, k4y, k4w;
        f(t0, y0, v0, k1y, k1w);
        f(t0 + 0.5 * d, y0 + 0.5 * d * k1y, v0 + 0.5 * d * k1w, k2y, k2w);
        f(t0 + 0.5 * d, y0 + 0.5 * d * k2y, v0 + 0.5 * d * k2w, k3y, k3w);
        f(t0 + d, y0 + d * k3y, v0 + d * k3w, k4y, k4w);
        y1 = y0 + d / 6.0 * (k1y + 2 * k2y + 2 * k3y + k4y);
        const double w1 = v0 + d / 6.0 * (k1w + 2 * k2w + 2 * k3w + k4w);
        v1 = w1 + (g_.v(t0 + d) - V0) * trig(y1, s, kap).G;
    }

    /// moment: the ground values at RK4's nodes (t0, middle, end) for which Simpson's rule, the
    /// quadrature inside RK4, gives the exact integrals of u, u s and u s^2 over the step
    /// (s = (t - t0) / d), from the piecewise-linear record (Simpson on each linear piece is exact).
    void moment_nodes(double t0, double d, double& u0, double& um, double& u1) const {
        const double t1 = t0 + d;
        double m0 = 0.0, m1 = 0.0, m2 = 0.0;
        double x;
        int i = g_.seg(t0, x);
        for (double ta = t0; ta < t1; ++i) {
            const double tb = std::min(t1, static_cast<double>(i + 1) * g_.dt);
            if (!(tb > ta)) continue;
            const double sa = (ta - t0) / d, sb = (tb - t0) / d, sm = 0.5 * (sa + sb), w = (sb - sa) / 6.0;
            const double ua = g_.u(ta), ub = g_.u(tb), um_ = 0.5 * (ua + ub);
            m0 += w * (ua + 4 * um_ + ub);
            m1 += w * (sa * ua + 4 * sm * um_ + sb * ub);
            m2 += w * (sa * sa * ua + 4 * sm * sm * um_ + sb * sb * ub);
            ta = tb;
        }
        const double B = 4.0 * (m1 - m2), C = 2.0 * m2 - m1, A = m0 - B - C;
        u0 = 6.0 * A, um = 1.5 * B, u1 = 6.0 * C;
    }

    /// E_w = int_0^h u(s) U2(s) ds and E_t = int_0^h (h - s) u(s) U2(s) ds, U2(s) =
    /// int_0^s (s - r) u(r) dr, on the piecewise-linear record over [t0, t0 + h]: 3-point
    /// Gauss-Legendre on each linear piece (the integrands are polynomials of degree <= 5 there).
    void iterated(double t0, double h, double& Ew, double& Et) const {
        static const double gx[3] = {0.5 - 0.5 * 0.7745966692414834, 0.5, 0.5 + 0.5 * 0.7745966692414834};
        static const double gw[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
        const double t1 = t0 + h;
        double U1 = 0.0, U2 = 0.0;  // at the piece's start
        Ew = Et = 0.0;
        double x;
        int i = g_.seg(t0, x);
        for (double ta = t0; ta < t1; ++i) {
            const double tb = std::min(t1, static_cast<double>(i + 1) * g_.dt);
            if (!(tb > ta)) continue;
            const double L = tb - ta, ua = g_.u(ta), beta = (g_.u(tb) - ua) / L;
            const double sa = ta - t0;
            for (int j = 0; j < 3; ++j) {
                const double tau = gx[j] * L, sj = sa + tau;
                const double uj = ua + beta * tau;
                const double U2j = U2 + U1 * tau + ua * tau * tau / 2 + beta * tau * tau * tau / 6;
                Ew += gw[j] * L * uj * U2j;
                Et += gw[j] * L * (h - sj) * uj * U2j;
            }
            U2 += U1 * L + ua * L * L / 2 + beta * L * L * L / 6;
            U1 += ua * L + beta * L * L / 2;
            ta = tb;
        }
    }

    // ---- events, as src/physics/rocking_events.hpp
    enum Ev { none, overturn, fracture, impact, turn };
    double gfun(Ev e, double d, double y, double v, double y0, double v0) const {
        const double s = side_;
        switch (e) {
            case overturn: return M_PI / 2 - s * y;
            case fracture: return m_.break_max - s * y;
            case impact:
                if (y0 != 0.0) return s * y;
                return s * v0 > 0.0 ? s * y / d : s * y / (d * d);
            case turn: return s * v;
            default: return 1.0;
        }
    }
    Ev earliest(double d, double y, double v, double y0, double v0, double& gmin) const {
        Ev w = none;
        gmin = INFINITY;
        for (Ev e : {overturn, fracture, impact}) {
            if (e == fracture && !intact(side_)) continue;
            const double ge = gfun(e, d, y, v, y0, v0);
            if (ge < gmin) gmin = ge, w = e;
        }
        return w;
    }
    static void hermite(double d1, double y0, double v0, double y1, double v1, double d, double& y, double& v) {
        const double u = d / d1, w = 1.0 - u;
        y = (1 + 2 * u) * w * w * y0 + u * w * w * d1 * v0 + u * u * (3 - 2 * u) * y1 - u * u * w * d1 * v1;
        v = 6 * u * w * (y1 - y0) / d1 + w * (1 - 3 * u) * v0 + u * (3 * u - 2) * v1;
    }
    static double hermite_peak(double dt, double y0, double v0, double y1, double v1) {
        const double tau = v0 / (v0 - v1);
        double y, v;
        hermite(dt, y0, v0, y1, v1, tau * dt, y, v);
        return y;
    }
    bool grazes(double dt, double y0, double v0, double y1, double v1) const {
        if (!intact(side_)) return false;
        const double s = side_;
        if (!(s * v0 > 0.0 && s * v1 < 0.0)) return false;
        const double peak = s * hermite_peak(dt, y0, v0, y1, v1);
        const double ends = std::max(s * y0, s * y1);
        const double brk = m_.break_max;
        return peak >= brk - (1e-4 * brk + 0.1 * (peak - ends));
    }

    /// The root of target's function (none: the earliest) in (0, hi], g(hi) <= 0: a first trial
    /// at the root on the cubic Hermite interpolant, probes across it, then Illinois on re-run
    /// RK4 steps from the step's start (the engine's event stepper, condensed). Returns hi.
    double locate(Ev target, double hi, double ghi, double& yhi, double& vhi) {
        const double y0 = th_, v0 = om_;
        const double H = hi;
        const double Y1 = yhi, V1 = vhi;
        auto g_at = [&](double d, double y, double v) {
            double g;
            if (target == none) earliest(d, y, v, y0, v0, g);
            else g = gfun(target, d, y, v, y0, v0);
            return g;
        };
        auto g_interp = [&](double d) {
            double y, v;
            hermite(H, y0, v0, Y1, V1, d, y, v);
            return g_at(d, y, v);
        };
        double lo = 0.0, glo = NAN;
        // root of the interpolant
        double x = NAN, slope = NAN;
        {
            double a = 0.0, b = H, ga = NAN, gb = ghi;
            int moved = 0;
            for (int i = 0; i < 40 && b - a > 1e-7 * H; ++i) {
                double xm = 0.5 * (a + b);
                if (!std::isnan(ga) && i % 4 != 3) {
                    const double xs = a + (b - a) * ga / (ga - gb);
                    if (xs > a && xs < b) xm = xs;
                }
                const double gx = g_interp(xm);
                if (!std::isfinite(gx)) break;
                if (gx > 0.0) {
                    if (moved == 1) gb *= 0.5;
                    a = xm, ga = gx, moved = 1;
                } else {
                    if (moved == -1) ga *= 0.5;
                    b = xm, gb = gx, moved = -1;
                }
            }
            const double e = 1e-7 * H;
            if (b - e > 0.0 && b + e < H) {
                x = b;
                slope = (g_interp(b + e) - g_interp(b - e)) / (2 * e);
                if (!(std::isfinite(slope) && slope != 0.0)) x = NAN;
            }
        }
        int probes = std::isnan(x) ? 0 : 1;
        bool plo = false, phi = false;
        double stride = 0.0;
        int last = 0, it = 0;
        double width = hi;
        double trial = std::isnan(x) ? 0.5 * hi : x;
        for (;;) {
            double y, v;
            rk4(t_, y0, v0, trial, y, v);
            ++r_.steps;
            ++r_.search;
            const double g = g_at(trial, y, v);
            ++it;
            if (g > 0.0) {
                if (last == 1) ghi *= 0.5;
                lo = trial, glo = g, last = 1;
            } else {
                if (last == -1) glo *= 0.5;
                hi = trial, ghi = g, yhi = y, vhi = v, last = -1;
            }
            const bool probe = probes > 0;
            if (probe) {
                last = 0;
                (g > 0.0 ? plo : phi) = true;
                if (probes == 1) stride = std::max(1.5 * std::abs(g / slope), 1e-9 * hi);
            }
            const double tol = std::max(4.0 * DBL_EPSILON * (std::abs(t_) + hi), 1e-12 * hi);
            if (hi - lo <= tol || ghi == 0.0 || it >= 100) return hi;
            if (probe && !(plo && phi) && probes < 4 && std::isfinite(stride)) {
                const double xn = trial + (g > 0.0 ? stride : -stride);
                stride *= 8.0;
                if (xn > lo && xn < hi) {
                    ++probes;
                    trial = xn;
                    continue;
                }
            }
            probes = 0;
            double xn = 0.5 * (lo + hi);
            if (!std::isnan(glo) && (it % 4 != 0 || hi - lo < 0.5 * width)) {
                const double xs = lo + (hi - lo) * glo / (glo - ghi);
                if (xs > lo && xs < hi) xn = xs;
            }
            if (it % 4 == 0) width = hi - lo;
            trial = std::clamp(xn, lo + 0.5 * tol, hi - 0.5 * tol);
        }
    }

    /// Event location in one re-run step (newton): the root of the event's theta level on the
    /// cubic Hermite interpolant (O(h^4) off), one RK4 step there, then a second-order Taylor
    /// step in time from that state onto the level (error O(eps^3) in time, O(eps^2) in omega,
    /// eps the interpolant's miss). Falls back to the full search (false) when the correction
    /// is not small or another event would come first.
    bool locate_newton(double H, double Y1, double V1, double& d_out, double& y_out, double& v_out, Ev& which) {
        const double y0 = th_, v0 = om_, s = side_;
        double gdummy;
        const Ev e = earliest(H, Y1, V1, y0, v0, gdummy);
        double level;
        if (e == impact) level = 0.0;
        else if (e == overturn) level = s * M_PI / 2;
        else if (e == fracture) level = s * m_.break_max;
        else return false;
        // root of theta - level on the interpolant, by Illinois (no RK4 step)
        auto f = [&](double d) {  // the event's function (trivial root at 0 divided out)
            double y, v;
            hermite(H, y0, v0, Y1, V1, d, y, v);
            return gfun(e, d, y, v, y0, v0);
        };
        double a = 0.0, b = H, fa = (e == impact && y0 == 0.0) ? NAN : f(0.0), fb = f(H);
        if (!(fb <= 0.0)) return false;
        int moved = 0;
        for (int i = 0; i < 60 && b - a > 1e-9 * H; ++i) {
            double xm = 0.5 * (a + b);
            if (!std::isnan(fa) && i % 4 != 3) {
                const double xs = a + (b - a) * fa / (fa - fb);
                if (xs > a && xs < b) xm = xs;
            }
            const double fx = f(xm);
            if (fx > 0.0) {
                if (moved == 1) fb *= 0.5;
                a = xm, fa = fx, moved = 1;
            } else {
                if (moved == -1) fa *= 0.5;
                b = xm, fb = fx, moved = -1;
            }
            if (std::isnan(fa) && i > 30) break;
        }
        const double x = b;
        double y, v;
        rk4(t_, y0, v0, x, y, v);
        ++r_.steps;
        ++r_.search;
        const double t = t_ + x;
        const double u = t <= g_.T ? g_.u(t) : 0.0;
        const Trig q = trig(y, s, kappa());
        const double acc = q.Gp + u * q.G - q.spring;
        const double eps = y - level;
        if (!(std::abs(v) > 0.0)) return false;
        const double delta = eps / v + acc * eps * eps / (2.0 * v * v * v);  // root = x - delta
        const double d = x - delta;
        if (!(d > 0.0 && d <= H) || std::abs(delta) > 0.05 * H) return false;
        // A step from theta = 0 (impact, uplift) whose root lies near its start: the trivial root
        // there may be double or triple (uplift at the threshold), where the interpolant's
        // function is not the RK4 one's; the full search decides on RK4 states.
        if (y0 == 0.0 && d < 1e-3 * H) return false;
        const double vr = v - acc * delta;
        // no other event before: the other functions at the root state stay positive
        for (Ev o : {overturn, fracture, impact}) {
            if (o == e || (o == fracture && !intact(side_))) continue;
            if (gfun(o, d, level, vr, y0, v0) <= 0.0) return false;
        }
        d_out = d, y_out = level, v_out = vr, which = e;
        return true;
    }

    /// The step's planned end: k samples on (adaptive: fewer where the ground kinks hard), the
    /// record's end; after the record, the sweep default's step.
    double plan_end() const {
        if (!in_pulse()) return t_ + h_free_;
        if (h_fixed_ > 0.0) return std::min(t_ + h_fixed_, g_.T);
        const double dt = g_.dt;
        double j = std::floor(t_ / dt) + 1.0;  // first sample after t (strictly)
        if (!(j * dt > t_)) j += 1.0;
        int k = k_;
        if (scheme_ == Scheme::trans_adaptive) {
            // largest k <= kmax with sum over the kinks inside the step of J_i h^4 <= tol
            const int j0 = static_cast<int>(j);
            double sumJ = 0.0;
            int best = 1;
            for (int kk = 1; kk <= k_; ++kk) {
                const double h = (j0 + kk - 1) * dt - t_;
                if (kk > 1) {
                    const int i = j0 + kk - 2;  // the kink the step of kk samples newly crosses
                    if (i >= g_.n) break;
                    sumJ += g_.J[i];
                }
                if (sumJ * h * h * h * h <= adapt_tol_) best = kk;
                else break;
            }
            k = best;
        }
        return std::min((j + k - 1) * dt, g_.T);
    }

    void leave_rest() {
        if (!in_pulse()) return finish("safe");
        const CellModel& m = m_;
        double tu;
        if (m.uplifts(t_)) tu = t_;
        else
            tu = m.pulse.first_uplift(t_, g_.T, [&m](double x) { return m.uplifts(x); }, [] { return true; });
        if (!std::isfinite(tu)) {
            t_ = g_.T;
            return finish("safe");
        }
        t_ = tu;
        th_ = om_ = 0.0;
        side_ = m.pulse.ax(tu) > 0.0 ? -1 : 1;
    }

    void finish(const char* o) {
        r_.outcome = o;
        r_.max_rot = max_phi_ / m_.alpha;
        done_ = true;
    }

    void step() {
        const double t0 = t_, y0 = th_, v0 = om_;
        const double t_end = plan_end();
        double d = t_end - t0;
        double y1, v1;
        rk4(t0, y0, v0, d, y1, v1);
        ++r_.steps;
        if (!in_pulse()) ++r_.post;
        double g;
        Ev e = earliest(d, y1, v1, y0, v0, g);
        bool exact_end = true;
        if (g > 0.0) {
            e = none;
            if (grazes(d, y0, v0, y1, v1)) {
                double yt = y1, vt = v1;
                const double dturn = locate(turn, d, gfun(turn, d, y1, v1, y0, v0), yt, vt);
                const double gf = gfun(fracture, dturn, yt, vt, y0, v0);
                if (gf <= 0.0) {
                    d = locate(fracture, dturn, gf, yt, vt);
                    e = fracture;
                } else {
                    d = dturn;
                }
                y1 = yt, v1 = vt;
                exact_end = false;
            }
        } else {
            double dn, yn, vn;
            Ev en;
            if (newton_ && locate_newton(d, y1, v1, dn, yn, vn, en)) {
                d = dn, y1 = yn, v1 = vn, e = en;
            } else {
                d = locate(none, d, g, y1, v1);
                double gh;
                e = earliest(d, y1, v1, y0, v0, gh);
            }
            exact_end = false;
        }
        const double t1 = exact_end ? t_end : t0 + d;
        accept(t0, y0, v0, t1, y1, v1, e);
    }

    void accept(double t0, double y0, double v0, double t1, double y1, double v1, Ev e) {
        const double s = side_;
        if (r_.steps > 99'990 && std::getenv("RECORD_STEPS_TRACE"))
            std::fprintf(stderr, "trace t0 %.17g t1 %.17g side %d y0 %g v0 %g y1 %g v1 %g ev %d\n", t0, t1, side_, y0, v0, y1, v1, static_cast<int>(e));
        if (s * v0 > 0.0 && s * v1 < 0.0) max_phi_ = std::max(max_phi_, s * hermite_peak(t1 - t0, y0, v0, y1, v1));
        max_phi_ = std::max(max_phi_, std::min(s * y1, M_PI / 2));
        if (hist_) record(t0, y0, v0, t1, y1, v1);
        t_ = t1, th_ = y1, om_ = v1;
        switch (e) {
            case overturn: {
                r_.t_ot = t_;
                max_phi_ = M_PI / 2;
                if (hist_) n_hist_ = static_cast<std::size_t>(std::floor(t_ / g_.dt)) + 1;
                return finish(impacts_total_ > 0 ? "overturned_with_impact" : "overturned_without_impact");
            }
            case fracture: broken_[side_ > 0 ? 0 : 1] = true; return;
            case impact: return do_impact();
            default: return;
        }
    }

    void do_impact() {
        const double approach = std::abs(om_);
        ++impacts_total_;
        th_ = 0.0;
        if (approach < m_.v_threshold) {
            om_ = 0.0;
            side_ = 0;
            return;
        }
        ++r_.impacts;
        om_ *= m_.e;
        side_ = -side_;
        if (!in_pulse()) {
            const FreeFate f = free_fate(m_, side_, std::abs(om_), !broken_[0], !broken_[1]);
            if (f.decided) {
                max_phi_ = std::max(max_phi_, f.max_phi);
                r_.impacts += f.impacts;
                finish("safe");
            }
        }
    }

    /// theta at the record samples in (t0, t1]: re-run steps from the step's start (not
    /// counted), and the cubic Hermite interpolant.
    void record(double t0, double y0, double v0, double t1, double y1, double v1) {
        const double dt = g_.dt;
        const long evals = r_.evals;  // the re-runs for the history are not the method's cost
        struct Restore {
            long& e;
            long v;
            ~Restore() { e = v; }
        } restore{r_.evals, evals};
        for (long i = static_cast<long>(std::floor(t0 / dt)) + 1; i < g_.n; ++i) {
            const double ts = static_cast<double>(i) * dt;
            if (ts > t1) break;
            double y, v;
            if (ts == t1) y = y1;
            else rk4(t0, y0, v0, ts - t0, y, v);
            double yh, vh;
            hermite(t1 - t0, y0, v0, y1, v1, ts - t0, yh, vh);
            (*hist_)[i] = y;
            (*hist_h_)[i] = yh;
        }
    }
};

// ---------------------------------------------------------------- reference
struct Ref {
    std::map<std::string, std::vector<double>> theta;
    std::map<std::string, std::string> outcome;
    std::map<std::string, double> max_rot;
};
Ref read_ref(const std::string& dir, const std::string& label) {
    Ref r;
    std::ifstream h(dir + "/records_peers_" + label + ".csv");
    if (!h) throw std::runtime_error("no " + dir + "/records_peers_" + label + ".csv (records_peers histories --out DIR)");
    std::string line;
    std::getline(h, line);
    while (std::getline(h, line)) {
        const auto c1 = line.find(','), c2 = line.find(',', c1 + 1);
        r.theta[line.substr(0, c1)].push_back(std::stod(line.substr(c2 + 1)));
    }
    std::ifstream o(dir + "/records_peers_" + label + "_outcomes.csv");
    std::getline(o, line);
    while (std::getline(o, line)) {
        std::vector<std::string> f;
        std::istringstream in(line);
        for (std::string x; std::getline(in, x, ',');) f.push_back(x);
        r.outcome[f[0]] = f[6];
        r.max_rot[f[0]] = std::stod(f[8]);
    }
    return r;
}

double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct Config {
    std::string label;
    bool engine = false;
    Method method = Method::paper;
    double spp = 48;
    Scheme scheme = Scheme::plain;
    int k = 1;
    bool newton = false;
    bool thr4 = false;  ///< settling threshold 1e-4 p alpha (simulate's) instead of 1e-3
};

struct Accuracy {
    long steps = 0, search = 0, post = 0, evals = 0;
    double err = 0.0, err_h = 0.0, err_all = 0.0, rot = 0.0;
    int bad = 0;
    std::string bad_runs;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int run(const std::string& suite, const std::string& ref_dir, int rounds, double min_s, double adapt_tol,
        const std::string& hist_out, bool with_adaptive, int scan_n) {
    const std::vector<Run> runs = read_runs(suite, 1e-3);
    std::vector<Ground> grounds;
    for (const Run& r : runs) grounds.emplace_back(r.pulse);
    const Ref ref = read_ref(ref_dir, "reference"), chk = read_ref(ref_dir, "reference_check");
    std::map<std::string, bool> chaotic;
    for (const Run& r : runs) {
        const auto &a = ref.theta.at(r.name), &b = chk.theta.at(r.name);
        double d = 0.0;
        for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) d = std::max(d, std::abs(a[i] - b[i]));
        chaotic[r.name] = d > 1e-9 || ref.outcome.at(r.name) != chk.outcome.at(r.name);
    }

    std::vector<Config> configs;
    configs.push_back({"paper (engine)", true, Method::paper});
    configs.push_back({"events48 (engine)", true, Method::events, 48});
    configs.push_back({"events384 (engine)", true, Method::events, 384});
    for (bool nw : {false, true})
        for (Scheme s : {Scheme::plain, Scheme::trans, Scheme::moment, Scheme::rkn, Scheme::rkn_moment, Scheme::rkn_moment2}) {
            if (!nw && (s == Scheme::rkn || s == Scheme::rkn_moment2)) continue;
            for (int k : {1, 2, 3, 4, 6, 8})
                configs.push_back({std::string(name_of(s)) + (nw ? "+newton" : ""), false, Method::events, 0, s, k, nw});
        }
    if (with_adaptive)
        for (int k : {4, 8}) configs.push_back({"transA+newton kmax", false, Method::events, 0, Scheme::trans_adaptive, k, true});
    // steps of the engine's knob (steps per period of omega_max), across samples
    for (Scheme s : {Scheme::plain, Scheme::rkn, Scheme::rkn_moment, Scheme::moment})
        for (double spp : {24.0, 32.0, 48.0, 96.0})
            configs.push_back({std::string(name_of(s)) + "+newton spp=" + std::to_string(static_cast<int>(spp)), false, Method::events, spp, s, 0, true});
    for (Scheme s : {Scheme::rkn, Scheme::rkn_moment})
        for (double spp : {192.0, 384.0})
            configs.push_back({std::string(name_of(s)) + "+newton spp=" + std::to_string(static_cast<int>(spp)) + " thr1e-4", false, Method::events, spp, s, 0, true, true});

    // Accuracy (not timed)
    std::vector<Accuracy> acc(configs.size());
    std::ofstream hout;
    if (!hist_out.empty()) {
        hout.open(hist_out);
        hout << "config,run,i,theta,theta_hermite,theta_ref\n";
    }
    for (std::size_t c = 0; c < configs.size(); ++c) {
        const Config& cf = configs[c];
        Accuracy& A = acc[c];
        for (std::size_t i = 0; i < runs.size(); ++i) {
            const Run& r = runs[i];
            std::vector<double> th, thh;
            std::string outcome;
            double rot;
            if (cf.engine) {
                IntegratorSettings is;
                is.method = cf.method;
                if (cf.method == Method::events) is.steps_per_period = cf.spp;
                const CellModel m = make_cell_model(smatteo(), r.anch, r.pulse, Equations::nonlinear, cf.spp == 384 ? 1e-4 : 1e-3);
                std::size_t kk = 0;
                const std::size_t ns = r.pulse.record->size();
                const CellResult res = integrate_cell(m, is, [&](const StepRecord& st) {
                    for (; kk < ns; ++kk) {
                        const double t = static_cast<double>(kk) * r.pulse.record_dt_s;
                        if (t > st.t1) break;
                        double a, b;
                        st.at(std::max(t, st.t0), a, b);
                        th.push_back(a);
                    }
                });
                thh = th;
                outcome = to_string(res.outcome);
                rot = res.max_rotation;
                A.steps += res.steps;
                A.evals += 4 * res.steps;
            } else {
                Proto p(cf.thr4 ? r.model4 : r.model, grounds[i], cf.scheme, cf.k, cf.spp, adapt_tol, cf.newton, &th, &thh);
                const Outcome3 o = p.run();
                outcome = o.outcome;
                rot = o.max_rot;
                A.steps += o.steps;
                A.search += o.search;
                A.evals += o.evals;
                A.post += o.post;
            }
            const std::vector<double>& tr = ref.theta.at(r.name);
            double e = 0.0, eh = 0.0;
            const std::size_t n = std::min(tr.size(), th.size());
            for (std::size_t j = 0; j < n; ++j) {
                e = std::max(e, std::abs(th[j] - tr[j]));
                eh = std::max(eh, std::abs(thh[j] - tr[j]));
                if (hout.is_open()) hout << cf.label << ',' << r.name << ',' << j << ',' << th[j] << ',' << thh[j] << ',' << tr[j] << '\n';
            }
            A.err_all = std::max(A.err_all, e);
            if (!chaotic[r.name]) {
                A.err = std::max(A.err, e);
                A.err_h = std::max(A.err_h, eh);
                A.rot = std::max(A.rot, std::abs(rot - ref.max_rot.at(r.name)) / ref.max_rot.at(r.name));
            }
            if (outcome != ref.outcome.at(r.name)) {
                ++A.bad;
                A.bad_runs += " " + r.name + "(" + outcome + ")";
            }
        }
    }

    // Outcomes on a denser scan of scales (every record at scan_n scales from 0.5 to 3, free and
    // anchored), against the engine at the reference's settings (4096 steps per period, settling
    // 1e-8 p alpha); runs on which that reference and its check (2048, 1e-7) differ are left out.
    std::vector<int> scan_bad(configs.size(), 0);
    int scan_used = 0;
    if (scan_n > 0) {
        std::vector<double> scales;
        for (int i = 0; i < scan_n; ++i) scales.push_back(0.5 + 2.5 * i / std::max(1, scan_n - 1));
        const std::vector<Run> sr = read_runs(suite, 1e-3, scales);
        std::vector<Ground> sg;
        for (const Run& r : sr) sg.emplace_back(r.pulse);
        std::vector<CellModel> mref, mchk, m3s, m4s;
        for (const Run& r : sr) {
            mref.push_back(make_cell_model(smatteo(), r.anch, r.pulse, Equations::nonlinear, 1e-8));
            mchk.push_back(make_cell_model(smatteo(), r.anch, r.pulse, Equations::nonlinear, 1e-7));
            m3s.push_back(r.model);
            m4s.push_back(r.model4);
        }
        std::vector<CellResult> rr(sr.size()), rc(sr.size()), ro(sr.size());
        IntegratorSettings isr, isc;
        isr.steps_per_period = 4096;
        isc.steps_per_period = 2048;
        integrate_cells(mref, rr, isr, 1);
        integrate_cells(mchk, rc, isc, 1);
        std::vector<bool> use(sr.size());
        for (std::size_t i = 0; i < sr.size(); ++i) {
            use[i] = rr[i].outcome == rc[i].outcome;
            scan_used += use[i] ? 1 : 0;
        }
        std::fprintf(stderr, "[scan] reference %.1f s CPU\n", cpu_seconds());
        for (std::size_t c = 0; c < configs.size(); ++c) {
            const Config& cf = configs[c];
            const double c0 = cpu_seconds();
            struct Report {
                const std::string& l;
                double c0;
                ~Report() { std::fprintf(stderr, "[scan] %s %.2f s\n", l.c_str(), cpu_seconds() - c0); }
            } report{cf.label, c0};
            if (cf.engine) {
                IntegratorSettings is;
                is.method = cf.method;
                if (cf.method == Method::events) is.steps_per_period = cf.spp;
                integrate_cells(cf.spp == 384 ? m4s : m3s, ro, is, 1);
                for (std::size_t i = 0; i < sr.size(); ++i)
                    if (use[i] && ro[i].outcome != rr[i].outcome) ++scan_bad[c];
            } else {
                for (std::size_t i = 0; i < sr.size(); ++i) {
                    Proto p(cf.thr4 ? sr[i].model4 : sr[i].model, sg[i], cf.scheme, cf.k, cf.spp, adapt_tol, cf.newton, nullptr, nullptr);
                    const std::string o = p.run().outcome;
                    if (use[i] && o != to_string(rr[i].outcome)) ++scan_bad[c];
                    if (o == "not_converged") std::fprintf(stderr, "[scan] %s k=%d: %s not converged\n", cf.label.c_str(), cf.k, sr[i].name.c_str());
                }
            }
        }
    }

    // Speed: rounds, every config once per round in a rotated order; CPU s per pass.
    std::vector<std::vector<double>> cpu(configs.size());
    std::vector<CellModel> m3, m4;
    for (const Run& r : runs) {
        m3.push_back(r.model);
        m4.push_back(make_cell_model(smatteo(), r.anch, r.pulse, Equations::nonlinear, 1e-4));
    }
    std::vector<CellResult> out(runs.size());
    for (int rd = 0; rd < rounds; ++rd) {
        for (std::size_t cc = 0; cc < configs.size(); ++cc) {
            const std::size_t c = (cc + static_cast<std::size_t>(rd)) % configs.size();
            const Config& cf = configs[c];
            long passes = 0;
            const auto w0 = std::chrono::steady_clock::now();
            const double c0 = cpu_seconds();
            double wall = 0.0;
            volatile long sink = 0;
            do {
                if (cf.engine) {
                    IntegratorSettings is;
                    is.method = cf.method;
                    if (cf.method == Method::events) is.steps_per_period = cf.spp;
                    integrate_cells(cf.spp == 384 ? m4 : m3, out, is, 1);
                    sink = sink + out[0].steps;
                } else {
                    for (std::size_t i = 0; i < runs.size(); ++i) {
                        Proto p(cf.thr4 ? runs[i].model4 : runs[i].model, grounds[i], cf.scheme, cf.k, cf.spp, adapt_tol, cf.newton, nullptr, nullptr);
                        sink = sink + p.run().steps;
                    }
                }
                ++passes;
                wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
            } while (wall < min_s);
            cpu[c].push_back((cpu_seconds() - c0) / static_cast<double>(passes));
            if (std::getenv("RECORD_STEPS_VERBOSE")) std::fprintf(stderr, "[time] %s k=%d %.3f s x %ld\n", cf.label.c_str(), cf.k, cpu[c].back(), passes);
        }
    }
    const double nruns = static_cast<double>(runs.size());
    std::printf("| method | k | steps, 12 runs | RHS evaluations | runs/s/core | x paper (median [min, max] over %d rounds) | x events48 | max abs theta err, 11 non-chaotic (re-run dense) | same, cubic Hermite dense | max abs theta err, all 12 | max rel. err max rotation (11) | outcomes != ref (12) | outcomes != ref, scan of %d | projected engine x paper |\n", rounds, scan_used);
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    // The prototype's plain k=1 is the events method at 48 (same steps, same error): the
    // projection scales the engine's events48 ratio by the prototype's speed-up over plain k=1.
    std::size_t plain1 = 0;
    for (std::size_t c = 0; c < configs.size(); ++c)
        if (!configs[c].engine && configs[c].scheme == Scheme::plain && configs[c].k == 1 && !configs[c].newton && configs[c].spp == 0) plain1 = c;
    for (std::size_t c = 0; c < configs.size(); ++c) {
        std::vector<double> rp, re;
        for (int rd = 0; rd < rounds; ++rd) {
            rp.push_back(cpu[0][rd] / cpu[c][rd]);
            re.push_back(cpu[1][rd] / cpu[c][rd]);
        }
        const Config& cf = configs[c];
        std::string k = cf.engine ? "-" : cf.spp > 0 ? "h" : std::to_string(cf.k);
        std::fprintf(stderr, "%s: steps %ld, of which search re-runs %ld, after the record %ld\n", cf.label.c_str(), acc[c].steps, acc[c].search, acc[c].post);
        std::vector<double> pj;
        for (int rd = 0; rd < rounds; ++rd) pj.push_back(cpu[0][rd] / cpu[1][rd] * (cf.engine ? cpu[1][rd] / cpu[c][rd] : cpu[plain1][rd] / cpu[c][rd]));
        std::printf("| %s | %s | %ld | %ld | %.0f | %.2f [%.2f, %.2f] | %.2f | %.2e | %.2e | %.2e | %.1e | %d%s | %d | %.1f |\n", cf.label.c_str(),
                    k.c_str(), acc[c].steps, acc[c].evals, nruns / median(cpu[c]), median(rp), *std::min_element(rp.begin(), rp.end()),
                    *std::max_element(rp.begin(), rp.end()), median(re), acc[c].err, acc[c].err_h, acc[c].err_all,
                    acc[c].rot, acc[c].bad, acc[c].bad_runs.c_str(), scan_bad[c], median(pj));
    }
    std::printf("\nchaotic (left out of the 11):");
    for (const auto& [n, ch] : chaotic)
        if (ch) std::printf(" %s", n.c_str());
    std::printf("\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"RK4 steps across record samples: a research prototype (benchmarks/RECORD_STEPS.md)"};
    std::string suite = "benchmarks/records_peers.csv", ref, hist;
    int rounds = 3;
    double min_s = 0.2, adapt_tol = 1e-6;
    app.add_option("--suite", suite)->check(CLI::ExistingFile)->capture_default_str();
    app.add_option("--ref", ref, "folder with records_peers histories (reference, reference_check)")->required();
    app.add_option("--rounds", rounds)->capture_default_str();
    app.add_option("--min-seconds", min_s, "wall seconds per config per round, at least")->capture_default_str();
    app.add_option("--adapt-tol", adapt_tol, "transA: sum J_i h^4 per step [1/s^3 s^4]")->capture_default_str();
    bool with_adaptive = false;
    int scan_n = 26;
    app.add_option("--scan", scan_n, "outcomes also on this many scales 0.5..3 of every record (0: none)")->capture_default_str();
    app.add_flag("--adaptive", with_adaptive, "also transA (k per step from the slope jumps)");
    app.add_option("--histories", hist, "write every config's theta at the samples to this csv");
    CLI11_PARSE(app, argc, argv);
    try {
        return run(suite, ref, rounds, min_s, adapt_tol, hist, with_adaptive, scan_n);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "record_steps: %s\n", e.what());
        return 1;
    }
}
