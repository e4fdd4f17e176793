#!/usr/bin/python3
"""Can RK4's four stages carry a piecewise-linear ground so that steps crossing its samples keep
order 4? (benchmarks/RECORD_STEPS.md, "Four ground values at the four stages")

    /usr/bin/python3 benchmarks/stage_ground.py [RECORD]    (default tests/data/elcentro_1940_NS.dat)

The test equation has the rocking equation's structure, theta'' = F(theta) + G(theta) u(t) with u
the record (x 2, in g) linear between samples, but is stable without impacts: a pendulum,
theta'' = -p^2 (sin theta + u cos theta), p = 2.3 rad/s (S. Matteo's), from rest, 20 s. The
reference ends its steps at the samples (exact ground) with 16 steps per sample. Steps of k
samples (k not an integer, so they cross samples everywhere) take the ground at the stages as:
  nodal    u at the stage times (t0, t0 + h/2, t0 + h/2, t0 + h): one kink in a step costs the order;
  moment   the engine's moment nodes (--record-steps cross): three values whose Simpson rule gives
           the exact integrals of u s^n, n = 0, 1, 2, over the step, stages 2 and 3 sharing one;
  linresp  four values, one per stage, that make the step's response linear in u exact up to
           the fourth power of the Jacobian (weights of int u (1 - s)^n, n = 0..3, from RK4's
           tableau: 1/6 (1, 2, 2, 1), 1/6 (1, 1, 1, 0), 1/12 (1, 1, 0, 0), 1/24 (1, 0, 0, 0)).
           The tableau's weights of int u s^2 (the term of theta's second derivative) are then
           no longer met: four values cannot meet the five conditions of order 4.
Prints the error at 20 s against the reference and the order between successive step sizes.
"""
import sys

import numpy as np

P2 = 2.3 ** 2
T_END = 20.0
GAUSS_X, GAUSS_W = np.polynomial.legendre.leggauss(4)  # exact for u s^3 on a linear piece


class Ground:
    def __init__(self, path, dt=0.02, factor=2.0):
        self.dt = dt
        a = np.loadtxt(path)[:, 1] * factor
        self.a = a[: int(T_END / dt) + 2]

    def at(self, t):
        x = t / self.dt
        i = min(int(x), len(self.a) - 2)
        return self.a[i] + (x - i) * (self.a[i + 1] - self.a[i])

    def moments(self, t0, h, n):
        """int_0^1 u(t0 + s h) s^j ds, j = 0..n, exact on each linear piece."""
        m = np.zeros(n + 1)
        ta, t1 = t0, t0 + h
        while ta < t1 - 1e-15:
            tb = min(t1, (np.floor(ta / self.dt + 1e-12) + 1) * self.dt)
            for x, w in zip(GAUSS_X, GAUSS_W):
                t = 0.5 * (ta + tb) + 0.5 * (tb - ta) * x
                m += 0.5 * (tb - ta) / h * w * self.at(t) * ((t - t0) / h) ** np.arange(n + 1)
            ta = tb
        return m


def nodal(g, t0, h):
    um = g.at(t0 + 0.5 * h)
    return g.at(t0), um, um, g.at(t0 + h)


def moment(g, t0, h):
    m0, m1, m2 = g.moments(t0, h, 2)
    um = 6 * (m1 - m2)
    return 6 * (m0 - 3 * m1 + 2 * m2), um, um, 6 * (2 * m2 - m1)


def linresp(g, t0, h):
    m = g.moments(t0, h, 3)
    a = [m[0], m[0] - m[1], m[0] - 2 * m[1] + m[2], m[0] - 3 * m[1] + 3 * m[2] - m[3]]  # int u (1-s)^n
    u1 = 4 * a[3]
    u2 = 6 * a[2] - u1
    u3 = 6 * a[1] - u1 - u2
    return u1, u2, u3, 6 * a[0] - u1 - 2 * u2 - 2 * u3


def f(y, u):
    return np.array([y[1], -P2 * (np.sin(y[0]) + u * np.cos(y[0]))])


def run(g, h, ground):
    n = int(round(T_END / h))
    h = T_END / n
    y = np.zeros(2)
    for i in range(n):
        u1, u2, u3, u4 = ground(g, i * h, h)
        k1 = f(y, u1)
        k2 = f(y + 0.5 * h * k1, u2)
        k3 = f(y + 0.5 * h * k2, u3)
        k4 = f(y + h * k3, u4)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return y


def main(path):
    g = Ground(path)
    ref = run(g, g.dt / 16, nodal)  # steps end at the samples: the ground is exact
    print(f"{path}: pendulum under the record x 2, {T_END:g} s; reference theta = {ref[0]:.9f} rad")
    print(f"{'ground':8s} {'h / dt':>6s} {'error':>10s} {'order':>6s}")
    for name, ground in (("nodal", nodal), ("moment", moment), ("linresp", linresp)):
        last = None
        for k in (4.3, 2.9, 2.05, 1.43):
            e = np.abs(run(g, k * g.dt, ground) - ref).max()
            order = f"{np.log(last[1] / e) / np.log(last[0] / k):6.2f}" if last else ""
            print(f"{name:8s} {k:6.2f} {e:10.2e} {order:>6s}")
            last = (k, e)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/elcentro_1940_NS.dat")
