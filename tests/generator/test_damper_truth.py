#!/usr/bin/env python3
"""The generator against analytic limits, so that its truth can be trusted: the field lag's step
response, the air's dead travel and linear ramp, J-A near saturation and at its initial slope, the
fluid's adiabatic heating; and the random damper's pieces: Herschel-Bulkley at v_ref and n = 1, the
sign shapes' symmetry, saturation and slope at rest, the yield laws' monotony, the draw's
determinism and ranges, J-A stable on every drawn core, effects scaled to the damper's size."""
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


def run(**kw):
    """simulate() on parsed arguments, so the tests go through the command line's defaults."""
    argv = ["--out", "unused.csv"]
    for key, value in kw.items():
        for item in value if isinstance(value, list) else [value]:
            argv += ["--" + key, str(item)]
    return g.simulate(g.parse_args(argv))


class RandomDamper(unittest.TestCase):
    SEEDS = range(1, 201)

    def test_herschel_bulkley_is_c0_v_ref_at_v_ref_odd_and_linear_at_n_1(self):
        d = dict(fluid="herschel_bulkley", n=0.7)
        self.assertAlmostEqual(g.viscous_force(np.array([g.V_REF]), 300.0, d)[0], 300.0 * g.V_REF, delta=1e-9)
        v = np.linspace(-0.5, 0.5, 101)
        np.testing.assert_allclose(g.viscous_force(-v, 300.0, d), -g.viscous_force(v, 300.0, d), atol=1e-12)
        np.testing.assert_allclose(g.viscous_force(v, 300.0, dict(fluid="herschel_bulkley", n=1.0)), 300.0 * v,
                                   rtol=1e-12, atol=1e-12)
        # Shear thinning (n < 1) lies above the line below v_ref and below it above.
        thin = g.viscous_force(np.array([0.02, 0.4]), 300.0, d)
        self.assertGreater(thin[0], 300.0 * 0.02)
        self.assertLess(thin[1], 300.0 * 0.4)

    def test_each_sign_shape_is_odd_saturates_to_one_and_has_slope_one_over_v0_at_rest(self):
        v0 = 3e-3
        v = np.linspace(-0.2, 0.2, 2001)
        for kind in g.SIGN_KINDS:
            s = g.sign_shape(v, kind, v0)
            np.testing.assert_allclose(s, -s[::-1], atol=1e-12, err_msg=kind)
            self.assertAlmostEqual(s[-1], 1.0, delta=0.01 if kind == "atan" else 1e-9, msg=kind)  # atan: 2/(pi u)
            self.assertTrue(np.all(np.abs(s) <= 1.0), kind)
            self.assertTrue(np.all(np.diff(s) >= -1e-12), kind)  # the knee's rounding far out
            h = 1e-4 * v0
            slope = (g.sign_shape(np.array([h]), kind, v0)[0] - g.sign_shape(np.array([-h]), kind, v0)[0]) / (2 * h)
            self.assertAlmostEqual(slope * v0, 1.0, delta=1e-6, msg=kind)

    def test_the_yield_laws_rise_monotonically_in_abs_b_from_f0_to_fmax(self):
        B = np.linspace(-3.0, 3.0, 601)
        for shape in (dict(yield_law="tanh", B_sat_T=0.8), dict(yield_law="power", p=0.5, B_ref_T=1.2),
                      dict(yield_law="power", p=1.2, B_ref_T=1.5)):
            d = dict(shape, F_max_N=10e3, F_0_N=500.0)
            F = g.yield_force(B, d)
            np.testing.assert_allclose(F, F[::-1], err_msg=str(shape))  # even in B
            self.assertTrue(np.all(np.diff(F[300:]) >= 0), shape)
            self.assertAlmostEqual(F[300], 500.0, msg=shape)
            self.assertLessEqual(F.max(), 10e3 + 1e-9, shape)
            self.assertGreater(F.max(), 0.98 * 10e3, shape)
        capped = g.yield_force(np.array([1.5, 2.0]),
                               dict(yield_law="power", p=0.8, B_ref_T=1.5, F_max_N=1e3, F_0_N=0.0))
        np.testing.assert_allclose(capped, [1e3, 1e3])

    def test_the_draw_is_deterministic_per_seed_and_inside_its_documented_ranges(self):
        def within(value, bounds, what, tol=1e-9):
            lo, hi = bounds
            self.assertTrue(lo * (1 - tol) <= value <= hi * (1 + tol), f"{what} {value} outside {bounds}")
        kinds = set()
        for seed in self.SEEDS:
            d = g.draw_damper(seed)
            self.assertEqual(d, g.draw_damper(seed))
            ja, m = d["ja"], g.MATERIALS[d["material"]]
            self.assertNotEqual(ja, g.JA)
            for name, bounds in m.items():
                within(ja[name], bounds, f"seed {seed} {d['material']} {name}")
            self.assertLessEqual(ja["alpha"] * ja["Ms"] / (3 * ja["a"]), g.FEEDBACK_LIMIT)
            within(d["I_max_A"], g.I_MAX_A, "I_max")
            within(d["turns_per_m"], g.TURNS_RANGE, "turns")
            if g.TURNS_RANGE[0] < d["turns_per_m"] < g.TURNS_RANGE[1]:  # else clipped to the coil's range
                within(d["H_top_over_knee"], g.H_TOP_OVER_KNEE, "H(I_max) / max(a, k)")
            within(d["F_max_N"], g.F_MAX_N, "F_max")
            within(d["F_0_N"] / d["F_max_N"], g.F_0_SHARE, "F_0 share")
            if d["yield_law"] == "power":
                within(d["p"], g.POWER_EXPONENT, "p")
                within(d["B_ref_T"] / d["B_top_T"], g.B_REF_SHARE, "B_ref share")
            else:
                within(d["B_sat_T"] / d["B_top_T"], g.B_SAT_SHARE, "B_sat share")
            self.assertLess(d["B_top_T"], g.MU0 * (d["H_top_A_m"] + ja["Ms"]))
            within(d["v0_m_s"], g.V0_RANGE, "v0")
            within(d["n"], g.FLOW_INDEX, "n")
            within(d["viscous_share"], g.VISCOUS_SHARE, "viscous share")
            within(d["force_noise_N"] / d["F_max_N"], g.NOISE_F_SHARE, "force noise share")
            within(d["displacement_noise_m"], g.NOISE_X_RANGE, "displacement noise")
            kinds.add((d["material"], d["yield_law"], d["sign"]))
        # 200 draws reach every class, law and sign kind.
        self.assertEqual({k[0] for k in kinds}, set(g.MATERIALS))
        self.assertEqual({k[1] for k in kinds}, set(g.YIELD_LAWS))
        self.assertEqual({k[2] for k in kinds}, set(g.SIGN_KINDS))
        self.assertNotEqual(g.draw_damper(1), g.draw_damper(2))

    def test_ja_on_every_drawn_core_stays_finite_bounded_and_monotone_on_its_branches(self):
        for seed in range(1, 41):
            d = g.draw_damper(seed)
            top = d["H_top_A_m"]
            up, down = np.linspace(0, top, 200), np.linspace(top, 0, 200)
            H = np.concatenate([up, down, up, down, up])
            B = g.ja_induction(H, d["ja"], d["field_step_A_m"])
            self.assertTrue(np.all(np.isfinite(B)), seed)
            self.assertTrue(np.all(B <= g.MU0 * (H + d["ja"]["Ms"]) * 1.001), seed)
            self.assertTrue(np.all(np.diff(B[400:600]) >= 0) and np.all(np.diff(B[200:400]) <= 0), seed)
            # The unipolar loop settles after the virgin curve: the third tip within 3 % of the second.
            self.assertLess(abs(B[-1] / B[599] - 1), 0.03, seed)
            # Hysteresis on the bipolar loop: remanence of the falling branch's sign, equal and opposite.
            H = np.concatenate([up, down, -up, -down, up, down])
            B = g.ja_induction(H, d["ja"], d["field_step_A_m"])
            self.assertGreater(B[399], 0.0, seed)
            self.assertAlmostEqual(B[799] / B[-1], -1.0, delta=0.02, msg=seed)

    def test_the_draw_depends_on_the_seed_alone(self):
        *_, a = run(damper="random", seed=5, profile="table4", duration=1)
        *_, b = run(damper="random", seed=5, profile="mixed", duration=2, effect="gas_spring:1")
        run_dependent = ("peak_speed_m_s", "c0_N_s_m")
        strip = lambda d: {k: v for k, v in d.items() if k not in run_dependent}  # noqa: E731
        self.assertEqual(strip(a["damper"]), strip(b["damper"]))

    def test_the_viscous_share_at_the_peak_speed_is_the_drawn_one(self):
        *_, truth = run(damper="random", seed=11, profile="random", duration=2)
        d = truth["damper"]
        peak = g.viscous_force(np.array([d["peak_speed_m_s"]]), d["c0_N_s_m"], d)[0]
        self.assertAlmostEqual(peak / d["F_max_N"], d["viscous_share"], delta=1e-9)

    def test_an_effects_force_scales_with_the_dampers_size(self):
        # Same seed, same noise: the difference is the gas spring alone, 2 (70 N + 500 N/m x) F_max / 1.5 kN.
        t, x, _, clean, *_ = run(damper="random", seed=3, profile="table4", duration=2)
        *_, spring, _, _, truth = run(damper="random", seed=3, profile="table4", duration=2, effect="gas_spring:2")
        scale = truth["damper"]["F_max_N"] / g.F_YIELD_MAX
        self.assertEqual(truth["effect_force_scale"], scale)
        np.testing.assert_allclose(spring - clean, 2 * scale * (70.0 + 500.0 * x), atol=2 * scale * 500.0 * 1e-4)

    def test_random_and_mixed_motions_keep_to_their_ranges(self):
        for seed in range(1, 6):
            t, x, I, _, v, _, truth = run(damper="random", seed=seed, profile="random", duration=8)
            peak, top = truth["motion"]["peak_mm"], truth["damper"]["I_max_A"]
            self.assertTrue(5 <= peak <= 40)
            self.assertTrue(np.all((I >= 0) & (I <= top + 1e-12)))
            steps = truth["motion"]["current_steps_s_share"]
            dwell = np.diff([s[0] for s in steps])
            self.assertTrue(np.all((dwell >= 0.1) & (dwell <= 1.0)))
            levels = np.unique(I)
            self.assertEqual(len(levels), len({s[1] for s in steps}))
            t, x, I, _, v, _, truth = run(damper="random", seed=seed, profile="mixed", duration=8)
            levels = truth["motion"]["amplitude_levels_mm"]
            self.assertTrue(3 <= len(levels) <= 4 and all(5 <= a <= 40 for a in levels))
            self.assertLessEqual(np.max(np.abs(x)), 1e-3 * max(levels) + 1e-4)
            # The amplitude ramps keep the velocity continuous (a bare level change jumps 2 pi f dA, ~0.1 m/s).
            self.assertLess(np.max(np.abs(np.diff(v))), 0.02)


if __name__ == "__main__":
    unittest.main()
