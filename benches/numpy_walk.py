#!/usr/bin/env python3
"""The CPU benchmark's inverse walk written plainly in numpy, timed beside `marbling bench`
in one run (docs/BENCHMARKS.md, "CPU reference renderer").

The design is the benchmark's own (`marbling random --seed 7 --mix comb-heavy`): drops,
tines, rakes, wavy combs and circular combs. Every pixel centre walks back through the
ops newest to oldest, one op at a time over all live samples (numpy's natural
vectorisation), samples covered by a drop leaving with its ink. The numpy picture is
checked against `marbling render --aa none` of the same design (the share of equal
pixels is printed), so both sides do the same work.

Usage: python3 benches/numpy_walk.py [--marbling target/release/marbling] [--ops 1000]
       [--size 1024]        (numpy and pillow from pip: pip install numpy pillow)
"""

import argparse
import json
import math
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np
from PIL import Image


def rgb(hex_colour):
    """'#rrggbb' as three ints."""
    return [int(hex_colour[i : i + 2], 16) for i in (1, 3, 5)]


def rake_distance(d, spacing):
    """Distance to the nearest tine of a rake: s/2 - |fmod(d, s) - s/2|."""
    return spacing * (0.5 - np.abs(np.mod(d / spacing, 1.0) - 0.5))


def walk(design):
    """Each pixel's ink index (-1: the background) after walking back every op."""
    w, h = design["width"], design["height"]
    ys, xs = np.mgrid[0:h, 0:w].astype(np.float64)
    x, y = xs.ravel() + 0.5, ys.ravel() + 0.5
    ids = np.arange(w * h)
    ink = np.full(w * h, -1)
    for k in range(len(design["ops"]) - 1, -1, -1):
        if ids.size == 0:
            break
        op = design["ops"][k]
        kind = op["type"]
        if kind == "drop":
            (cx, cy), r = op["center"], op["radius"]
            dx, dy = x - cx, y - cy
            d2 = dx * dx + dy * dy
            inside = d2 < r * r
            ink[ids[inside]] = k
            keep = ~inside
            f = np.sqrt(1.0 - r * r / d2[keep])
            x, y, ids = cx + dx[keep] * f, cy + dy[keep] * f, ids[keep]
        elif kind in ("tine", "rake"):
            (ax, ay), (mx, my) = op["origin"], op["direction"]
            norm = math.hypot(mx, my)
            mx, my = mx / norm, my / norm
            d = np.abs((x - ax) * -my + (y - ay) * mx)
            if kind == "rake":
                d = rake_distance(d, op["spacing"])
            f = op["alpha"] * op["lambda"] / (d + op["lambda"])
            x, y = x - f * mx, y - f * my
        elif kind == "wavy":
            t = op["angle"]
            mx, my, nx, ny = math.cos(t), math.sin(t), math.sin(t), -math.cos(t)
            k_ = 2.0 * math.pi / op["wavelength"]
            f = op["amplitude"] * np.sin(k_ * (x * nx + y * ny) + op["phase"])
            x, y = x - f * mx, y - f * my
        elif kind == "circular":
            (cx, cy), r = op["center"], op["radius"]
            dx, dy = x - cx, y - cy
            rho = np.sqrt(dx * dx + dy * dy)
            safe = np.where(rho == 0.0, 1.0, rho)
            theta = -op["alpha"] * op["lambda"] / (np.abs(safe - r) + op["lambda"]) / safe
            theta = np.where(rho == 0.0, 0.0, theta)
            s, c = np.sin(theta), np.cos(theta)
            x, y = cx + dx * c - dy * s, cy + dx * s + dy * c
        else:
            raise SystemExit(f"numpy_walk.py: op {k}: type {kind!r} is not walked here")
    return ink.reshape(h, w)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--marbling", default="target/release/marbling")
    ap.add_argument("--ops", type=int, default=1000)
    ap.add_argument("--size", type=int, default=1024)
    a = ap.parse_args()
    tmp = Path(tempfile.mkdtemp())
    size = f"{a.size}x{a.size}"
    design_file, png = tmp / "design.json", tmp / "render.png"
    subprocess.run(
        [a.marbling, "random", "--seed", "7", "--mix", "comb-heavy", "--ops", str(a.ops),
         "--size", size, "-o", str(design_file)],
        check=True, capture_output=True,
    )
    design = json.loads(design_file.read_text())
    start = time.perf_counter()
    ink = walk(design)
    seconds = time.perf_counter() - start
    work = a.size * a.size * a.ops
    colours = np.array([rgb(op.get("color", "#000000")) for op in design["ops"]] + [rgb(design["background"])])
    picture = colours[ink]  # index -1 is the background, the last row
    subprocess.run([a.marbling, "render", "--aa", "none", str(design_file), "-o", str(png)],
                   check=True, capture_output=True)
    ours = np.asarray(Image.open(png).convert("RGB")).astype(int)
    same = np.mean(np.all(ours == picture, axis=2))
    bench = subprocess.run(
        [a.marbling, "bench", "--mix", "comb-heavy", "--ops", str(a.ops), "--size", str(a.size),
         "--aa", "none", "--repeat", "3"],
        check=True, capture_output=True, text=True,
    ).stdout
    rate = float(bench.strip().splitlines()[-1].split()[-1])
    print(f"comb-heavy {a.ops} ops, {a.size}² px, aa none")
    print(f"numpy (1 thread)     {seconds:8.3f} s  {work / seconds:.3e} op-samples/s")
    print(f"marbling bench       {work / rate:8.3f} s  {rate:.3e} op-samples/s")
    print(f"ratio                {rate / (work / seconds):8.1f}×")
    print(f"pixels equal to marbling render --aa none: {100 * same:.3f} %")


if __name__ == "__main__":
    main()
