#!/usr/bin/env bash
# Renders a fixed set of pictures (every example scene and two legacy ones, in six modes
# each) with the given raylab binary into a folder, so that two builds can be compared
# byte for byte:  scripts/render_set.sh BIN DIR, then `cmp` the two folders' files.
set -euo pipefail
bin=${1:?usage: render_set.sh RAYLAB_BINARY OUT_DIR}
out=${2:?usage: render_set.sh RAYLAB_BINARY OUT_DIR}
cd "$(dirname "$0")/.."
mkdir -p "$out"
scenes=(scenes/*.ron)
for legacy in tests/legacy/full.txt tests/legacy/camera_target.txt; do
    name=$(basename "$legacy" .txt)
    "$bin" import "$legacy" -o "$out/legacy_$name.ron" >/dev/null 2>&1 || continue
    scenes+=("$out/legacy_$name.ron")
done
modes=("--spp 1" "--spp 4" "--solo specular --spp 1" "--off shadows,reflection --spp 1"
       "--view normal --spp 1" "--view shadow-mask --spp 1")
for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .ron)
    for i in "${!modes[@]}"; do
        # shellcheck disable=SC2086 # each mode is a list of flags
        "$bin" render "$scene" -o "$out/${name}_$i.png" --width 160 ${modes[$i]} >/dev/null
    done
done
ls "$out"/*.png | wc -l
