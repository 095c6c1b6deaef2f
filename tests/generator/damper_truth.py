#!/usr/bin/env python3
"""An independent truth generator for mrd-residual: a simulated MR damper test run, written from
the physics with numpy alone and sharing no code with the fitter (which runs model::Observer).

--damper fixed (the default) is a 1 kN class whose forms differ on purpose from sim::DamperPlant's:
  - hysteresis: Jiles-Atherton integrated by explicit Euler on a fine field grid (not RK4 on the
    paper's sub-steps); B = mu0 (H + M);
  - yield: tau_y = tau_max tanh(B / B_sat) (not Eq. 13's power law); sign smoothing 2/pi atan(v/v0)
    (not tanh);
  - coil_lag: a first-order lag on the FIELD H (not on the current);
  - stroke_end_air: dead travel, then a linear ramp after reversals beyond a threshold;
  - preyield_hysteresis: Bouc-Wen in Spencer's form with its own alpha z term (not a share of F_y);
  - thermal_drift: adiabatic heating (no cooling), a hyperbolic viscosity law and a linear yield
    law (the model: exponential viscosity, cooling towards ambient);
  - non-candidates: moving_mass, coulomb_friction, mains_hum, field_viscosity, bump_stop.

--damper random draws the damper from physical ranges, one draw per --seed from a random stream of
its own (the draw does not depend on the profile, the duration or the effects):
  - core: a J-A material class, picked at random:
      soft steel  Ms 1.2e6-1.7e6 A/m, a 200-1500 A/m, k 100-1500 A/m, c 0.05-0.5, alpha 1e-4-2e-3
      hard steel  Ms 1.0e6-1.6e6 A/m, a 1500-6000 A/m, k 2000-8000 A/m, c 0.05-0.4, alpha 1e-4-3e-3
    a, k and alpha log-uniform, Ms and c uniform, redrawn while alpha Ms / (3 a) > 0.8 (at 1 the
    mean-field feedback makes the anhysteretic's slope, and Euler's J-A, run away); Euler's field
    step max(5 A/m, min(a, k) / 20);
  - coil: top current I_max 1-3 A; turns per metre such that the field at I_max is 2-20 times
    max(a, k) (log-uniform), clipped to 3e3-6e4 turns/m: past both the anhysteretic's knee (a)
    and the pinning field (k), from the knee into saturation (a coil that stops short of k drives
    a minor loop whose first cycles climb well above the virgin curve, J-A's accommodation);
  - yield: F_y = F_0 + (F_max - F_0) law(|B|), law either a power (|B| / B_ref)^p capped at 1
    (p 0.4-1.2, B_ref 0.6-1.0 of the anhysteretic B at I_max) or tanh(|B| / B_sat) (B_sat 0.4-1.0
    of it); F_max log-uniform 1-100 kN; F_0, the plateau at 0 A (residual yield, seal friction),
    0-8 % of F_max;
  - sign smoothing, u = v / v0, v0 log-uniform 0.5-10 mm/s, each with slope 1/v0 at rest: tanh(u),
    2/pi atan(pi u / 2), or a sharper knee u / (1 + |u|^8)^(1/8);
  - fluid: Herschel-Bulkley c0 v_ref sign(v) |v / v_ref|^n, v_ref 0.1 m/s, n 0.6-1.4, c0 such that
    the viscous force at the run's peak speed is 10-40 % of F_max;
  - noise (white): load cell 0.2-0.5 % of F_max, displacement 1-5 um.
The effects are sized for the 1.5 kN class: on a random damper their forces (and the heat capacity
of thermal_drift) scale with F_max / 1500 N, and the air's threshold and the bump stop with the
run's peak displacement, so that a size is as visible on a 100 kN damper as on the 1 kN one.

Profiles (motion; current):
  table4     20 mm sine at 0.5 Hz; Table 4's schedule of current against |x| (times I_max);
  telegraph  a sum of sines 0.1-5 Hz, 20 mm; the current switches 0 / I_max (mean dwell 50 ms);
  beyond     1 Hz sine, every reversal at 18-20 mm; Table 4's schedule;
  random     a sum of 12 sines, 0.1-3 Hz log-uniform, random phases, peak 5-40 mm; the current
             steps between random levels in [0, I_max] (15 % each 0 and I_max), dwell 0.1-1 s;
  mixed      a 0.3-1 Hz sine whose amplitude moves (0.5 s raised-cosine ramps) between 3-4 levels
             of 5-40 mm; Table 4's schedule scaled to the amplitude of the moment.
Writes the project's recorded-run CSV (time_s, displacement_mm, current_A, force_N,
velocity_mm_s) and a JSON manifest of the truth (with --damper random: every drawn value).
  damper_truth.py --damper fixed|random --seed N --profile table4|telegraph|beyond|random|mixed
                  --duration S --effect NAME:SIZE ... --out run.csv --manifest run.json
"""
import argparse, json, math, sys

