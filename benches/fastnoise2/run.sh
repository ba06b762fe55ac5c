#!/usr/bin/env bash
# `make bench-fastnoise2`: builds FastNoise2 v1.1.1 and its bench driver (CMake from pip),
# then prints its figures and ours from the same run, one thread each.
# FASTNOISE2_SOURCE / FASTSIMD_SOURCE: existing checkouts (else cloned from GitHub into
# target/fastnoise2/).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work="$root/target/fastnoise2"
mkdir -p "$work"
fn2=${FASTNOISE2_SOURCE:-$work/FastNoise2}
simd=${FASTSIMD_SOURCE:-$work/FastSIMD}
if [ ! -d "$fn2/include/FastNoise" ]; then
  git clone --quiet https://github.com/Auburn/FastNoise2 "$fn2"
  git -C "$fn2" checkout --quiet v1.1.1
fi
if [ ! -d "$simd/include/FastSIMD" ]; then
  git clone --quiet https://github.com/Auburn/FastSIMD "$simd"
  git -C "$simd" checkout --quiet 16450da  # the commit FastNoise2 v1.1.1 pins
fi
command -v cmake > /dev/null || python3 -m pip install --quiet cmake
cmake -S "$root/benches/fastnoise2" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DFASTNOISE2_SOURCE="$fn2" -DFASTSIMD_SOURCE="$simd" > "$work/configure.log"
cmake --build "$work/build" --parallel 2 > "$work/build.log"
"$work/build/fastnoise2_bench"
cd "$root" && cargo bench --quiet -p marbling-noise --bench noise -- --grids
