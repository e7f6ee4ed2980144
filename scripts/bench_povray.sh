#!/usr/bin/env bash
# CPU time of raylab against POV-Ray 3.7 on one example scene, scenes/NAME.ron, and its
# twin scripts/bench/NAME.pov (csg, more_shapes, glass): the median user+sys seconds of RUNS
# runs of each at 800x600 and one sample, the ratio, and both pictures side by side.
# Installs povray with apt-get only when it is missing (never run by the tests or CI).
#
# usage: [RAYLAB_BIN=path] scripts/bench_povray.sh NAME [RUNS] [OUT_DIR]   (defaults: 7, /tmp/bench_povray_NAME)
set -euo pipefail
name=${1:?usage: scripts/bench_povray.sh NAME [RUNS] [OUT_DIR]}
runs=${2:-7}
out=${3:-/tmp/bench_povray_$name}
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
if ! command -v povray >/dev/null; then
    sudo=$(command -v sudo || true)
    $sudo apt-get update -qq && $sudo apt-get install -y -qq povray
fi
target=${CARGO_TARGET_DIR:-$here/target}
# RAYLAB_BIN times a binary built before (another build holding cargo's lock need not
# be waited for); otherwise the release build of this checkout.
if [ -n "${RAYLAB_BIN:-}" ]; then
    raylab=$RAYLAB_BIN
else
    (cd "$here" && cargo build --release --bin raylab -q)
    raylab=$target/release/raylab
fi
# POV-Ray reads only below its working folder by default: run it in the output folder.
cp "$here/scripts/bench/$name.pov" "$out/scene.pov"

median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
# User + system CPU seconds of a command, to the millisecond (time(1) gives hundredths,
# too coarse for renders of a fifth of a second). Spawned, not forked: a forked Python
# child's own start-up counts as the command's (0.05 s).
cpu() {
    python3 -c 'import os, sys
null = [(os.POSIX_SPAWN_OPEN, fd, "/dev/null", os.O_WRONLY, 0) for fd in (1, 2)]
pid = os.posix_spawnp(sys.argv[1], sys.argv[1:], os.environ, file_actions=null)
_, status, r = os.wait4(pid, 0)
sys.exit(f"{sys.argv[1]} failed") if status else print(f"{r.ru_utime + r.ru_stime:.3f}")' "$@"
}

: >"$out/povray.txt"
: >"$out/raylab.txt"
for _ in $(seq "$runs"); do
    (cd "$out" && cpu povray +Iscene.pov +W800 +H600 -D +WT2 -GA +Opovray.png 2>/dev/null) >>"$out/povray.txt"
    cpu "$raylab" render "$here/scenes/$name.ron" --width 800 --height 600 --spp 1 -o "$out/raylab.png" >>"$out/raylab.txt"
done
pov=$(median <"$out/povray.txt")
ray=$(median <"$out/raylab.txt")
echo "date: $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, $(uname -m), raylab $(cd "$here" && git rev-parse --short HEAD)"
echo "povray +Iscene.pov +W800 +H600 -D +WT2 -GA: median CPU ${pov} s over $runs runs ($(tr '\n' ' ' <"$out/povray.txt"))"
echo "raylab render scenes/$name.ron --spp 1: median CPU ${ray} s over $runs runs ($(tr '\n' ' ' <"$out/raylab.txt"))"
awk -v p="$pov" -v r="$ray" 'BEGIN { printf "raylab uses %.2fx less CPU than POV-Ray\n", p / r }'
if command -v montage >/dev/null; then
    montage "$out/povray.png" "$out/raylab.png" -tile 2x1 -geometry 800x600+2+2 "$out/side_by_side.png"
    echo "pictures: $out/side_by_side.png (POV-Ray left, raylab right)"
else
    echo "pictures: $out/povray.png $out/raylab.png"
fi
