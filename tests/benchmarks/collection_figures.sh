#!/usr/bin/env bash
# Figures of issue 13 for collections at scale, measured on this machine and printed as a
# Markdown table:
#  - filter throughput (objects/s), computing descriptors (cold) and from the descriptor cache;
#  - peak RSS of `sagrid annotate` over 20 candidates and over all 200 objects (/usr/bin/time -v; the worker's
#    resident memory after its first object and at its largest, from the run manifest);
#  - objects per hour with a two-task Slurm array on a one-node cluster started here
#    (packaging/slurm/local_cluster.sh; skipped without slurm-wlm and munge);
#  - a projection for 1M meshes on a 100-node cluster: filter everything, then annotate the
#    candidates, from the measured CPU seconds per object.
#
#   tests/benchmarks/collection_figures.sh [BUILD_DIR [WORK_DIR]]
#
# Environment: OBJECTS (default 200; RSS is measured over 20 and OBJECTS), ARRAY_OBJECTS (objects
# for the Slurm run, default 40), NODES (100), CORES_PER_NODE (default: this machine's nproc),
# CANDIDATE_SHARE (share of a wild collection that filter keeps for annotation, default 0.01),
# ANNOTATE_OPTIONS (extra options for every annotate run). About 20 minutes on 2 cores.
set -euo pipefail

. "$(dirname "$0")/bench_dirs.sh" collection-figures "${1:-}" "${2:-}"
objects=${OBJECTS:-200}
array_objects=${ARRAY_OBJECTS:-40}
nodes=${NODES:-100}
cores=${CORES_PER_NODE:-$(nproc)}
share=${CANDIDATE_SHARE:-0.01}
models=$root/resources/models
read -r -a extra <<< "${ANNOTATE_OPTIONS:-}"

