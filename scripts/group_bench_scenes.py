#!/usr/bin/env python3
"""Writes two scenes of the same 10,000 small spheres: flat.ron (a flat object list)
and grouped.ron (10 groups of 10 groups of 100, placed by the groups' transforms), for
the groups-vs-flat figure in docs/BENCHMARKS.md.

usage: python3 scripts/group_bench_scenes.py OUT_DIR
"""
import os
import sys

HEAD = """Scene(
    format: 1,
    camera: (position: (0.0, 60.0, 75.0), look_at: (0.0, 0.0, 0.0), up: (0.0, 1.0, 0.0),
             fov_deg: 50.0, width: 800, height: 600),
    render: (max_depth: 3, background: (0.05, 0.06, 0.09), samples_per_pixel: 1),
    materials: {
        "floor": (ambient: (0.2, 0.2, 0.2), diffuse: (0.5, 0.5, 0.5), specular: (0.1, 0.1, 0.1),
                  shininess: 8.0, mirror: (0.2, 0.2, 0.2)),
        "ball": (ambient: (0.3, 0.1, 0.1), diffuse: (0.7, 0.2, 0.2), specular: (0.5, 0.5, 0.5),
                 shininess: 40.0),
    },
    lights: [
        Ambient(colour: (0.2, 0.2, 0.2)),
        Point(position: (-20.0, 40.0, 30.0), colour: (1.0, 1.0, 1.0), intensity: 2500.0),
    ],
    objects: [
        (name: "floor", shape: Plane, transform: (rotate_deg: (-90.0, 0.0, 0.0),
         scale: (60.0, 60.0, 1.0)), material: "floor"),
"""

SPACING = 0.9


def ball(name, x, z):
    return (f'(name: "{name}", shape: Sphere, transform: (translate: ({x:.3f}, 0.35, {z:.3f}), '
            f'scale: (0.35, 0.35, 0.35)), material: "ball")')


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    flat = []
    grouped = []
    for a in range(10):
        rows = []
        for b in range(10):
            row = []
            for c in range(100):
                x = (c - 49.5) * SPACING
                z = ((a * 10 + b) - 49.5) * SPACING
                flat.append(ball(f"ball {a}.{b}.{c}", x, z))
                # In the row group's space, the row sits at z = 0.
                row.append(ball(f"ball {c}", x, 0.0))
            z_row = (b - 4.5) * SPACING
            rows.append(f'(name: "row {b}", shape: Group(children: [{", ".join(row)}]), '
                        f'transform: (translate: (0.0, 0.0, {z_row:.3f})))')
        z_block = (a * 10 + 4.5 - 49.5) * SPACING
        grouped.append(f'(name: "block {a}", shape: Group(children: [{", ".join(rows)}]), '
                       f'transform: (translate: (0.0, 0.0, {z_block:.3f})))')
    for name, objects in (("flat.ron", flat), ("grouped.ron", grouped)):
        with open(os.path.join(out, name), "w") as f:
            f.write(HEAD + ",\n".join(objects) + "\n    ],\n)\n")


if __name__ == "__main__":
    main()
