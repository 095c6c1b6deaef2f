#!/usr/bin/env python3
"""Checks CSV files the tools write as pandas.read_csv(f, comment='#') reads them, with the
standard csv module alone (the smoke.csv_* tests in tests/CMakeLists.txt; docs/ARCHITECTURE.md,
"CSV outputs").

usage: check_csv_outputs.py [--text COLS] [--nan COLS] [--unitless COLS] [--blank-lines]
                            [--min-rows N] FILE...

For each file:
- Lines starting with '#' are comments, allowed only before the column line. A '#' anywhere
  else is refused: with comment='#' pandas drops the rest of that line.
- The first other line is the column line: each name non-empty, unique, without surrounding
  spaces, letters, digits and underscores starting with a letter.
- Each numeric column (not in --text) names its unit: the name ends in a unit suffix, as in
  time_s, force_N, force_kN, current_A, displacement_mm, velocity_mm_s, B_T, H_A_per_m,
  temperature_C (tokens after the quantity, each an SI symbol with an optional prefix and
  power, joined by '_' for a product and '_per_' for a quotient; '_s' after a length is per
  second, as the recorded-run format writes it). A pure number says what it is: its name ends in
  _scale, _factor, _ratio, _fraction, _percent or _count. Counts and 0/1 flags of a format
  others already read by name (the controller's telemetry: cycle, enable, ...) are named with
  --unitless in the test that checks them.
- Every row has exactly as many fields as the column line (no ragged row, no trailing
  delimiter; pandas would otherwise shift a column into the index or fill NaN silently).
- Every cell of a numeric column is a decimal number (what pandas parses as a float: no
  '1_000', no spaces) and finite. 'nan' (or '-nan', as printf writes a negative NaN) only in
  --nan columns: a column the tool documents as carrying it. Text cells are non-empty and not
  one of pandas's missing-value words ('NA', 'None', 'null', ...), which it reads as NaN.
- Blank lines (pandas skips them) only with --blank-lines, and only after the column line.
- At least --min-rows rows (default 1).
- Each column whose name starts with 'time' strictly increases.

Exits 1 on the first failure with FILE:LINE: column 'NAME': what (2 for a usage error); on
success prints one line per file.
"""
import argparse
import csv
import math
import re
import sys

PREFIXES = ["", "n", "u", "m", "c", "k", "M", "G"]
# SI base and derived units, and the few others the SI accepts: C is the coulomb and, in a
# temperature's name (temperature_C), the degree Celsius, as the recorded-run format reads it.
SYMBOLS = ["s", "m", "g", "A", "K", "Hz", "N", "Pa", "J", "W", "C", "V", "F", "Ohm", "S", "Wb", "T",
           "H", "rad", "deg", "degC", "min", "h", "L", "bar"]
UNIT_TOKEN = re.compile("^(" + "|".join(re.escape(p) for p in PREFIXES if p) + ")?(" +
                        "|".join(sorted((re.escape(s) for s in SYMBOLS), key=len, reverse=True)) +
                        ")[23]?$")
DIMENSIONLESS = ["scale", "factor", "ratio", "fraction", "percent", "count"]
NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")
NUMBER = re.compile(r"^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$")
NAN_WORDS = {"nan", "-nan"}
# pandas.read_csv's default na_values: a text cell equal to one of these reads as NaN.
PANDAS_MISSING = {"", "#N/A", "#N/A N/A", "#NA", "-1.#IND", "-1.#QNAN", "-NaN", "-nan", "1.#IND",
                  "1.#QNAN", "<NA>", "N/A", "NA", "NULL", "NaN", "None", "n/a", "nan", "null"}


class Failure(Exception):
    pass


def unit_of(name):
    """The unit suffix of a column name ('mm_s' for velocity_mm_s, 'A_per_m' for H_A_per_m), or None."""
    tokens = name.split("_")
    unit = []
    # Keep at least one token for the quantity: H_A_per_m is H in A/m, not henry.
    while len(tokens) > 1 and (UNIT_TOKEN.match(tokens[-1]) or tokens[-1] == "per"):
        unit.insert(0, tokens.pop())
    while unit and unit[0] == "per":  # 'per' needs a unit on each side
        tokens.append(unit.pop(0))
    if not unit or unit[-1] == "per" or "_per_per_" in "_" + "_".join(unit) + "_":
        return None
    return "_".join(unit)


def check_unit(name):
    if name.split("_")[-1] in DIMENSIONLESS and "_" in name:
        return "1"
    return unit_of(name)


def columns(option):
    return [c for c in (option or "").split(",") if c]