[ -x "$sagrid" ] || { echo "collection_figures.sh: no $sagrid (build it first)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "collection_figures.sh: needs GNU time (apt-get install time)" >&2; exit 1; }
log() { echo "collection_figures.sh: $*" >&2; }
now() { date +%s.%N; }
calc() { python3 -c "print($1)"; }

# A collection like a wild one: stoves and sinks among other appliances (category none).
log "generating $objects objects in $work/objects"
rm -rf "$work/objects"
n_stove=$((objects * 2 / 5)) n_sink=$((objects * 3 / 10))
n_none=$((objects - n_stove - n_sink))
"$sagrid" generate --category stove --count "$n_stove" --seed 71 --format mixed --out "$work/objects/stoves" > /dev/null 2>&1
"$sagrid" generate --category sink --count "$n_sink" --seed 72 --format mixed --out "$work/objects/sinks" > /dev/null 2>&1
"$sagrid" generate --category none --count "$n_none" --seed 73 --format mixed --out "$work/objects/other" > /dev/null 2>&1
# In a fixed mixed order (a wild collection is not sorted by category).
find "$work/objects" \( -name mesh.obj -o -name mesh.glb \) | sort |
  python3 -c 'import random, sys; l = sys.stdin.readlines(); random.Random(7).shuffle(l); print("".join(l), end="")' \
    > "$work/all.txt"

# Filter: descriptors computed (no cache yet), then read from the cache.
rm -rf "$work/cache"
# CPU seconds (user + system) of a /usr/bin/time -v log: what the work costs a core, which the
# other processes of a shared machine change much less than the wall time.
cpu_seconds() { awk -F: '/User time|System time/ {s += $2} END {printf "%.1f", s}' "$1"; }
filter() {  # -> "objects/s cpu_seconds"
  /usr/bin/time -v "$sagrid" filter "$work/all.txt" --like stove --models "$models" \
    --cache "$work/cache" --list-out "$work/candidates.txt" > /dev/null 2> "$work/filter.log"
  echo "$(grep -o '[0-9.]* objects/s' "$work/filter.log" | tail -n 1 | cut -d' ' -f1)" \
    "$(cpu_seconds "$work/filter.log")"
}
log "filter, cold"
read -r filter_cold filter_cold_cpu <<< "$(filter)"
log "filter, cached"
read -r filter_cached filter_cached_cpu <<< "$(filter)"
candidates=$(grep -vc '^#' "$work/candidates.txt" || true)

# Peak RSS and time per object, one process.
annotate_rss() {  # LIST OUT -> "peak_MiB seconds cpu_seconds first_worker_MiB largest_worker_MiB"
  rm -rf "$2"
  local t0 t1
  t0=$(now)
  /usr/bin/time -v "$sagrid" annotate "$1" --out "$2" --models "$models" "${extra[@]}" \
    > /dev/null 2> "$2.time"
  t1=$(now)
  local peak
  peak=$(awk -F: '/Maximum resident set size/ {print int($2 / 1024)}' "$2.time")
  python3 - "$2/annotate.jsonl" "$peak" "$(calc "round($t1 - $t0, 1)")" "$(cpu_seconds "$2.time")" << 'PY'
import json, sys
rss = [json.loads(l).get("rss_mib") for l in open(sys.argv[1])]
rss = [r for r in rss if r is not None]
print(sys.argv[2], sys.argv[3], sys.argv[4], int(rss[0]) if rss else 0, int(max(rss)) if rss else 0)
PY
}
# 20 of filter's candidates: what the pipeline annotates (the category-none objects of the
# collection cost a tenth: no model runs on them); their CPU seconds feed the projection.
grep -v '^#' "$work/candidates.txt" | head -n 20 > "$work/candidates20.txt"
n20=$(wc -l < "$work/candidates20.txt")
log "annotate 20 candidates (peak RSS)"
read -r rss20 sec20 cpu20 first20 last20 <<< "$(annotate_rss "$work/candidates20.txt" "$work/out20")"
log "annotate $objects objects (peak RSS)"
read -r rssN secN cpuN firstN lastN <<< "$(annotate_rss "$work/all.txt" "$work/outN")"
cpu_per_object=$(calc "round($cpuN / $objects, 2)")
filter_cpu_per_object=$(calc "round($filter_cold_cpu / $objects, 2)")
candidate_cpu=$(calc "round($cpu20 / $n20, 2)")

# Two array tasks on a one-node cluster, one CPU each.
array_rate="not measured (no slurm-wlm/munge)"
if command -v sbatch > /dev/null 2>&1 && [ -x /usr/sbin/slurmctld ]; then
  log "Slurm: two array tasks over $array_objects candidates"
  grep -v '^#' "$work/candidates.txt" | head -n "$array_objects" > "$work/array.txt"
  cluster=$work/cluster
  "$root/packaging/slurm/local_cluster.sh" start "$cluster" > /dev/null
  trap '"$root/packaging/slurm/local_cluster.sh" stop "$cluster"' EXIT
  rm -rf "$work/array_out"
  mkdir -p "$work/jobs"
  t0=$(now)
  SLURM_CONF=$cluster/slurm.conf SAGRID=$sagrid sbatch --wait --array=0-1 --cpus-per-task=1 \
    --output="$work/jobs/%A_%a.out" "$root/packaging/slurm/annotate.sbatch" "$work/array.txt" \
    "$work/array_out" --models "$models" "${extra[@]}" > /dev/null
  t1=$(now)
  done_objects=$(grep -c '"status":"annotated"' "$work/array_out/annotate.jsonl")
  array_rate=$(calc "round($done_objects / ($t1 - $t0) * 3600)")
  "$root/packaging/slurm/local_cluster.sh" stop "$cluster"
  trap - EXIT
fi

# Projection: 1M meshes, every one filtered (cold descriptor), the candidates annotated, from the
# CPU seconds per object of the one-process runs (filter over the collection, annotate over 20
# candidates: what each object costs a core; each core of the cluster runs one task).
python3 - "$filter_cpu_per_object" "$candidate_cpu" "$nodes" "$cores" "$share" << 'PY' > "$work/projection.txt"
import sys
filter_core_s, annotate_core_s, nodes, cores, share = map(float, sys.argv[1:6])
meshes = 1_000_000
filter_h = meshes * filter_core_s / (nodes * cores) / 3600
annotate_h = meshes * share * annotate_core_s / (nodes * cores) / 3600
print(f"{filter_h:.1f} {annotate_h:.2f} {filter_h + annotate_h:.1f}")
PY
load=$(cut -d' ' -f1-3 /proc/loadavg)
read -r proj_filter proj_annotate proj_total < "$work/projection.txt"

cat << EOF

Measured on $(hostname) ($(nproc) cores, $(free -g | awk '/Mem:/ {print $2}') GiB), $(date -u +%Y-%m-%d), load average
at the end $load (a shared machine: wall times depend on what else runs, CPU seconds much less);
annotate options: defaults ${ANNOTATE_OPTIONS:-}
| figure | value |
| --- | --- |
| filter, descriptors computed (cold) | $filter_cold objects/s wall; $filter_cpu_per_object CPU s/object |
| filter, descriptors from the cache | $filter_cached objects/s wall ($filter_cached_cpu CPU s for $objects) |
| filter candidates (decided stove) | $candidates of $objects |
| annotate $n20 candidates: peak RSS (time -v) | $rss20 MiB ($sec20 s wall, $cpu20 CPU s: $candidate_cpu CPU s/object) |
| annotate all $objects objects: peak RSS (time -v) | $rssN MiB ($secN s wall, $cpuN CPU s: $cpu_per_object CPU s/object) |
| worker RSS after its first object / largest ($n20) | $first20 / $last20 MiB |
| worker RSS after its first object / largest ($objects) | $firstN / $lastN MiB |
| Slurm, 2 array tasks x 1 CPU, $array_objects candidates | $array_rate objects/hour (wall, sbatch --wait) |
| 1M meshes on $nodes nodes x $cores cores: filter all ($filter_cpu_per_object CPU s each) | $proj_filter h |
| then annotate ${share} of them ($candidate_cpu CPU s each) | $proj_annotate h |
| total | $proj_total h |
EOF
