#!/usr/bin/env python3
"""Checks the examples' pictures (examples/common/plot.hpp) under the given folders.

PNG: a valid file (signature, chunk CRCs, zlib stream, one filter byte and
3 bytes per pixel per row) that has more than the field colours: a colour bar
and text. SVG: well-formed XML; the tick labels of each linear axis are round
(equally spaced by 1, 2 or 5 x 10^k, each a multiple of that step); a log
axis is labelled 10^k once per decade (consecutive exponents).
Usage: check_pictures.py DIR... (exit 1 with the reasons if a check fails)
"""
import math
import pathlib
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

SVG = "{http://www.w3.org/2000/svg}"


def check_png(path):
    data = path.read_bytes()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        return ["not a PNG signature"]
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        (crc,) = struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])
        if zlib.crc32(kind + body) != crc:
            return [f"bad CRC of chunk {kind!r}"]
        if kind == b"IHDR":
            width, height = struct.unpack(">II", body[:8])
            if body[8:10] != b"\x08\x02":
                return ["not 8-bit RGB"]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = 1 + 3 * width
    if len(raw) != height * stride:
        return [f"{len(raw)} bytes of pixels, expected {height} x {stride}"]
    if any(raw[r * stride] != 0 for r in range(height)):
        return ["unexpected row filter"]
    colours = {raw[r * stride + 1 + 3 * c:r * stride + 4 + 3 * c] for r in range(height)
               for c in range(width)}
    if len(colours) < 20 or b"\x00\x00\x00" not in colours:
        return [f"{len(colours)} colours, no black: no colour bar, axes or text"]
    return []


def number(text):
    try:
        return float(text.replace("\u2212", "-"))
    except ValueError:
        return None


def round_ticks(values):
    """Why `values` are not round linear ticks, or None."""
    if len(values) < 2:
        return f"{len(values)} tick label(s): {values}"
    step = values[1] - values[0]
    if step <= 0:
        return f"ticks not increasing: {values}"
    mantissa = step / 10 ** math.floor(math.log10(step) + 1e-9)
    if not any(abs(mantissa - m) < 1e-6 for m in (1, 2, 5)):
        return f"step {step:g} is not 1, 2 or 5 x 10^k: {values}"
    for a, b in zip(values, values[1:]):
        if abs((b - a) - step) > 1e-6 * step:
            return f"ticks not equally spaced: {values}"
    for v in values:
        if abs(v / step - round(v / step)) > 1e-6:
            return f"tick {v:g} is not a multiple of the step {step:g}: {values}"
    return None


def check_svg(path):
    root = ET.parse(path).getroot()
    x_ticks, y_ticks, decades = [], [], []
    for t in root.iter(SVG + "text"):
        anchor = t.get("text-anchor")
        sup = t.find(SVG + "tspan")
        if sup is not None and (t.text or "") == "10":
            decades.append(int(number(sup.text)))
            continue
        v = number("".join(t.itertext()))
        if v is None:
            continue
        if anchor == "end":
            y_ticks.append(v)
        elif anchor == "middle":
            x_ticks.append(v)
    problems = []
    why = round_ticks(sorted(x_ticks))
    if why:
        problems.append("x axis: " + why)
    if decades:
        if y_ticks:
            problems.append(f"log axis with linear labels too: {y_ticks}")
        decades.sort()
        if len(decades) < 2 or any(b - a != decades[1] - decades[0] for a, b in
                                   zip(decades, decades[1:])) or decades[1] - decades[0] != 1:
            problems.append(f"log axis not labelled once per decade: 10^{decades}")
    else:
        why = round_ticks(sorted(y_ticks))
        if why:
            problems.append("y axis: " + why)
    return problems


def main(dirs):
    failed, seen = False, 0
    for d in dirs:
        for path in sorted(pathlib.Path(d).rglob("*")):
            if path.suffix not in (".png", ".svg"):
                continue
            seen += 1
            problems = check_png(path) if path.suffix == ".png" else check_svg(path)
            for p in problems:
                print(f"{path}: {p}")
                failed = True
    if seen == 0:
        print(f"no pictures under {' '.join(dirs)}")
        return 1
    print(f"{seen} pictures checked" + (", some failed" if failed else ", all fine"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