import numpy as np

MU0 = 4e-7 * math.pi
RATE = 1000.0
# The 1 kN class's magnitudes: 400 turns over 40 mm, a yield force of about 1.4 kN at 1 A, c0 850 N s/m.
TURNS_PER_M = 400.0 / 0.04
JA = dict(Ms=1.3e6, a=2000.0, alpha=1e-3, k=1500.0, c=0.2)
F_YIELD_MAX = 1500.0   # [N] at saturation
B_SAT = 0.9            # [T] of the tanh yield law
C0 = 850.0             # [N s/m]
V0 = 2e-3              # [m/s] of the atan sign smoothing
AMPLITUDE = 0.020      # [m]
SCHEDULE = ([0.0025, 0.005, 0.010, 0.015, 0.020], [0.0, 0.15, 0.3, 0.5, 0.7, 1.0])
NOISE_X, NOISE_F = 2e-6, 2.0
HEAT_CAPACITY = 20.0   # [J/K] of the fluid that heats (thermal_drift)
VISCOSITY_PER_K, YIELD_PER_K = 0.03, 0.004   # [1/K] at size 1

FIXED = dict(kind="fixed", material="fixed", ja=JA, I_max_A=1.0, turns_per_m=TURNS_PER_M, yield_law="tanh",
             F_max_N=F_YIELD_MAX, F_0_N=0.0, B_sat_T=B_SAT, sign="atan_fixed", v0_m_s=V0, fluid="bingham",
             c0_N_s_m=C0, n=1.0, force_noise_N=NOISE_F, displacement_noise_m=NOISE_X, field_step_A_m=5.0)

# The ranges of --damper random (see the docstring); (low, high) each.
MATERIALS = {
    "soft_steel": dict(Ms=(1.2e6, 1.7e6), a=(200.0, 1500.0), k=(100.0, 1500.0), c=(0.05, 0.5), alpha=(1e-4, 2e-3)),
    "hard_steel": dict(Ms=(1.0e6, 1.6e6), a=(1500.0, 6000.0), k=(2000.0, 8000.0), c=(0.05, 0.4), alpha=(1e-4, 3e-3)),
}
LOG_UNIFORM = ("a", "k", "alpha")
FEEDBACK_LIMIT = 0.8            # the largest alpha Ms / (3 a) drawn
I_MAX_A = (1.0, 3.0)
H_TOP_OVER_KNEE = (2.0, 20.0)  # H(I_max) / max(a, k)
TURNS_RANGE = (3e3, 6e4)
F_MAX_N = (1e3, 1e5)
F_0_SHARE = (0.0, 0.08)
POWER_EXPONENT = (0.4, 1.2)
B_REF_SHARE, B_SAT_SHARE = (0.6, 1.0), (0.4, 1.0)
YIELD_LAWS = ("power", "tanh")
SIGN_KINDS = ("tanh", "atan", "knee")
V0_RANGE = (0.5e-3, 10e-3)
FLOW_INDEX = (0.6, 1.4)
V_REF = 0.1
VISCOUS_SHARE = (0.1, 0.4)
NOISE_F_SHARE = (0.002, 0.005)
NOISE_X_RANGE = (1e-6, 5e-6)
DAMPER_STREAM = 0x6D7264  # keeps the damper's stream apart from the motion's and the noise's
PROFILES = ["table4", "telegraph", "beyond", "random", "mixed"]


def langevin(x):
    """L(x) = coth x - 1/x for one float (math, not numpy: J-A's Euler loop calls it per step)."""
    return x / 3.0 if abs(x) < 1e-4 else 1.0 / math.tanh(x) - 1.0 / x