def check_file(path, args):
    where = lambda line, column=None: f"{path}:{line}:" + (f" column '{column}':" if column else "")
    try:
        with open(path, newline="", encoding="utf-8") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError) as e:
        raise Failure(f"{path}: cannot read: {e}")
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()  # the last line's newline
    header = None
    names = []
    rows = comments = blanks = 0
    text_columns, nan_columns, unitless = columns(args.text), columns(args.nan), columns(args.unitless)
    times = {}  # time column index -> (last value, its line)
    for number, raw in enumerate(lines, start=1):
        line = raw[:-1] if raw.endswith("\r") else raw
        if line.startswith("#"):
            if header is not None:
                raise Failure(f"{where(number)} a comment after the column line (line {header}): comments "
                              "belong before it")
            comments += 1
            continue
        if line == "":
            if header is None or not args.blank_lines:
                raise Failure(f"{where(number)} a blank line" +
                              ("" if header is None else " (pandas skips it; --blank-lines if the tool writes "
                               "it on purpose)"))
            blanks += 1
            continue
        if "#" in line:
            raise Failure(f"{where(number)} '#' inside a line: pandas.read_csv(comment='#') drops the rest "
                          f"of the line from column {line.index('#') + 1} on")
        fields = next(csv.reader([line]))
        if header is None:
            header = number
            names = fields
            seen = set()
            for name in names:
                if name == "" or name.strip() == "":
                    raise Failure(f"{where(number)} an empty column name (field {len(seen) + 1}" +
                                  (", a trailing delimiter" if len(seen) + 1 == len(names) else "") + ")")
                if name != name.strip():
                    raise Failure(f"{where(number, name)} spaces around the name")
                if not NAME.match(name):
                    raise Failure(f"{where(number, name)} not a name of letters, digits and underscores "
                                  "starting with a letter")
                if name in seen:
                    raise Failure(f"{where(number, name)} the name comes twice")
                seen.add(name)
            for option, given in (("--text", text_columns), ("--nan", nan_columns), ("--unitless", unitless)):
                for name in given:
                    if name not in seen:
                        raise Failure(f"{where(number)} {option} names '{name}', not a column of the file")
            for name in names:
                if name in text_columns or name in unitless:
                    continue
                if check_unit(name) is None:
                    raise Failure(f"{where(number, name)} a numeric column without a unit suffix (time_s, "
                                  "force_N, velocity_mm_s, ...; a pure number ends in _" +
                                  ", _".join(DIMENSIONLESS) + ")")
            times = {i: None for i, name in enumerate(names) if name.startswith("time")}
            continue
        if len(fields) != len(names):
            # Short: the first column with no field; long: the first field past the last column,
            # by its number (as the recorded-run reader names it).
            column = names[len(fields)] if len(fields) < len(names) else str(len(names) + 1)
            raise Failure(f"{where(number, column)} ragged row: {len(fields)} fields, but the column line "
                          f"(line {header}) has {len(names)}" +
                          (" (a trailing delimiter)" if len(fields) == len(names) + 1 and fields[-1] == "" else ""))
        rows += 1
        for i, (name, cell) in enumerate(zip(names, fields)):
            if name in text_columns:
                if cell in PANDAS_MISSING:
                    raise Failure(f"{where(number, name)} text cell '{cell}' reads as missing (NaN) in pandas")
                continue
            if cell in NAN_WORDS and name in nan_columns:
                continue
            word = cell.strip().lower().lstrip("+-")
            if word == "nan":
                raise Failure(f"{where(number, name)} '{cell}' in a column not documented to carry nan (--nan)")
            if word in ("inf", "infinity"):
                raise Failure(f"{where(number, name)} '{cell}' is not finite")
            if not NUMBER.match(cell):
                raise Failure(f"{where(number, name)} '{cell}' is not a number")
            value = float(cell)
            if not math.isfinite(value):
                raise Failure(f"{where(number, name)} '{cell}' is not finite (overflows a double)")
            if i in times:
                last = times[i]
                if last is not None and not value > last[0]:
                    raise Failure(f"{where(number, name)} time {cell} does not increase (line {last[1]}: "
                                  f"{last[0]:g})")
                times[i] = (value, number)
    if header is None:
        raise Failure(f"{path}: no column line")
    if rows < args.min_rows:
        raise Failure(f"{where(header)} {rows} rows, fewer than --min-rows {args.min_rows}")
    units = ", ".join(f"{n} [{check_unit(n)}]" for n in names if n not in text_columns and n not in unitless)
    span = "".join(f"; {names[i]} to {v[0]:g}" for i, v in times.items() if v)
    print(f"{path}: ok, {rows} rows x {len(names)} columns, {comments} comment and {blanks} blank lines{span}; "
          f"units: {units}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("files", nargs="+", metavar="FILE")
    parser.add_argument("--text", metavar="COL[,COL]", help="columns that hold text")
    parser.add_argument("--nan", metavar="COL[,COL]", help="numeric columns documented to carry nan")
    parser.add_argument("--unitless", metavar="COL[,COL]",
                        help="numeric columns that are counts or flags of an established format")
    parser.add_argument("--blank-lines", action="store_true", help="allow blank lines between rows")
    parser.add_argument("--min-rows", type=int, default=1, metavar="N")
    args = parser.parse_args()
    try:
        for path in args.files:
            check_file(path, args)
    except Failure as e:
        print(f"check_csv_outputs: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
