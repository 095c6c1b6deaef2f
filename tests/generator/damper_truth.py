#!/usr/bin/env python3
"""An independent truth generator for mrd-residual: a simulated 1 kN MR damper test run, written
from the physics with numpy alone and sharing no code with the fitter (which runs model::Observer).
Its forms differ on purpose from sim::DamperPlant's:
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
Writes the project's recorded-run CSV (time_s, displacement_mm, current_A, force_N,
velocity_mm_s) and a JSON manifest of the truth.
  damper_truth.py --profile table4|telegraph|beyond --duration S --effect NAME:SIZE ... --out run.csv
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


def langevin(x):
    x = np.asarray(x, dtype=float)
    small = np.abs(x) < 1e-4
    safe = np.where(small, 1.0, x)
    return np.where(small, x / 3.0, 1.0 / np.tanh(safe) - 1.0 / safe)


def ja_induction(H):
    """B(t) for the field H(t) by Jiles-Atherton (Eq. 1-10 in its textbook form), explicit Euler on
    steps of at most 5 A/m."""
    Ms, a, alpha, k, c = (JA[n] for n in ("Ms", "a", "alpha", "k", "c"))
    M = 0.0
    B = np.empty_like(H)
    h_prev = 0.0
    for i, h in enumerate(H):
        dh_total = h - h_prev
        n = max(1, int(math.ceil(abs(dh_total) / 5.0)))
        dh = dh_total / n
        for _ in range(n):
            he = h_prev + alpha * M
            man = Ms * float(langevin(he / a))
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


def motion(profile, t, rng):
    if profile == "table4":
        return AMPLITUDE * np.sin(2 * np.pi * 0.5 * t)
    if profile == "beyond":  # every reversal at 18-20 mm
        return AMPLITUDE * (0.95 + 0.05 * np.sin(2 * np.pi * 0.13 * t)) * np.sin(2 * np.pi * 1.0 * t)
    # telegraph: a sum of sines 0.1-5 Hz with random phases, scaled to the amplitude
    f = np.linspace(0.1, 5.0, 25)
    x = sum(np.sin(2 * np.pi * fi * t + rng.uniform(0, 2 * np.pi)) / (1 + fi) for fi in f)
    return AMPLITUDE * x / np.max(np.abs(x))


def current(profile, x, t, rng):
    if profile == "telegraph":
        I = np.zeros_like(t)
        state, nxt = 0.0, 0.0
        for i, ti in enumerate(t):
            if ti >= nxt:
                state = 1.0 - state
                nxt = ti + rng.exponential(0.05)
            I[i] = state
        return I
    thresholds, currents = SCHEDULE
    return np.array([currents[int(np.searchsorted(thresholds, abs(xi), side="right"))] for xi in x])


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


def adiabatic_heating(yield_part, viscous_part, v, size):
    """The fluid's temperature rise from the power it dissipates, C dT/dt = F v, by explicit Euler,
    and the factors it puts on the two parts: c0 / (1 + b dT) and tau_y (1 - c dT)."""
    b, c = VISCOSITY_PER_K * size, YIELD_PER_K * size
    f_visc, f_yield = np.ones_like(v), np.ones_like(v)
    rise = 0.0
    for i in range(len(v)):
        f_visc[i], f_yield[i] = 1.0 / (1.0 + b * rise), max(1.0 - c * rise, 0.05)
        power = (f_yield[i] * yield_part[i] + f_visc[i] * viscous_part[i]) * v[i]
        rise += max(power, 0.0) / HEAT_CAPACITY / RATE
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
    rng = np.random.default_rng(args.seed)
    t = np.arange(int(args.duration * RATE)) / RATE
    x = motion(args.profile, t, rng)
    v = np.gradient(x, 1.0 / RATE)
    a = np.gradient(v, 1.0 / RATE)
    I = current(args.profile, x, t, rng)
    effects = dict(e.split(":") for e in args.effect)
    size = {k: float(s) for k, s in effects.items()}
    H = TURNS_PER_M * I
    if "coil_lag" in size:
        H = first_order(H, 5.3e-3 * size["coil_lag"])
    B = ja_induction(H)
    F_y = F_YIELD_MAX * np.tanh(B / B_SAT)
    sign = 2 / np.pi * np.arctan(v / V0)
    c0 = C0 * (1 + 0.5 * size.get("field_viscosity", 0) * B / 1.3)
    yield_part, viscous_part, elastic_part = F_y * sign, c0 * v, 0.0
    if "preyield_hysteresis" in size:
        z = bouc_wen(v, 0.2e-3)
        yield_part = F_y * (0.8 * sign + 0.2 * z / 0.2e-3)
        elastic_part = 5e5 * size["preyield_hysteresis"] * z
    if "thermal_drift" in size:
        f_visc, f_yield = adiabatic_heating(yield_part, viscous_part, v, size["thermal_drift"])
        yield_part, viscous_part = f_yield * yield_part, f_visc * viscous_part
    fluid = yield_part + viscous_part + elastic_part
    if "stroke_end_air" in size:
        travel, armed = reversals_travel(x, 0.015)
        dead, ramp = 1.0e-3, 3.0e-3
        depth = min(0.45 * size["stroke_end_air"], 0.95)
        recovered = np.clip((travel - dead) / ramp, 0.0, 1.0)
        fluid = fluid * np.where(armed, 1.0 - depth * (1.0 - recovered), 1.0)
    F = fluid
    if "gas_spring" in size:
        F = F + size["gas_spring"] * (70.0 + 500.0 * x)
    F = F + 50.0 * size.get("moving_mass", 0) * a
    F = F + 40.0 * size.get("coulomb_friction", 0) * np.tanh(v / 1e-3)
    F = F + 100.0 * size.get("bump_stop", 0) * (x / 0.02) ** 3
    x_sensed = x
    if "sensor_delay" in size:
        shift = int(round(1.5e-3 * size["sensor_delay"] * RATE))
        x_sensed = np.concatenate([np.full(shift, x[0]), x[:-shift]]) if shift else x
    x_meas = x_sensed + rng.normal(0, NOISE_X, len(t))
    F_meas = F + rng.normal(0, NOISE_F, len(t)) + 30.0 * size.get("mains_hum", 0) * np.sin(2 * np.pi * 50 * t)
    v_meas = np.gradient(x_sensed, 1.0 / RATE)
    return t, x_meas, I, F_meas, v_meas, size


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--profile", default="table4", choices=["table4", "telegraph", "beyond"])
    p.add_argument("--duration", type=float, default=6.0)
    p.add_argument("--effect", action="append", default=[], help="NAME:SIZE, repeatable")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--out", required=True)
    p.add_argument("--manifest")
    args = p.parse_args()
    t, x, I, F, v, size = simulate(args)
    with open(args.out, "w") as f:
        f.write("time_s,displacement_mm,current_A,force_N,velocity_mm_s\n")
        for row in zip(t, x * 1e3, I, F, v * 1e3):
            f.write(",".join(f"{val:.9g}" for val in row) + "\n")
    if args.manifest:
        json.dump({"generator": "tests/generator/damper_truth.py", "profile": args.profile, "duration_s": args.duration,
                   "seed": args.seed, "effects": size, "force_noise_N": NOISE_F}, open(args.manifest, "w"), indent=2)


if __name__ == "__main__":
    sys.exit(main())