def ja_induction(H, ja=JA, step=5.0):
    """B(t) for the field H(t) by Jiles-Atherton (Eq. 1-10 in its textbook form), explicit Euler on
    field steps of at most `step` A/m."""
    Ms, a, alpha, k, c = (ja[n] for n in ("Ms", "a", "alpha", "k", "c"))
    M = 0.0
    B = np.empty_like(H)
    h_prev = 0.0
    for i, h in enumerate(H):
        dh_total = h - h_prev
        n = max(1, int(math.ceil(abs(dh_total) / step)))
        dh = dh_total / n
        for _ in range(n):
            he = h_prev + alpha * M
            man = Ms * langevin(he / a)
            delta = 1.0 if dh >= 0 else -1.0
            dman = Ms * (1.0 / a) * (1.0 - (1.0 / math.tanh(he / a)) ** 2 + (a / he) ** 2) if abs(he / a) > 1e-4 else Ms / (3 * a)
            irr = (man - M) / (delta * k - alpha * (man - M))
            if (man - M) * dh < 0:
                irr = 0.0  # the irreversible part only moves towards the anhysteretic curve
            dm = ((1 - c) * irr + c * dman) / (1 - alpha * c * dman) * dh
            M += dm
            h_prev += dh
        B[i] = MU0 * (h + M)
    return B


def anhysteretic_induction(H, ja):
    """B on the anhysteretic curve at the field H: M = Ms L((H + alpha M) / a) by fixed-point
    iteration, a contraction while alpha Ms / (3 a) < 1."""
    M = 0.0
    for _ in range(200):
        M = ja["Ms"] * langevin((H + ja["alpha"] * M) / ja["a"])
    return MU0 * (H + M)


def draw_damper(seed):
    """A damper drawn from the documented ranges; the same seed gives the same damper."""
    rng = np.random.default_rng([seed, DAMPER_STREAM])
    uniform = lambda lo, hi: float(rng.uniform(lo, hi))  # noqa: E731
    log_uniform = lambda lo, hi: float(math.exp(rng.uniform(math.log(lo), math.log(hi))))  # noqa: E731
    material = ("soft_steel", "hard_steel")[int(rng.integers(2))]
    while True:
        ja = {n: (log_uniform if n in LOG_UNIFORM else uniform)(*MATERIALS[material][n])
              for n in ("Ms", "a", "k", "c", "alpha")}
        if ja["alpha"] * ja["Ms"] / (3 * ja["a"]) <= FEEDBACK_LIMIT:
            break
    I_max = uniform(*I_MAX_A)
    knee = max(ja["a"], ja["k"])
    turns = float(np.clip(log_uniform(*H_TOP_OVER_KNEE) * knee / I_max, *TURNS_RANGE))
    H_top = turns * I_max
    B_top = anhysteretic_induction(H_top, ja)  # the yield law's field scale
    law = YIELD_LAWS[int(rng.integers(len(YIELD_LAWS)))]
    if law == "power":
        shape = dict(p=uniform(*POWER_EXPONENT), B_ref_T=B_top * uniform(*B_REF_SHARE))
    else:
        shape = dict(B_sat_T=B_top * uniform(*B_SAT_SHARE))
    F_max = log_uniform(*F_MAX_N)
    d = dict(kind="random", material=material, ja=ja, I_max_A=I_max, turns_per_m=turns, H_top_A_m=H_top,
             H_top_over_knee=H_top / knee, B_top_T=B_top, yield_law=law, **shape,
             F_max_N=F_max, F_0_N=F_max * uniform(*F_0_SHARE),
             sign=SIGN_KINDS[int(rng.integers(len(SIGN_KINDS)))], v0_m_s=log_uniform(*V0_RANGE),
             fluid="herschel_bulkley", n=uniform(*FLOW_INDEX), v_ref_m_s=V_REF,
             viscous_share=uniform(*VISCOUS_SHARE), force_noise_N=F_max * uniform(*NOISE_F_SHARE),
             displacement_noise_m=uniform(*NOISE_X_RANGE),
             # Euler's error scales with the step over the material's field scales.
             field_step_A_m=max(5.0, min(ja["a"], ja["k"]) / 20.0))
    assert d["ja"] != JA
    return d


def yield_force(B, d):
    """The yield force of the damper d at the induction B: F_0 at B = 0, rising to F_max."""
    b = np.abs(B)
    if d["yield_law"] == "tanh":
        law = np.tanh(b / d["B_sat_T"])
    else:
        law = np.minimum((b / d["B_ref_T"]) ** d["p"], 1.0)
    return d["F_0_N"] + (d["F_max_N"] - d["F_0_N"]) * law


