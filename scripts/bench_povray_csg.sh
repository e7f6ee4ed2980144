#!/usr/bin/env bash
# CPU time of raylab against POV-Ray 3.7 on the CSG scene (scenes/csg.ron and its twin
# scripts/bench/csg.pov): the median user+sys seconds of RUNS runs of each, the ratio,
# and both pictures. Installs povray with apt-get only when it is missing (never run by
# the tests or CI).
#
# usage: scripts/bench_povray_csg.sh [RUNS] [OUT_DIR]     (defaults: 7, /tmp/bench_povray_csg)
set -euo pipefail
runs=${1:-7}
out=${2:-/tmp/bench_povray_csg}
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
if ! command -v povray >/dev/null; then
    sudo=$(command -v sudo || true)
    $sudo apt-get update -qq && $sudo apt-get install -y -qq povray
fi
target=${CARGO_TARGET_DIR:-$here/target}
(cd "$here" && cargo build --release --bin raylab -q)
raylab=$target/release/raylab
# POV-Ray reads only below its working folder by default: run it in the output folder.
cp "$here/scripts/bench/csg.pov" "$out/scene.pov"

median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
cpu() { /usr/bin/time -f "%U %S" "$@" 2>&1 >/dev/null | tail -1 | awk '{ print $1 + $2 }'; }

: >"$out/povray.txt"
: >"$out/raylab.txt"
for _ in $(seq "$runs"); do
    (cd "$out" && cpu povray +Iscene.pov +W800 +H600 -D +WT2 -GA +Opovray.png) >>"$out/povray.txt"
    cpu "$raylab" render "$here/scenes/csg.ron" --width 800 --height 600 -o "$out/raylab.png" >>"$out/raylab.txt"
done
pov=$(median <"$out/povray.txt")
ray=$(median <"$out/raylab.txt")
echo "date: $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, $(uname -m), raylab $(cd "$here" && git rev-parse --short HEAD)"
echo "povray +Iscene.pov +W800 +H600 -D +WT2 -GA: median CPU ${pov} s over $runs runs ($(tr '\n' ' ' <"$out/povray.txt"))"
echo "raylab render scenes/csg.ron: median CPU ${ray} s over $runs runs ($(tr '\n' ' ' <"$out/raylab.txt"))"
awk -v p="$pov" -v r="$ray" 'BEGIN { printf "raylab uses %.2fx less CPU than POV-Ray\n", p / r }'
echo "pictures: $out/povray.png $out/raylab.png"
