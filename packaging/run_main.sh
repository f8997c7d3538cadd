#!/usr/bin/env bash
# The README's main job. Until the GUI lands it runs `sagrid info` on the bundled samples.
set -euo pipefail
build_dir=${1:-build}
for mesh in resources/samples/*/mesh.*; do
  case "$mesh" in *.mtl|*.png|*.jpg) continue ;; esac
  "$build_dir/sagrid" info "$mesh"
done