def sign_shape(v, kind, v0):
    """A smoothed sign(v); every kind but the fixed damper's has slope 1/v0 at rest."""
    u = v / v0
    if kind == "tanh":
        return np.tanh(u)
    if kind == "atan":
        return 2 / np.pi * np.arctan(np.pi / 2 * u)
    if kind == "knee":
        return u / (1 + np.abs(u) ** 8) ** (1 / 8)
    return 2 / np.pi * np.arctan(v / v0)  # atan_fixed: the 1 kN class's, slope 2 / (pi v0)


def viscous_force(v, c0, d):
    if d["fluid"] == "bingham":
        return c0 * v
    return c0 * V_REF * np.sign(v) * np.abs(v / V_REF) ** d["n"]


def smooth_steps(t, levels, width):
    """Piecewise-constant levels over equal spans of t, joined by raised-cosine ramps of `width`
    centred on the span boundaries (so that x = level sin(w t) keeps a continuous velocity)."""
    span = (t[-1] + 1.0 / RATE) / len(levels)
    out = np.full_like(t, levels[0])
    for j in range(1, len(levels)):
        s = np.clip((t - j * span) / width + 0.5, 0.0, 1.0)
        out += (levels[j] - levels[j - 1]) * (0.5 - 0.5 * np.cos(np.pi * s))
    return out


def motion(profile, t, rng):
    """The displacement, the amplitude Table 4's schedule is scaled to, and what was drawn."""
    if profile == "table4":
        return AMPLITUDE * np.sin(2 * np.pi * 0.5 * t), AMPLITUDE, dict(amplitude_mm=20.0, frequency_Hz=0.5)
    if profile == "beyond":  # every reversal at 18-20 mm
        x = AMPLITUDE * (0.95 + 0.05 * np.sin(2 * np.pi * 0.13 * t)) * np.sin(2 * np.pi * 1.0 * t)
        return x, AMPLITUDE, dict(amplitude_mm=19.0, frequency_Hz=1.0)
    if profile == "telegraph":  # a sum of sines 0.1-5 Hz with random phases, scaled to the amplitude
        f = np.linspace(0.1, 5.0, 25)
        x = sum(np.sin(2 * np.pi * fi * t + rng.uniform(0, 2 * np.pi)) / (1 + fi) for fi in f)
        return AMPLITUDE * x / np.max(np.abs(x)), AMPLITUDE, dict(amplitude_mm=20.0)
    if profile == "random":
        peak = rng.uniform(0.005, 0.040)
        f = np.sort(np.exp(rng.uniform(math.log(0.1), math.log(3.0), 12)))
        phase = rng.uniform(0, 2 * np.pi, 12)
        x = sum(np.sin(2 * np.pi * fi * t + ph) / (1 + fi) for fi, ph in zip(f, phase))
        return peak * x / np.max(np.abs(x)), AMPLITUDE, dict(
            peak_mm=1e3 * peak, frequencies_Hz=f.tolist(), phases_rad=phase.tolist())
    # mixed
    freq = rng.uniform(0.3, 1.0)
    levels = rng.uniform(0.005, 0.040, int(rng.integers(3, 5)))
    envelope = smooth_steps(t, levels, 0.5)
    return envelope * np.sin(2 * np.pi * freq * t), envelope, dict(
        frequency_Hz=freq, amplitude_levels_mm=(1e3 * levels).tolist())


def current(profile, x, t, rng, envelope=AMPLITUDE):
    """The current as a share of the top current, and the random profile's steps."""
    if profile == "telegraph":
        I = np.zeros_like(t)
        state, nxt = 0.0, 0.0
        for i, ti in enumerate(t):
            if ti >= nxt:
                state = 1.0 - state
                nxt = ti + rng.exponential(0.05)
            I[i] = state
        return I, {}
    if profile == "random":
        I, steps, start = np.zeros_like(t), [], 0.0
        while start < t[-1] + 1.0 / RATE:
            r = rng.uniform()
            level = 0.0 if r < 0.15 else 1.0 if r < 0.3 else rng.uniform()
            steps.append([start, level])
            I[t >= start] = level
            start += rng.uniform(0.1, 1.0)
        return I, dict(current_steps_s_share=steps)
    thresholds, currents = SCHEDULE
    if profile == "mixed":  # the schedule's thresholds move with the amplitude
        reached = np.abs(x)[:, None] >= np.asarray(thresholds)[None, :] * (envelope / AMPLITUDE)[:, None]
        return np.asarray(currents)[reached.sum(axis=1)], {}
    return np.array([currents[int(np.searchsorted(thresholds, abs(xi), side="right"))] for xi in x]), {}


