#!/usr/bin/env bash
# The whole test suite, from a fresh clone on a fresh Debian machine with the Rust
# toolchain: installs the system packages the tests need, then checks formatting,
# lints and runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."

# A headless X server for the one test that opens a real window.
if ! command -v xvfb-run >/dev/null 2>&1 || ! command -v xauth >/dev/null 2>&1; then
    sudo_cmd=""
    if [ "$(id -u)" != 0 ]; then sudo_cmd="sudo"; fi
    echo "installing xvfb and xauth (for the editor window test)"
    $sudo_cmd apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq xvfb xauth >/dev/null
fi

# A C++ compiler for nv-flip-sys, which builds NVIDIA's FLIP (the perceptual difference).
if ! command -v c++ >/dev/null 2>&1; then
    sudo_cmd=""
    if [ "$(id -u)" != 0 ]; then sudo_cmd="sudo"; fi
    echo "installing g++ (for the FLIP perceptual difference)"
    $sudo_cmd apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq g++ >/dev/null
fi

cargo fmt --check
# No module imports one that imports it back (see README, Layout; the script's ALLOWED
# list names the one circle that may stay, and why).
if command -v python3 >/dev/null 2>&1; then
    python3 scripts/import_cycles.py src
fi
cargo clippy --all-targets --locked -- -D warnings
cargo test --all-targets --locked
