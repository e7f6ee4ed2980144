#!/usr/bin/env bash
# CPU time of raylab against POV-Ray 3.7 on example scenes: scenes/NAME.ron and its twin
# scripts/bench/NAME.pov, at the scene's own size and one sample per pixel, both on 2
# threads: the median user+sys seconds of RUNS runs of each (alternating), the ratio, and
# both pictures side by side. NAME `all` runs every scene that has a twin, one after the
# other, and ends with a Markdown table of them.
# Installs povray with apt-get only when it is missing (never run by the tests or CI).
#
# usage: [RAYLAB_BIN=path] scripts/bench_povray.sh NAME|all [RUNS] [OUT_DIR]
#        (defaults: 7, /tmp/bench_povray_NAME; with `all`, OUT_DIR holds one folder a scene)
set -euo pipefail
name=${1:?usage: scripts/bench_povray.sh NAME|all [RUNS] [OUT_DIR]}
runs=${2:-7}
out=${3:-/tmp/bench_povray_$name}
here=$(cd "$(dirname "$0")/.." && pwd)
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
load() { cut -d' ' -f1-3 /proc/loadavg; }

# bench_one NAME DIR: times one scene and its twin; appends a row to $rows.
bench_one() {
    local scene=$1 dir=$2 ron=$here/scenes/$1.ron
    local width height pov ray
    # The scene's own size (its camera's width and height).
    width=$(grep -o 'width: *[0-9]*' "$ron" | head -1 | grep -o '[0-9]*$')
    height=$(grep -o 'height: *[0-9]*' "$ron" | head -1 | grep -o '[0-9]*$')
    mkdir -p "$dir"
    # POV-Ray reads only below its working folder by default: run it in the output folder.
    cp "$here/scripts/bench/$scene.pov" "$dir/scene.pov"
    : >"$dir/povray.txt"
    : >"$dir/raylab.txt"
    for _ in $(seq "$runs"); do
        (cd "$dir" && cpu povray +Iscene.pov +W"$width" +H"$height" -D +WT2 -GA +Opovray.png 2>/dev/null) >>"$dir/povray.txt"
        cpu "$raylab" render "$ron" --width "$width" --height "$height" --spp 1 -o "$dir/raylab.png" >>"$dir/raylab.txt"
    done
    pov=$(median <"$dir/povray.txt")
    ray=$(median <"$dir/raylab.txt")
    echo "== $scene, ${width}x${height}, load average $(load)"
    echo "povray +Iscene.pov +W$width +H$height -D +WT2 -GA: median CPU ${pov} s over $runs runs ($(tr '\n' ' ' <"$dir/povray.txt"))"
    echo "raylab render scenes/$scene.ron --width $width --height $height --spp 1: median CPU ${ray} s over $runs runs ($(tr '\n' ' ' <"$dir/raylab.txt"))"
    awk -v p="$pov" -v r="$ray" 'BEGIN { printf "raylab uses %.2fx less CPU than POV-Ray\n", p / r }'
    if command -v montage >/dev/null; then
        montage "$dir/povray.png" "$dir/raylab.png" -tile 2x1 -geometry "${width}x${height}+2+2" "$dir/side_by_side.png"
        echo "pictures: $dir/side_by_side.png (POV-Ray left, raylab right)"
    else
        echo "pictures: $dir/povray.png $dir/raylab.png"
    fi
    rows+=$(awk -v s="$scene" -v w="$width" -v h="$height" -v p="$pov" -v r="$ray" \
        'BEGIN { printf "| `%s.ron` | %dx%d | %.3f s | %.3f s | %.2fx |\\n", s, w, h, p, r, p / r }')
}

rows=""
echo "date: $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, $(uname -m), raylab $(cd "$here" && git rev-parse --short HEAD), load average $(load)"
if [ "$name" = all ]; then
    for twin in "$here"/scripts/bench/*.pov; do
        scene=$(basename "$twin" .pov)
        [ -f "$here/scenes/$scene.ron" ] && bench_one "$scene" "$out/$scene"
    done
    echo
    echo "| scene | size | POV-Ray CPU | raylab CPU | ratio |"
    echo "|---|---|---|---|---|"
    printf '%b' "$rows"
    echo "load average at the end: $(load)"
else
    bench_one "$name" "$out"
fi
