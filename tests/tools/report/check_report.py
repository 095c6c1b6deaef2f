#!/usr/bin/env python3
"""Checks a tool's report.html against its JSON (tests/CMakeLists.txt, docs/CLOSING-THE-LOOP.md).

- The HTML parses with html.parser and every non-void element closes in order.
- There is one inline <svg> per plot script (*.gp) in the directory, at least --plots of them,
  and each has drawn content.
- Every cell with data-key names a path in the JSON (dots; numbers index arrays) whose number
  equals data-value to 1e-12 relative (null in the JSON for nan), at least --keys of them.
"""
import argparse
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

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "svg":
            self.svgs.append(0)
        elif self.svgs and tag in ("path", "text", "g"):
            self.svgs[-1] += 1
        if "data-key" in a:
            self.cells.append((a["data-key"], a.get("data-value")))
        if tag not in VOID:
            self.stack.append((tag, self.getpos()))

    def handle_startendtag(self, tag, attrs):
        if self.svgs and tag in ("path", "text", "g"):
            self.svgs[-1] += 1

    def handle_endtag(self, tag):
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
    if len(c.svgs) != len(scripts):
        errors.append(f"{len(c.svgs)} inline <svg> for {len(scripts)} plot scripts")
    if len(c.svgs) < a.plots:
        errors.append(f"{len(c.svgs)} inline <svg>, expected at least {a.plots}")
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
    print(f"check_report: {len(c.svgs)} svg, {matched} figures checked against {a.json}, {len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
