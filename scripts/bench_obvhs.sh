#!/usr/bin/env bash
# raylab's mesh hierarchy against the obvhs crate (PLOC BVH2 and CWBVH builders) on the
# 1,000,000-triangle knot of `raylab bench`: build time on all cores and primary rays per
# second on one thread. Builds its own small crate (scripts/bench/obvhs_compare, its own
# workspace and target folder), so neither the tests nor CI ever build obvhs.
# Usage: scripts/bench_obvhs.sh
set -euo pipefail
cd "$(dirname "$0")/bench/obvhs_compare"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); $(date -u +%F)"
cargo build --release --quiet
./target/release/obvhs_compare
