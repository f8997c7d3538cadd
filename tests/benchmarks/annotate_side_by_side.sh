#!/bin/bash
# The whole `sagrid annotate` process on one mesh, timed for several builds side by side in one run
# (issue 40: annotate <= 1.5 s, compared with the build before). Runs alternate between the builds
# (ABAB..., the order reversed every other round) so a load that comes and goes falls on all of
# them alike; prints the median, the fastest and the slowest wall time of each.
#
#   tests/benchmarks/annotate_side_by_side.sh ROUNDS MESH NAME=BIN:MODELS [NAME=BIN:MODELS ...]
#   e.g. tests/benchmarks/annotate_side_by_side.sh 6 ../shared/data/real-dev/libero__flat_stove/mesh.obj \
#          before=/tmp/old/sagrid:/tmp/old/models now=build/sagrid:resources/models
#
# Each run writes a fresh output folder (--force), so no run reuses another's labels.
set -euo pipefail

if [ $# -lt 3 ]; then
  sed -n '2,11p' "$0" >&2
  exit 2
fi
rounds=$1
mesh=$2
shift 2
[ -f "$mesh" ] || { echo "annotate_side_by_side: no mesh file $mesh" >&2; exit 2; }
names=() bins=() models=()
for spec in "$@"; do
  name=${spec%%=*}
  rest=${spec#*=}
  bin=${rest%%:*}
  folder=${rest#*:}
  if [ "$name" = "$spec" ] || [ "$bin" = "$rest" ] || [ ! -x "$bin" ] || [ ! -d "$folder" ]; then
    echo "annotate_side_by_side: '$spec' is not NAME=BIN:MODELS with an executable BIN and a models folder" >&2
    exit 2
  fi
  names+=("$name") bins+=("$bin") models+=("$folder")
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=${#names[@]}
for ((r = 0; r < rounds; r++)); do
  for ((k = 0; k < n; k++)); do
    i=$(( r % 2 == 0 ? k : n - 1 - k ))
    start=$(date +%s.%N)
    if ! "${bins[$i]}" annotate "$mesh" --models "${models[$i]}" --out "$work/out-$i" --force \
        > "$work/log-$i" 2>&1; then
      echo "annotate_side_by_side: ${names[$i]} failed:" >&2
      tail -5 "$work/log-$i" >&2
      exit 1
    fi
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.4f\n", b - a }' >> "$work/times-$i"
  done
done

echo "| build | median s | fastest s | slowest s | runs |"
echo "|---|---:|---:|---:|---:|"
for ((i = 0; i < n; i++)); do
  sort -g "$work/times-$i" | awk -v name="${names[$i]}" '
    { t[NR] = $1 }
    END {
      median = NR % 2 ? t[(NR + 1) / 2] : (t[NR / 2] + t[NR / 2 + 1]) / 2
      printf "| %s | %.3f | %.3f | %.3f | %d |\n", name, median, t[1], t[NR], NR
    }'
done
