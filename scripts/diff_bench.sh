#!/usr/bin/env bash
# Times `raylab diff` (release) on pairs like the public corpus's slowest (issue 50): the
# course scenes of scripts/bench/diff/ at their own sizes (1280x720 with mirrors and
# 4 samples a pixel, ...), each against raylab's own picture and against pictures with
# planted bugs (`raylab render --bug`). Prints seconds per pair, the median and the
# maximum, and keeps every pair's `--json` output.
#
#   scripts/diff_bench.sh [bench|corpus|identity] [OUT]
#
# `bench` (the default): the corpus-like pairs above. `corpus`: pairs spread as the
# public corpus's are, for its median: mostly small course scenes (scripts/bench/diff/
# corpus/, written for the purpose: 100x100 to 1000x1000, most 640x480 or smaller, one
# sample a pixel, one to eight objects, one or two lights besides the ambient, a mirror in
# three of nine, a spot light and a CSG object in one each), sized and filled like the
# students' scenes seen in public course repositories (a plane at 100x100, a mirror
# floor at 140x140, a snowman and cut cones at 400x300, the framework's default
# 800x600, lighting tests at 1000x1000), plus the three large scenes of `bench`, each
# against the same three pictures. `identity`: the example scenes and
# the comparison tests' scenes at 160x120, each against its own picture and pictures
# with several bugs; its JSON is what proves a change of the diff's speed kept every
# verdict (`diff -r` two OUT folders). RAYLAB names the binary (default: a fresh release
# build); pictures are cached in OUT/pictures.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-bench}
out=${2:-/tmp/raylab-diff-bench}
if [[ -z "${RAYLAB:-}" ]]; then
    cargo build --release --quiet --bin raylab
    RAYLAB=./target/release/raylab
fi
mkdir -p "$out/pictures" "$out/json" "$out/scenes"

# Pairs as `scene|bug` (an empty bug: raylab's own picture).
pairs=()
case "$mode" in
bench)
    for scene in scripts/bench/diff/*.txt; do
        for bug in "" mirror-blend light-off@1; do
            pairs+=("$scene|$bug")
        done
    done
    ;;
corpus)
    for scene in scripts/bench/diff/corpus/*.txt scripts/bench/diff/*.txt; do
        for bug in "" mirror-blend light-off@1; do
            pairs+=("$scene|$bug")
        done
    done
    ;;
identity)
    # Every example and test scene at 160x120 (meshes beside them, as the scene names them).
    cp scenes/*.obj "$out/scenes/"
    for scene in scenes/*.ron tests/compare/*.ron; do
        python3 - "$scene" "$out/scenes/$(basename "$scene")" <<'EOF'
import re, sys
text = open(sys.argv[1]).read()
text = re.sub(r"width:\s*\d+", "width: 160", text, count=1)
text = re.sub(r"height:\s*\d+", "height: 120", text, count=1)
open(sys.argv[2], "w").write(text)
EOF
        for bug in "" light-off@1 mirror-blend clamp-each-ray no-depth-limit half-vector \
            shadow-acne normal-not-flipped one-sided spot-no-cone diffuse=0.5 extra-object \
            truncate; do
            pairs+=("$out/scenes/$(basename "$scene")|$bug")
        done
    done
    ;;
*)
    echo "usage: $0 [bench|corpus|identity] [OUT]" >&2
    exit 2
    ;;
esac

times=()
for pair in "${pairs[@]}"; do
    scene=${pair%%|*}
    bug=${pair#*|}
    name="$(basename "${scene%.*}")__${bug:-correct}"
    picture="$out/pictures/$name.png"
    if [[ ! -f "$picture" ]]; then
        if [[ -z "$bug" ]]; then
            "$RAYLAB" render "$scene" -o "$picture" >/dev/null 2>&1 || continue
        else
            "$RAYLAB" render "$scene" --bug "$bug" -o "$picture" >/dev/null 2>&1 || continue
        fi
    fi
    # Wall and CPU (user + system) seconds: on a shared machine the CPU time is the
    # steadier figure, and on 2 quiet cores the wall time is about half of it.
    /usr/bin/time -f '%e %U %S' -o "$out/time.txt" \
        "$RAYLAB" diff --json "$scene" "$picture" >"$out/json/$name.json" 2>/dev/null ||
        echo "diff failed" >>"$out/json/$name.json"
    read -r wall user system <"$out/time.txt"
    cpu=$(echo "$user + $system" | bc)
    times+=("$wall $cpu")
    printf '%-50s %8.2f s wall %8.2f s cpu\n' "$name" "$wall" "$cpu"
done
summary() {
    sort -g | awk '
        { t[NR] = $1 }
        END {
            median = (NR % 2) ? t[(NR + 1) / 2] : (t[NR / 2] + t[NR / 2 + 1]) / 2
            printf "median %.2f s, max %.2f s", median, t[NR]
        }'
}
printf 'pairs %d; wall: %s; cpu: %s (%s cores, load %s)\n' "${#times[@]}" \
    "$(printf '%s\n' "${times[@]}" | cut -d' ' -f1 | summary)" \
    "$(printf '%s\n' "${times[@]}" | cut -d' ' -f2 | summary)" \
    "$(nproc)" "$(cut -d' ' -f1 /proc/loadavg)"
