#!/usr/bin/env python3
"""What resampling a jittered log costs before any model is fitted (docs/CLOSING-THE-LOOP.md,
"Data as loggers write it"). The independent generator's telegraph run (tests/generator/
damper_truth.py, coil_lag:2, 8 s) at 10 kHz without noise; rows taken every tenth fine sample, or
a neighbouring fine sample up to 10 % or 30 % of a period off as inject_logger_faults.py
--fine-every 10 picks them; the jittered rows put back on the even grid by linear interpolation,
as record::resample_on_even_grid does; printed: each channel's RMS and largest difference from
the even rows. A model that is evaluated on the grid can do no better than the force's figure.
Usage: tools/residual/jitter_floor.py [--seed N]
"""
import argparse
import os
import random
import sys
import types

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "generator"))
import damper_truth  # noqa: E402

FINE = 10


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--seed", type=int, default=5, help="of the jitter's draw")
    a = p.parse_args()
    damper_truth.RATE = 1000.0 * FINE
    damper_truth.FIXED.update(force_noise_N=0.0, displacement_noise_m=0.0)
    run = types.SimpleNamespace(profile="telegraph", duration=8.0, effect=["coil_lag:2"], seed=1, damper="fixed")
    t, x, current, force, _, _, _ = damper_truth.simulate(run)
    even = np.arange(0, len(t), FINE)
    rng = random.Random(a.seed)
    print("| jitter | force RMS [N] | force max [N] | current RMS [A] | displacement RMS [m] |")
    print("|---|---:|---:|---:|---:|")
    for percent in (10, 30):
        reach, picked, last = round(percent / 100 * FINE), [], -1
        for i in even:
            last = min(max(i + rng.randint(-reach, reach), last + 1), len(t) - 1)
            picked.append(last)
        picked = np.array(picked)
        error = {name: np.interp(t[even], t[picked], channel[picked]) - channel[even]
                 for name, channel in (("force", force), ("current", current), ("x", x))}
        rms = {name: np.sqrt(np.mean(e ** 2)) for name, e in error.items()}
        print(f"| {percent} % | {rms['force']:.3g} | {np.max(np.abs(error['force'])):.3g} | {rms['current']:.3g} | "
              f"{rms['x']:.3g} |")


if __name__ == "__main__":
    main()
