#!/usr/bin/env bash
# Compares raylab's triangle-mesh tracing with its peers on the same 1,000,000-triangle
# torus knot (the mesh `raylab bench` generates, rebuilt here with the same formula):
#   1. primary-ray throughput per thread against Embree (Python binding `embreex`,
#      rtcIntersect1M-style batch of the same 800x600 pinhole rays), and
#   2. whole-render CPU time (user + sys) against POV-Ray 3.7 (`mesh2`), 800x600,
#      one point light (raylab: intensity 70 at distance^2 ~70, POV-Ray: no fading), shadows,
#      no anti-aliasing.
# Installs what it needs when run (pip: numpy, embreex; apt: povray); never run by tests
# or CI. Usage: scripts/bench_mesh_peers.sh [path/to/raylab]   (default: a release build)
set -euo pipefail
cd "$(dirname "$0")/.."
RAYLAB=${1:-}
if [[ -z "$RAYLAB" ]]; then
    cargo build --release --quiet --bin raylab
    RAYLAB="${CARGO_TARGET_DIR:-target}/release/raylab"
fi
python3 -c "import numpy, embreex" 2>/dev/null || python3 -m pip install --quiet numpy embreex
command -v povray >/dev/null || { sudo=$(command -v sudo || true); $sudo apt-get install -y povray; }
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); $(date -u +%F)"

# The knot (as src/bench/mesh.rs: 5000 rings of 100 vertices, tube 0.15, (2, 3) knot),
# as OBJ for raylab and mesh2 for POV-Ray, and the Embree run on the same rays.
python3 - "$WORK" <<'PY'
import sys, time, numpy as np, embreex.rtcore_scene as rtcs
from embreex.mesh_construction import TriangleMesh
work = sys.argv[1]
segments, sides, tube = 5000, 100, 0.15
s = 2 * np.pi * np.arange(segments) / segments
def centre(s):
    r = 1 + 0.4 * np.cos(3 * s)
    return np.stack([r * np.cos(2 * s), r * np.sin(2 * s), 0.4 * np.sin(3 * s)], -1)
c = centre(s)
t = centre(s + 1e-4) - centre(s - 1e-4); t /= np.linalg.norm(t, axis=1)[:, None]
n = np.cross(t, [0, 0, 1]); n /= np.linalg.norm(n, axis=1)[:, None]
b = np.cross(t, n)
a = 2 * np.pi * np.arange(sides) / sides
out = n[:, None, :] * np.cos(a)[None, :, None] + b[:, None, :] * np.sin(a)[None, :, None]
v = (c[:, None, :] + tube * out).reshape(-1, 3).astype(np.float32)
i, j = np.meshgrid(np.arange(segments), np.arange(sides), indexing="ij")
at = lambda i, j: (i % segments) * sides + (j % sides)
v00, v10, v01, v11 = at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)
f = np.stack([np.stack([v00, v10, v11], -1), np.stack([v00, v11, v01], -1)], 2).reshape(-1, 3)
with open(f"{work}/knot.obj", "w") as obj:
    np.savetxt(obj, v, fmt="v %.9g %.9g %.9g")
    np.savetxt(obj, f + 1, fmt="f %d %d %d")
with open(f"{work}/knot.pov", "w") as pov:
    pov.write("camera { perspective location <0,0,4> look_at <0,0,0> right <-4/3,0,0> up <0,1,0> angle 75.18 }\n")
    pov.write("light_source { <-3,5,6> color rgb 1 }\nbackground { rgb 0 }\n")
    pov.write(f"mesh2 {{ vertex_vectors {{ {len(v)},\n")
    np.savetxt(pov, v, fmt="<%.9g,%.9g,%.9g>,")
    pov.write(f"}} face_indices {{ {len(f)},\n")
    np.savetxt(pov, f, fmt="<%d,%d,%d>,")
    pov.write("} pigment { rgb <0.8,0.6,0.2> } finish { ambient 0.1 diffuse 0.8 } }\n")
# The same 800x600 pinhole rays as raylab's bench (60 degrees vertical field of view).
w, h = 800, 600
hh = np.tan(np.radians(30)); hw = hh * w / h
x, y = np.meshgrid(np.arange(w), np.arange(h))
d = np.stack([(2 * (x + 0.5) / w - 1) * hw, (1 - 2 * (y + 0.5) / h) * hh, -np.ones_like(x, float)], -1).reshape(-1, 3)
d = (d / np.linalg.norm(d, axis=1)[:, None]).astype(np.float32)
o = np.tile(np.array([0, 0, 4], np.float32), (len(d), 1))
scene = rtcs.EmbreeScene()
start = time.perf_counter(); TriangleMesh(scene, v[f]); scene.run(o[:1], d[:1]); build = time.perf_counter() - start
best = float("inf")
for _ in range(5):
    start = time.perf_counter(); hits = scene.run(o, d); best = min(best, time.perf_counter() - start)
print(f"embree: {len(f)} triangles, build+commit {build*1e3:.0f} ms, "
      f"{len(d)/best/1e6:.2f} Mrays/s on one thread (rtcIntersect1M batch), {int((hits >= 0).sum())} hits")
PY

RAYON_NUM_THREADS=1 "$RAYLAB" bench --quick --json > "$WORK/bench.json"
python3 - "$WORK/bench.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print(f"raylab: {r['mesh_triangles']} triangles, build {r['mesh_build_ms']:.0f} ms (1 thread), "
      f"{r['mesh_mrays_per_s']:.2f} Mrays/s on one thread, {r['mesh_bytes_per_triangle']:.1f} bytes/triangle")
PY

# Whole renders, 800x600, one sample per pixel, CPU seconds (user + sys).
cat > "$WORK/knot.ron" <<'RON'
Scene(
    camera: (position: (0.0, 0.0, 4.0), look_at: (0.0, 0.0, 0.0), fov_deg: 60.0, width: 800, height: 600),
    render: (max_depth: 0, background: (0.0, 0.0, 0.0), samples_per_pixel: 1),
    materials: { "gold": (ambient: (0.08, 0.06, 0.02), diffuse: (0.64, 0.48, 0.16)) },
    objects: [ (name: "knot", shape: Mesh(path: "knot.obj"), material: "gold") ],
    lights: [ Ambient(colour: (1.0, 1.0, 1.0)), Point(position: (-3.0, 5.0, 6.0), colour: (1.0, 1.0, 1.0), intensity: 70.0) ],
)
RON
cpu() { /usr/bin/time -f "%U %S %e" "$@" 2>&1 >/dev/null | tail -1 | awk '{printf "%.2f s CPU (%.2f s wall)", $1 + $2, $3}'; }
echo "raylab render (load + build + trace): $(cpu "$RAYLAB" render "$WORK/knot.ron" -o "$WORK/raylab.png")"
echo "povray 3.7 render (parse + build + trace): $(cpu povray -D +I"$WORK/knot.pov" +O"$WORK/povray.png" +W800 +H600 -A)"
# KEEP=folder keeps the two images to look at.
if [[ -n "${KEEP:-}" ]]; then mkdir -p "$KEEP" && cp "$WORK/raylab.png" "$WORK/povray.png" "$KEEP/"; fi
