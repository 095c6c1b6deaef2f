#!/usr/bin/env python3
"""The generator against analytic limits, so that its truth can be trusted: the field lag's step
response, the air's dead travel and linear ramp, J-A near saturation and at its initial slope, the
fluid's adiabatic heating."""
import math, os, sys, unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import damper_truth as g  # noqa: E402


class Generator(unittest.TestCase):
    def test_field_lag_is_a_first_order_step_response(self):
        y = g.first_order(np.ones(200), 0.02)  # tau = 20 samples at 1 kHz
        self.assertAlmostEqual(y[19], 1 - math.exp(-1), delta=2e-3)

    def test_air_recovers_along_a_ramp_after_dead_travel(self):
        x = np.concatenate([np.linspace(0, 0.018, 200), np.linspace(0.018, 0.0, 200)])
        travel, armed = g.reversals_travel(x, 0.015)
        self.assertTrue(armed[-1])
        self.assertAlmostEqual(travel[-1], 0.018, delta=1e-4)
        self.assertFalse(armed[150])

    def test_ja_saturates_to_mu0_h_plus_ms_and_starts_at_the_initial_susceptibility(self):
        H = np.linspace(0, 2e6, 400)
        B = g.ja_induction(H)
        self.assertAlmostEqual(B[-1] / (g.MU0 * (H[-1] + g.JA["Ms"])), 1.0, delta=0.01)
        # Initial slope: chi = c Ms / (3 a - alpha c Ms) for the reversible part (Jiles 1992).
        Hs = np.linspace(0, 20.0, 5)
        Bs = g.ja_induction(Hs)
        Ms, a, alpha, c = (g.JA[n] for n in ("Ms", "a", "alpha", "c"))
        chi = c * Ms / (3 * a - alpha * c * Ms)
        self.assertLess(abs((Bs[1] / (g.MU0 * Hs[1]) - 1) / chi - 1), 0.5)

    def test_adiabatic_heating_follows_the_closed_form_of_a_constant_viscous_power(self):
        # C dT/dt = c0 v^2 / (1 + b T)  =>  T + b T^2 / 2 = c0 v^2 t / C.
        v = np.full(4000, 0.05)
        f_visc, f_yield = g.adiabatic_heating(np.zeros_like(v), g.C0 * v, v, 2.0)
        b = 2.0 * g.VISCOSITY_PER_K
        energy = g.C0 * 0.05 ** 2 * (len(v) / g.RATE) / g.HEAT_CAPACITY
        rise = (math.sqrt(1 + 2 * b * energy) - 1) / b
        self.assertAlmostEqual(1.0 / f_visc[-1], 1 + b * rise, delta=1e-3)
        self.assertAlmostEqual(f_yield[-1], 1 - 2.0 * g.YIELD_PER_K * rise, delta=1e-3)


if __name__ == "__main__":
    unittest.main()
