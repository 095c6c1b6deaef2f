#!/usr/bin/env python3
"""Checks a tool's report.html against its JSON (tests/CMakeLists.txt, docs/CLOSING-THE-LOOP.md).

- The HTML parses with html.parser and every non-void element closes in order.
- There is one inline plot (<svg>, or <img> of an inline PNG) per plot script (*.gp) in the
  directory, at least --plots of them, and each SVG has drawn content.
- Each time chart (figure.mrd-chart) holds JSON whose x and series decode (base64: float32 and
  uint16) to the same number of points, at least --charts of them.
- Every cell with data-key names a path in the JSON (dots; numbers index arrays) whose number
  equals data-value to 1e-12 relative (null in the JSON for nan), at least --keys of them.
"""
import argparse
import base64
import glob
import json
import math
import os
import sys
from html.parser import HTMLParser

VOID = {"meta", "br", "img", "input", "link", "hr", "col", "area", "base", "wbr", "source",
        "path", "circle", "rect", "use", "line", "polyline", "polygon", "image", "stop", "ellipse"}


class Checker(HTMLParser):
    def __init__(self):
        super().__init__()
        self.stack, self.errors, self.svgs, self.cells = [], [], [], []
        self.svg_children = 0
        self.images, self.charts, self.in_chart_json = 0, [], False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "svg":
            self.svgs.append(0)
        elif self.svgs and tag in ("path", "text", "g"):
            self.svgs[-1] += 1
        if tag == "img" and (a.get("src") or "").startswith("data:image/png;base64,"):
            self.images += 1
        if tag == "figure" and "mrd-chart" in (a.get("class") or "").split():
            self.charts.append("")
        self.in_chart_json = tag == "script" and a.get("type") == "application/json" and bool(self.charts)
        if "data-key" in a:
            self.cells.append((a["data-key"], a.get("data-value")))
        if tag not in VOID:
            self.stack.append((tag, self.getpos()))

    def handle_startendtag(self, tag, attrs):
        if self.svgs and tag in ("path", "text", "g"):
            self.svgs[-1] += 1

    def handle_data(self, data):
        if self.in_chart_json:
            self.charts[-1] += data

    def handle_endtag(self, tag):
        self.in_chart_json = False
        if tag in VOID:
            return
        if not self.stack:
            self.errors.append(f"</{tag}> at {self.getpos()} closes nothing")
            return
        open_tag, where = self.stack.pop()
        if open_tag != tag:
            self.errors.append(f"<{open_tag}> opened at {where} closed by </{tag}> at {self.getpos()}")


def lookup(document, path):
    node = document
    for part in path.split("."):
        if isinstance(node, list):
            node = node[int(part)]
        else:
            node = node[part]
    return node


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("directory")
    ap.add_argument("json")
    ap.add_argument("--plots", type=int, default=1)
    ap.add_argument("--keys", type=int, default=1)
    ap.add_argument("--charts", type=int, default=0)
    a = ap.parse_args()
    html = open(os.path.join(a.directory, "report.html"), encoding="utf-8").read()
    document = json.load(open(a.json, encoding="utf-8"))
    c = Checker()
    c.feed(html)
    c.close()
    errors = list(c.errors)
    if c.stack:
        errors.append(f"unclosed: {c.stack[:5]}")
    scripts = glob.glob(os.path.join(a.directory, "*.gp"))
    plots = len(c.svgs) + c.images
    if plots != len(scripts):
        errors.append(f"{plots} inline plots for {len(scripts)} plot scripts")
    if plots < a.plots:
        errors.append(f"{plots} inline plots, expected at least {a.plots}")
    for i, text in enumerate(c.charts):
        try:
            chart = json.loads(text)
            points = len(base64.b64decode(chart["x"])) // 4
            lengths = [len(base64.b64decode(s["q"])) // 2 for s in chart["series"]]
            if points < 2 or not lengths or any(n != points for n in lengths):
                errors.append(f"chart {i}: {points} x values, series of {lengths}")
        except (ValueError, KeyError, TypeError) as e:
            errors.append(f"chart {i}: {e}")
    if len(c.charts) < a.charts:
        errors.append(f"{len(c.charts)} time charts, expected at least {a.charts}")
    errors += [f"svg {i} draws nothing" for i, n in enumerate(c.svgs) if n < 5]
    matched = 0
    for key, value in c.cells:
        try:
            expected = lookup(document, key)
        except (KeyError, IndexError, ValueError, TypeError):
            errors.append(f"data-key {key} is not in the JSON")
            continue
        if expected is None:
            if value != "nan":
                errors.append(f"{key}: JSON null, report {value}")
            matched += 1
            continue
        shown = float(value)
        if not math.isclose(shown, float(expected), rel_tol=1e-12, abs_tol=1e-300):
            errors.append(f"{key}: JSON {expected!r}, report {value}")
        matched += 1
    if matched < a.keys:
        errors.append(f"{matched} figures matched the JSON, expected at least {a.keys}")
    for e in errors:
        print("check_report:", e)
    print(f"check_report: {len(c.svgs)} svg, {c.images} png, {len(c.charts)} charts, {matched} figures checked against {a.json}, {len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