def first_order(u, tau):
    y = np.empty_like(u)
    acc = u[0] * 0.0
    g = 1.0 - math.exp(-1.0 / (RATE * tau))
    for i, ui in enumerate(u):
        acc += g * (ui - acc)
        y[i] = acc
    return y


def reversals_travel(x, threshold, reversal=1e-4):
    """For each sample: travel since the last reversal, and whether that reversal lay beyond the threshold."""
    travel = np.zeros_like(x)
    armed = np.zeros_like(x, dtype=bool)
    direction, extreme, rev, on = 0, x[0], x[0], False
    for i, xi in enumerate(x):
        if direction == 0:
            if abs(xi - extreme) > reversal:
                direction, extreme = (1 if xi > extreme else -1), xi
        elif (xi - extreme) * direction >= 0:
            extreme = xi
        elif (extreme - xi) * direction > reversal:
            rev, on, direction, extreme = extreme, abs(extreme) > threshold, -direction, xi
        travel[i], armed[i] = abs(xi - rev), on
    return travel, armed


def adiabatic_heating(yield_part, viscous_part, v, size, heat_capacity=HEAT_CAPACITY):
    """The fluid's temperature rise from the power it dissipates, C dT/dt = F v, by explicit Euler,
    and the factors it puts on the two parts: c0 / (1 + b dT) and tau_y (1 - c dT)."""
    b, c = VISCOSITY_PER_K * size, YIELD_PER_K * size
    f_visc, f_yield = np.ones_like(v), np.ones_like(v)
    rise = 0.0
    for i in range(len(v)):
        f_visc[i], f_yield[i] = 1.0 / (1.0 + b * rise), max(1.0 - c * rise, 0.05)
        power = (f_yield[i] * yield_part[i] + f_visc[i] * viscous_part[i]) * v[i]
        rise += max(power, 0.0) / heat_capacity / RATE
    return f_visc, f_yield


def bouc_wen(v, x_scale):
    """Spencer's z: dz/dt = -gamma |v| z |z|^(n-1) - beta v |z|^n + A v, n = 2."""
    A, n = 1.0, 2
    gamma = beta = 1.0 / (2 * x_scale ** 2)
    z, out, dt = 0.0, np.empty_like(v), 1.0 / RATE / 20
    for i, vi in enumerate(v):
        for _ in range(20):
            z += dt * (-gamma * abs(vi) * z * abs(z) ** (n - 1) - beta * vi * abs(z) ** n + A * vi)
        out[i] = z
    return out


