#!/usr/bin/env bash
# The README's main job: the annotation GUI on the bundled samples with the shipped models.
# With no display (ssh, CI), it renders each sample headless (EGL) to build/run-screenshots/
# instead, so `make run` always shows something.
set -euo pipefail
build_dir=${1:-build}
models=resources/models
samples=""
# The curator works on a copy, so saved labels never touch the repository; a second run resumes
# the same copy where the curator stopped.
if [ -d resources/samples ]; then
  samples="$build_dir/samples"
  [ -d "$samples" ] || cp -r resources/samples "$samples"
else
  echo "sagrid: no bundled samples in resources/samples; opening the GUI empty" >&2
fi
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$build_dir/sagrid" gui --models "$models" ${samples:+"$samples"}
fi
echo "sagrid: no display; rendering the samples headless instead (run 'make run' on a desktop for the GUI)" >&2
out="$build_dir/run-screenshots"
mkdir -p "$out"
for mesh in ${samples:+$samples/*/mesh.*}; do
  case "$mesh" in *.mtl|*.png|*.jpg) continue ;; esac
  name=$(basename "$(dirname "$mesh")")
  "$build_dir/sagrid" render "$mesh" --field --backend egl --screenshot "$out/$name.png"
  echo "$out/$name.png"
done
