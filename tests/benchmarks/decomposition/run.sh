#!/usr/bin/env bash
# Convex decomposition benchmark: ours beside V-HACD 4 (npm vhacd-js: its WASM build under node,
# and its VHACD.h compiled natively) on the same meshes, in one run. Not part of CI: it fetches
# vhacd-js from the npm registry into the build folder (BSD-3; not kept in this repository).
#
# usage: tests/benchmarks/decomposition/run.sh [BUILD_DIR] [MESH...]
# Writes BUILD_DIR/decomposition-bench/results.md and pictures/{stove,sink}_{parts,mesh}.png.
# Default meshes: the three real-dev objects and the first PER_CATEGORY (5) stoves and sinks of
# the val split of `sagrid generate --preset bench` (generated into
# BUILD_DIR/decomposition-bench/generated). MAX_HULLS (32) is the part budget of all three
# methods. Needs node and npm. Results also go to BUILD_DIR/decomposition-bench/results.md.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
shift || true
max_hulls="${MAX_HULLS:-32}"
per_category="${PER_CATEGORY:-5}"  # generated stoves and sinks (the first of the bench val split)
work="$build/decomposition-bench"
vhacd_dir="$build/vhacd-js/package"

if [ ! -f "$vhacd_dir/include/VHACD.h" ]; then
  mkdir -p "$build/vhacd-js"
  (cd "$build/vhacd-js" && npm pack --silent vhacd-js@0.0.1 >/dev/null && tar xzf vhacd-js-0.0.1.tgz)
fi
c++ -O2 -std=c++17 -w -I"$vhacd_dir/include" "$here/vhacd_native.cpp" -o "$build/vhacd_native" -lpthread

meshes=("$@")
if [ ${#meshes[@]} -eq 0 ]; then
  for d in "$root/../shared/data/real-dev"/*/; do meshes+=("$d/mesh.obj"); done
  if [ ! -d "$work/generated" ]; then
    "$build/sagrid" generate --preset bench --out "$work/generated" >/dev/null
  fi
  for category in stove sink; do
    for d in $(ls -d "$work/generated/val/${category}_"*/ | head -n "$per_category"); do
      meshes+=("$(ls "$d"mesh.* | grep -v '\.mtl$' | head -n 1)")
    done
  done
fi

rm -rf "$work/objects"
"$build/tests/benchmarks/decomposition_compare" prepare "$work/objects" "${meshes[@]}" >/dev/null
node "$here/vhacd_wasm.mjs" "$vhacd_dir" "$work/objects" "$max_hulls"
"$build/vhacd_native" "$work/objects" "$max_hulls"
"$build/tests/benchmarks/decomposition_compare" evaluate "$work/objects" | tee "$work/results.md"

# Pictures of our collision parts (one colour per part) for the first generated stove and sink.
mkdir -p "$work/pictures"
for category in stove sink; do
  object="$(ls -d "$work/objects/${category}_"*/ 2>/dev/null | head -n 1)"
  [ -n "$object" ] || continue
  "$build/tests/benchmarks/decomposition_compare" parts-glb "$object/ours.obj" "$work/pictures/${category}_parts.glb" >/dev/null
  "$build/sagrid" render "$work/pictures/${category}_parts.glb" --backend egl --no-panels --size 900x700 \
    --yaw 35 --pitch 40 --screenshot "$work/pictures/${category}_parts.png" || true
  "$build/sagrid" render "$object/input.obj" --backend egl --no-panels --size 900x700 \
    --yaw 35 --pitch 40 --screenshot "$work/pictures/${category}_mesh.png" || true
done