def simulate(args):
    """The run: t, measured x, current, measured force, velocity, effect sizes, and the truth
    (the damper with its run-dependent values filled in, the motion's draw)."""
    damper = dict(FIXED) if getattr(args, "damper", "fixed") == "fixed" else draw_damper(args.seed)
    fixed = damper["kind"] == "fixed"
    rng = np.random.default_rng(args.seed)
    t = np.arange(int(args.duration * RATE)) / RATE
    x, envelope, motion_info = motion(args.profile, t, rng)
    v = np.gradient(x, 1.0 / RATE)
    a = np.gradient(v, 1.0 / RATE)
    share, current_info = current(args.profile, x, t, rng, envelope)
    I = damper["I_max_A"] * share
    motion_info.update(current_info)
    effects = dict(e.split(":") for e in args.effect)
    size = {k: float(s) for k, s in effects.items()}
    if not fixed:
        peak_speed = float(np.max(np.abs(v)))
        damper["peak_speed_m_s"] = peak_speed
        damper["c0_N_s_m"] = (damper["viscous_share"] * damper["F_max_N"]
                              / (V_REF * (peak_speed / V_REF) ** damper["n"]))
    # The effects' constants are the 1.5 kN class's: scale forces to the damper, lengths to the stroke.
    scale = damper["F_max_N"] / F_YIELD_MAX
    reach = AMPLITUDE if fixed else float(np.max(np.abs(x)))
    air_threshold = 0.015 if fixed else 0.75 * reach
    H = damper["turns_per_m"] * I
    if "coil_lag" in size:
        H = first_order(H, 5.3e-3 * size["coil_lag"])
    B = ja_induction(H, damper["ja"], damper["field_step_A_m"])
    F_y = yield_force(B, damper)
    sign = sign_shape(v, damper["sign"], damper["v0_m_s"])
    c0 = damper["c0_N_s_m"] * (1 + 0.5 * size.get("field_viscosity", 0) * B / 1.3)
    yield_part, viscous_part, elastic_part = F_y * sign, viscous_force(v, c0, damper), 0.0
    if "preyield_hysteresis" in size:
        z = bouc_wen(v, 0.2e-3)
        yield_part = F_y * (0.8 * sign + 0.2 * z / 0.2e-3)
        elastic_part = 5e5 * scale * size["preyield_hysteresis"] * z
    if "thermal_drift" in size:
        f_visc, f_yield = adiabatic_heating(yield_part, viscous_part, v, size["thermal_drift"],
                                            HEAT_CAPACITY * scale)
        yield_part, viscous_part = f_yield * yield_part, f_visc * viscous_part
    fluid = yield_part + viscous_part + elastic_part
    if "stroke_end_air" in size:
        travel, armed = reversals_travel(x, air_threshold)
        dead, ramp = 1.0e-3, 3.0e-3
        depth = min(0.45 * size["stroke_end_air"], 0.95)
        recovered = np.clip((travel - dead) / ramp, 0.0, 1.0)
        fluid = fluid * np.where(armed, 1.0 - depth * (1.0 - recovered), 1.0)
    F = fluid
    if "gas_spring" in size:
        F = F + scale * size["gas_spring"] * (70.0 + 500.0 * x)
    F = F + 50.0 * scale * size.get("moving_mass", 0) * a
    F = F + 40.0 * scale * size.get("coulomb_friction", 0) * np.tanh(v / 1e-3)
    F = F + 100.0 * scale * size.get("bump_stop", 0) * (x / reach) ** 3
    x_sensed = x
    if "sensor_delay" in size:
        shift = int(round(1.5e-3 * size["sensor_delay"] * RATE))
        x_sensed = np.concatenate([np.full(shift, x[0]), x[:-shift]]) if shift else x
    x_meas = x_sensed + rng.normal(0, damper["displacement_noise_m"], len(t))
    F_meas = (F + rng.normal(0, damper["force_noise_N"], len(t))
              + 30.0 * scale * size.get("mains_hum", 0) * np.sin(2 * np.pi * 50 * t))
    v_meas = np.gradient(x_sensed, 1.0 / RATE)
    truth = dict(damper=damper, motion=motion_info, effect_force_scale=scale)
    return t, x_meas, I, F_meas, v_meas, size, truth


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--profile", default="table4", choices=PROFILES)
    p.add_argument("--damper", default="fixed", choices=["fixed", "random"],
                   help="fixed: the 1 kN class; random: drawn from the ranges above by --seed")
    p.add_argument("--duration", type=float, default=6.0)
    p.add_argument("--effect", action="append", default=[], help="NAME:SIZE, repeatable")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--rate", type=float, default=RATE,
                   help="sample rate [Hz]; a finer run lets a logger's jitter pick real samples "
                        "(tools/residual/logger-faults.sh)")
    p.add_argument("--out", required=True)
    p.add_argument("--manifest")
    return p.parse_args(argv)


def main():
    global RATE
    args = parse_args()
    RATE = args.rate
    t, x, I, F, v, size, truth = simulate(args)
    with open(args.out, "w") as f:
        f.write("time_s,displacement_mm,current_A,force_N,velocity_mm_s\n")
        for row in zip(t, x * 1e3, I, F, v * 1e3):
            f.write(",".join(f"{val:.9g}" for val in row) + "\n")
    if args.manifest:
        manifest = {"generator": "tests/generator/damper_truth.py", "profile": args.profile,
                    "duration_s": args.duration, "seed": args.seed, "effects": size, "force_noise_N": truth["damper"]["force_noise_N"]}
        if args.damper == "random":  # the fixed damper's manifest stays as it always was
            manifest.update(damper_kind="random", **truth)
        with open(args.manifest, "w") as f:
            json.dump(manifest, f, indent=2)


if __name__ == "__main__":
    sys.exit(main())
