#!/usr/bin/env python3
"""Holds raylab's LDR-FLIP (src/compare/perceptual.rs) against NVIDIA's Python package
`flip-evaluator`, on pairs of pictures from a generated class: for each scene, two
students' renders with different planted bugs (and one student's against itself); and
on the bug galleries of a few example scenes (`raylab bugs`): the scene's own picture
against each known bug's, from a one-level rounding change to a missing object.

    python3 -m venv /tmp/flipref && /tmp/flipref/bin/pip install flip-evaluator numpy
    /tmp/flipref/bin/python scripts/flip_check.py

Prints each pair's mean and 99th percentile from both, and exits 1 if a mean differs by
more than 1e-4. The 99th percentile is numpy's (linear between ranks) of the package's
error map, as raylab computes it.
"""
import json, os, shutil, subprocess, sys, tempfile

import flip_evaluator as flip
import numpy as np

TOLERANCE = 1e-4

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
os.chdir(root)
subprocess.run(["cargo", "build", "--release", "--quiet", "--no-default-features", "--bin",
                "raylab", "--example", "class_generate", "--example", "flip_pairs"], check=True)
work = tempfile.mkdtemp(prefix="raylab-flip-check-")
subprocess.run(["target/release/examples/class_generate", work, "3", "10", "160", "120"], check=True)
subs = os.path.join(work, "submissions")
pairs = []
for name in sorted(os.listdir(os.path.join(work, "scenes"))):
    png = name.replace(".ron", ".png")
    a, b, c = (os.path.join(subs, f"student_{i:02}", png) for i in range(3))
    pairs += [(a, b), (b, c), (a, a)]
for scene in ["shapes", "spotlights", "glass", "csg"]:
    gallery = os.path.join(work, "bugs", scene)
    subprocess.run(["target/release/raylab", "bugs", f"scenes/{scene}.ron", "-o", gallery,
                    "--width", "160"], check=True, capture_output=True)
    pictures = sorted(f for f in os.listdir(gallery) if f.endswith(".png") and f != "contact_sheet.png")
    own = os.path.join(gallery, pictures[0])
    assert pictures[0] == "00-own.png", pictures[0]
    pairs += [(own, os.path.join(gallery, bug)) for bug in pictures[1:]]
ours = subprocess.run(["target/release/examples/flip_pairs"] + [p for pair in pairs for p in pair],
                      check=True, capture_output=True, text=True).stdout.splitlines()
worst = worst_p99 = 0.0
print(f"{'pair':75} {'mean (package)':>15} {'mean (raylab)':>14} {'p99 (package)':>14} {'p99 (raylab)':>13}")
for (reference, test), line in zip(pairs, ours):
    mine = json.loads(line)
    error_map, mean, _ = flip.evaluate(reference, test, "LDR", applyMagma=False)
    p99 = float(np.percentile(np.asarray(error_map, dtype=np.float64), 99))
    worst = max(worst, abs(mean - mine["mean"]))
    worst_p99 = max(worst_p99, abs(p99 - mine["p99"]))
    label = os.path.relpath(test, work) + " vs " + os.path.join(*reference.split(os.sep)[-2:])
    print(f"{label:75} {mean:15.6f} {mine['mean']:14.6f} {p99:14.6f} {mine['p99']:13.6f}")
print(f"{len(pairs)} pairs; largest difference of the means: {worst:.2e} (tolerance {TOLERANCE}); "
      f"of the 99th percentiles: {worst_p99:.2e}")
shutil.rmtree(work)
sys.exit(0 if worst <= TOLERANCE else 1)
