#!/usr/bin/env python3
"""Writes the formats fixtures: one short synthetic damper run as the comma CSV (the reference),
as semicolons with decimal commas, CRLF and a byte-order mark, as tabs, and as a MATLAB v5 .mat
file laid out byte by byte here (no libmatio), the way MATLAB's `save` writes one: a 1xN time row
vector, an Nx3 matrix [x F I], a sample rate stored as uint16 data in a double, a char array.
run_v73.mat is written by libmatio (tests/record/test_run_mat.cpp checks it against run.csv).
usage: make_fixtures.py [DIR]"""
import math
import struct
import sys

out = sys.argv[1] if len(sys.argv) > 1 else "."
N, RATE = 300, 500.0
t = [i / RATE for i in range(N)]
x = [10.0 * math.sin(2 * math.pi * 2.0 * ti) for ti in t]  # mm
v = [10e-3 * 2 * math.pi * 2.0 * math.cos(2 * math.pi * 2.0 * ti) for ti in t]  # m/s
F = [round(800.0 * math.tanh(vi / 0.02) + 2000.0 * vi + 5.0 * math.sin(37.0 * i), 6) for i, vi in enumerate(v)]
I = [0.5] * N
rows = list(zip(t, x, F, I))


def text(delimiter, eol, decimal_comma=False, bom=""):
    def cell(value):
        s = repr(value)
        return s.replace(".", ",") if decimal_comma else s
    lines = [delimiter.join(["t", "x", "F", "I"])] + [delimiter.join(cell(v) for v in r) for r in rows]
    return bom + eol.join(lines) + eol


with open(f"{out}/run.csv", "w", newline="") as f:
    f.write(text(",", "\n"))
with open(f"{out}/run_semicolon.csv", "w", newline="", encoding="utf-8") as f:
    f.write(text(";", "\r\n", decimal_comma=True, bom="\ufeff"))
with open(f"{out}/run_tab.tsv", "w", newline="") as f:
    f.write(text("\t", "\r\n"))

# MAT-file level 5: a 128-byte header, then one miMATRIX element a variable.
miINT8, miUINT16, miINT32, miUINT32, miDOUBLE, miMATRIX = 1, 4, 5, 6, 9, 14
mxCHAR, mxDOUBLE = 4, 6


def element(kind, payload):
    if len(payload) <= 4:  # the small element format: type and size share the tag's first 4 bytes
        return struct.pack("<HH", kind, len(payload)) + payload.ljust(4, b"\0")
    return struct.pack("<II", kind, len(payload)) + payload + b"\0" * (-len(payload) % 8)


def matrix(name, cls, dims, data_type, data):
    body = element(miUINT32, struct.pack("<II", cls, 0))
    body += element(miINT32, struct.pack(f"<{len(dims)}i", *dims))
    body += element(miINT8, name.encode())
    body += element(data_type, data)
    return struct.pack("<II", miMATRIX, len(body)) + body


def doubles(values):
    return struct.pack(f"<{len(values)}d", *values)


header = b"MATLAB 5.0 MAT-file, Platform: GLNXA64, Created by tests/record/data/formats/make_fixtures.py"
header = header.ljust(116, b" ") + b"\0" * 8 + struct.pack("<H", 0x0100) + b"IM"
variables = [
    matrix("t", mxDOUBLE, [1, N], miDOUBLE, doubles(t)),
    matrix("data", mxDOUBLE, [N, 3], miDOUBLE, doubles(x + F + I)),  # column after column
    matrix("fs", mxDOUBLE, [1, 1], miUINT16, struct.pack("<H", int(RATE))),
    matrix("rig", mxCHAR, [1, 7], miUINT16, "MTS 810".encode("utf-16-le")),
]
with open(f"{out}/run_v5.mat", "wb") as f:
    f.write(header + b"".join(variables))
