#!/usr/bin/python3
"""A `rocksweep basin` file against the energy argument written out again here, in closed form
(docs/physics.md, "Basins"): the boundaries, the simulated map away from them, the attributes.

    test_basin_file.py BASIN.h5
"""
import math
import sys
import unittest

import h5py
import numpy as np

PATH = sys.argv[1] if len(sys.argv) > 1 else None


def gravity(phi, alpha):
    """Potential of gravity per unit I0 p^2, zero at rest."""
    return np.cos(alpha - phi) - math.cos(alpha)


def spring(phi, kappa):
    """Potential of the Eq. 8 moment kappa sin(phi/2), per unit I0 p^2 (kappa in units of p^2)."""
    return 2.0 * kappa * (1.0 - np.cos(phi / 2))


def gravity_below(phi, alpha):
    """gravity(alpha, alpha) - gravity(phi, alpha) = 1 - cos(alpha - phi), without cancellation."""
    return 2.0 * np.sin((alpha - phi) / 2) ** 2


def spring_below(phi_f, phi, kappa):
    """spring(phi_f, kappa) - spring(phi, kappa) = 2 kappa (cos(phi/2) - cos(phi_f/2)), without
    cancellation."""
    return 4.0 * kappa * np.sin((phi_f + phi) / 4) * np.sin((phi_f - phi) / 4)


# A no-impact boundary goes to 0 where theta reaches its barrier, as the root of a difference of
# two nearly equal potentials. Written so here, with numpy's cosine (on AVX-512 a few ulps off the
# C library's), the reference itself was off by a relative 1e-9 near the end. So the boundaries
# are checked as energies, 0.5 (theta_dot/p)^2, against the difference written without
# cancellation (gravity_below, spring_below): to a relative 1e-9 (the file is within 1e-10), or ten
# roundings of a potential of order 1 where the difference itself is near 0.
ENERGY_ATOL = 2e-15


def assert_energy(boundary, difference):
    np.testing.assert_allclose(0.5 * boundary**2, difference, rtol=1e-9, atol=ENERGY_ATOL)


class BasinFile(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.f = h5py.File(PATH, "r")
        cls.alpha = float(cls.f.attrs["alpha_rad"])
        cls.e = float(cls.f.attrs["e"])
        cls.theta = cls.f["axes/theta_ratio"][()]
        cls.rate = cls.f["axes/theta_dot_ratio"][()]
        cls.curve_theta = cls.f["axes/curve_theta_ratio"][()]

    @classmethod
    def tearDownClass(cls):
        cls.f.close()

    def test_maps_carry_their_axes(self):
        for name in ("outcome", "outcome_predicted"):
            ds = self.f["basins/free/" + name]
            self.assertEqual(ds.shape, (self.rate.size, self.theta.size))
            self.assertEqual(ds.dims[0][0].name, "/axes/theta_dot_ratio")
            self.assertEqual(ds.dims[1][0].name, "/axes/theta_ratio")
        self.assertEqual(self.f["basins/free/no_impact_boundary"].dims[0][0].name, "/axes/curve_theta_ratio")

    def test_free_boundaries_are_the_separatrix_and_its_one_impact_image(self):
        g = self.f["basins/free"]
        x = self.curve_theta
        inside = (x > 0) & (x < 1)
        th = x[inside] * self.alpha
        above = g["no_impact_boundary"][()][inside]
        self.assertTrue(np.all(above > 0))
        assert_energy(above, gravity_below(th, self.alpha))
        want = -np.sqrt(2 * (gravity(self.alpha, self.alpha) / self.e**2 - gravity(th, self.alpha)))
        np.testing.assert_allclose(g["impact_boundary"][()][inside], want, rtol=1e-9)

    def test_spring_broken_before_alpha_adds_only_the_energy_it_held(self):
        g = self.f["basins/constant_tf0.5"]
        tf = 0.5 * self.alpha
        # kappa / p^2 = 8 b^2 K / (m g R) with K = F_u / (4 b tan(theta_f/2)), F_u = 0.4 m g, b = R sin(alpha)
        kappa = 0.8 * math.sin(self.alpha) / math.tan(tf / 2)
        x = self.curve_theta
        inside = (x > 0) & (x < 0.5)
        th = x[inside] * self.alpha
        # The barrier gravity(alpha) + spring(theta_f), less the potentials at theta.
        above = g["no_impact_boundary"][()][inside]
        self.assertTrue(np.all(above > 0))
        assert_energy(above, gravity_below(th, self.alpha) + spring_below(tf, th, kappa))

    def test_simulated_free_map_away_from_the_boundaries(self):
        out = self.f["basins/free/outcome"][()]
        th = self.theta * self.alpha
        barrier = gravity(self.alpha, self.alpha)
        checked = 0
        for i, q in enumerate(self.rate):
            for j, x in enumerate(self.theta):
                if not 0 < x < 1:
                    continue
                ke = 0.5 * q * q
                energy = ke + gravity(th[j], self.alpha)
                if q > 0 and ke > 1.1 * (barrier - gravity(th[j], self.alpha)):
                    want = 2  # over the barrier without an impact
                elif q < 0 and self.e**2 * energy > 1.1 * barrier:
                    want = 1  # back through theta = 0, over the other side's barrier
                elif energy < 0.9 * barrier:
                    want = 0
                else:
                    continue
                self.assertEqual(out[i, j], want, "theta/alpha = {}, theta_dot/p = {}".format(x, q))
                checked += 1
        self.assertGreater(checked, 100)

    def test_rest_fraction_is_the_share_of_rest_cells(self):
        for name, g in self.f["basins"].items():
            share = float(np.mean(g["outcome"][()] == 0))
            self.assertAlmostEqual(float(g.attrs["rest_fraction"]), share, delta=1e-12, msg=name)
            self.assertEqual(int(g.attrs["cells_clear_disagreeing"]), 0, name)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
