#!/usr/bin/env python3
"""Writes a run file again as data loggers write it (issue 27, docs/CLOSING-THE-LOOP.md "Data as
loggers write it"): the unfaulted run, a gap of 0.05 s, 0.3 s and 2 s, 1 % of its rows written
twice, 5 empty cells, 3 rows whose time goes back, each sample taken up to 10 % or 30 % of a
period off its grid time, and a rig at its end stop.

Any delimited run: comma, semicolon or tab with a header, or blank-separated numbers without one
(Quiroz's tests); rows keep their text except the cells a fault changes. Prints the variants it
wrote, one name a line (a gap that would not leave 1 s of the run on either side is skipped).

Jitter: with --fine-every N the source is N times finer than the run it writes (every N-th row),
and a jittered sample is a neighbouring fine row, so every variant carries the same noise (what
tools/residual/logger-faults.sh does with a 10 kHz simulation). Without it the run is interpolated
linearly at the jittered times, which also averages the noise of neighbouring samples a little;
--held-columns (a switched current) keep the level of the period the time falls in.
"""
import argparse
import math
import os
import random
import re

GAPS_S = (0.05, 0.3, 2.0)
MIN_KEPT_S = 1.0  # of the run on either side of a gap
JITTER_PERCENT = (10, 30)


class Table:
    def __init__(self, path, drop_prefix):
        lines = [line.rstrip("\r\n") for line in open(path) if line.strip()]
        first = lines[0]
        self.delimiter = next((d for d in (";", ",", "\t") if d in first), None)
        cells = self.split(first)
        self.header = None if all(re.fullmatch(r"[-+0-9.eE]+", c) for c in cells) else cells
        self.rows = [self.split(line) for line in (lines if self.header is None else lines[1:])]
        if self.header and drop_prefix:
            keep = [i for i, h in enumerate(self.header) if not h.startswith(drop_prefix)]
            self.header = [self.header[i] for i in keep]
            self.rows = [[r[i] for i in keep] for r in self.rows]

    def split(self, line):
        return line.split(self.delimiter) if self.delimiter else line.split()

    def write(self, path, rows):
        joiner = self.delimiter or "  "
        with open(path, "w") as f:
            if self.header:
                f.write(joiner.join(self.header) + "\n")
            f.writelines(joiner.join(r) + "\n" for r in rows)

    def empty_cell(self):
        # A blank-separated file has no empty field: its logger writes nan.
        return "" if self.delimiter else "nan"


def number(cell):
    return float(cell.replace(",", "."))


def interpolated(rows, time, at, held=()):
    """The row at time `at`: linearly interpolated (every cell a number), but for the `held`
    columns, a command's steps, which read the value of the period `at` falls in (a row's value
    holds over the period that ends at it): sampled at any time, a switched current is one of
    its levels, never a blend of two."""
    i = max(1, min(len(time) - 1, next_index(time, at)))
    w = (at - time[i - 1]) / (time[i] - time[i - 1])
    row = [repr(number(a) + w * (number(b) - number(a))) for a, b in zip(rows[i - 1], rows[i])]
    for c in held:
        row[c] = rows[i - 1][c] if w <= 0.0 else rows[i][c]
    return row


def next_index(time, at):
    lo, hi = 0, len(time)
    while lo < hi:
        mid = (lo + hi) // 2
        if time[mid] <= at:
            lo = mid + 1
        else:
            hi = mid
    return lo


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("source")
    p.add_argument("out_dir")
    p.add_argument("--extension", help="of the files written (default: the source's)")
    p.add_argument("--time-column", type=int, default=0, help="0-based; its unit must be seconds")
    p.add_argument("--displacement-column", type=int, default=1, help="0-based")
    p.add_argument("--force-column", type=int, help="0-based; without it no end-stop variant")
    p.add_argument("--empty-column", type=int, default=1, help="0-based column of the empty cells")
    p.add_argument("--drop-columns", help="leave out the header's columns starting with this")
    p.add_argument("--fine-every", type=int, help="the source is this many times finer than the run")
    p.add_argument("--held-columns", type=int, nargs="*", default=[],
                   help="0-based columns of step signals (a switched current), held, not interpolated, "
                        "at a jittered time")
    p.add_argument("--seed", type=int, default=5)
    a = p.parse_args()
    os.makedirs(a.out_dir, exist_ok=True)
    extension = a.extension or os.path.splitext(a.source)[1]
    table = Table(a.source, a.drop_columns)
    fine = table.rows
    data = fine[:: a.fine_every] if a.fine_every else fine
    tc = a.time_column
    time = [number(r[tc]) for r in data]
    n = len(data)
    rate = (n - 1) / (time[-1] - time[0])
    written = []

    def write(name, rows):
        table.write(os.path.join(a.out_dir, name + extension), rows)
        written.append(name)

    write("clean", data)
    for seconds in GAPS_S:
        lost = int(round(seconds * rate))
        a_ = (n - lost) // 2
        if a_ < MIN_KEPT_S * rate:
            continue
        write(f"gap_{seconds:g}s", data[:a_] + data[a_ + lost:])
    # The draws keep the order they had in logger-faults.sh, so its simulated table reproduces.
    rng = random.Random(a.seed)
    twice = set(rng.sample(range(n), n // 100))
    write("duplicates_1pc", [r for i, r in enumerate(data) for _ in range(2 if i in twice else 1)])
    empty = list(data)
    for i in rng.sample(range(10, n - 10), 5):
        empty[i] = list(empty[i])
        empty[i][a.empty_column] = table.empty_cell()
    write("empty_cells_5", empty)
    back = list(data)
    for i in rng.sample(range(10, n - 10), 3):
        back[i] = list(back[i])
        back[i][tc] = repr(time[i - 5])
    write("time_back_3", back)
    for percent in JITTER_PERCENT:
        if a.fine_every:
            reach = round(percent / 100 * a.fine_every)
            picked, last = [], -1
            for i in range(0, len(fine), a.fine_every):
                j = min(max(i + rng.randint(-reach, reach), last + 1), len(fine) - 1)
                picked.append(fine[j])
                last = j
        else:
            period = 1.0 / rate
            picked = []
            for i, t in enumerate(time):
                at = t + percent / 100 * period * (2.0 * rng.random() - 1.0) if 0 < i < n - 1 else t
                row = interpolated(data, time, at, a.held_columns)
                row[tc] = repr(at)
                picked.append(row)
        write(f"jitter_{percent}pc", picked)
    if a.force_column is not None:
        write("end_stop_ringing", end_stop(data, time, a.displacement_column, a.force_column, rng))
    print("\n".join(written))


def end_stop(data, time, xc, fc, rng):
    """A rig at its end stop for 0.36 s from the run's middle: the LVDT jitters within 0.5 % of
    the stroke while the load cell rings at 25 Hz through both signs and clips at the run's peak."""
    xs = [number(r[xc]) for r in data]
    fs = [number(r[fc]) for r in data]
    stroke, peak = max(xs) - min(xs), max(abs(f) for f in fs)
    start = time[0] + 0.5 * (time[-1] - time[0])
    first = next(i for i, t in enumerate(time) if t >= start)
    stop = [list(r) for r in data]
    for i in range(first, len(data)):
        t = time[i] - start
        if t > 0.36:
            break
        stop[i][xc] = repr(xs[first] + 0.005 * stroke * (2.0 * rng.random() - 1.0))
        stop[i][fc] = repr(max(-peak, min(peak, 1.2 * peak * math.cos(2.0 * math.pi * 25.0 * t))))
    return stop


if __name__ == "__main__":
    main()
