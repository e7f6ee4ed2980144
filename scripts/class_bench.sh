#!/usr/bin/env bash
# Times `raylab class` at class scale: a generated class of 40 students x 12 scenes at
# 400x300 (the 10 example scenes without meshes, and two of them from a turned camera;
# renders with planted bugs), every pair compared from an empty report folder, then a
# rerun that reuses the cache. The figures go in docs/BENCHMARKS.md ("A whole class").
#   scripts/class_bench.sh [STUDENTS] [SCENES] [WIDTH] [HEIGHT]
set -euo pipefail
cd "$(dirname "$0")/.."
students=${1:-40}
scenes=${2:-12}
width=${3:-400}
height=${4:-300}
work=$(mktemp -d /tmp/raylab-class-bench.XXXXXX)
trap 'rm -rf "$work"' EXIT
# No editor: the timing needs none, and a release build of egui costs many minutes.
cargo build --release --quiet --no-default-features --bin raylab --example class_generate
echo "generating $students students x $scenes scenes at ${width}x${height} in $work"
./target/release/examples/class_generate "$work" "$students" "$scenes" "$width" "$height"
echo "raylab class, every pair compared ($(nproc) cores):"
/usr/bin/time -f "%e s wall, %U s user, %M KB max resident" \
    ./target/release/raylab class "$work/scenes" "$work/submissions" -o "$work/report"
echo "raylab class again (the cache reused):"
/usr/bin/time -f "%e s wall, %U s user, %M KB max resident" \
    ./target/release/raylab class "$work/scenes" "$work/submissions" -o "$work/report"
