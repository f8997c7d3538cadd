#!/usr/bin/env bash
# Runs every libFuzzer target of a SAGRID_FUZZ build for SECONDS each, all at once at low
# priority; after a finding (crash, timeout, out-of-memory: the input is saved) the target starts
# again and fuzzing goes on. Usage: tests/fuzz/run_fuzzers.sh BUILD_DIR SECONDS [TARGET...]
# Per target: corpus in BUILD_DIR/fuzz-corpus/<target> (grows across runs), findings in
# BUILD_DIR/fuzz-findings/<target>/, log in BUILD_DIR/fuzz-logs/<target>.log; a summary table
# (time, executions, coverage, findings) goes to stdout and BUILD_DIR/fuzz-summary.txt.
set -uo pipefail
build=${1:?usage: run_fuzzers.sh BUILD_DIR SECONDS [TARGET...]}
seconds=${2:?usage: run_fuzzers.sh BUILD_DIR SECONDS [TARGET...]}
shift 2
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_mesh_obj fuzz_mesh_ply fuzz_mesh_stl fuzz_mesh_glb
  fuzz_mesh_fbx fuzz_labels fuzz_model_card fuzz_npz fuzz_npy fuzz_architecture)

seeds="$build/fuzz-seeds"
"$build/fuzz/make_fuzz_seeds" "$seeds" "$source_dir" "$source_dir/../shared" > /dev/null

# ASan/UBSan stop at the first report. Leak checks are left to `make test-asan` (libFuzzer's
# per-input leak check slows the runs).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}

seed_dir() {
  case $1 in
    fuzz_mesh_*) echo "$seeds/mesh_${1#fuzz_mesh_}" ;;
    *) echo "$seeds/${1#fuzz_}" ;;
  esac
}

# One target for SECONDS of wall time. libFuzzer stops at a finding (the input is saved under
# fuzz-findings/); the loop then starts it again on the grown corpus until the time is used.
# (Fork mode would go on by itself, but each of its jobs starts a new process, and every start
# loads libtorch: in-process runs are far faster here.)
fuzz_for() {
  local t=$1 end=$((SECONDS + seconds)) run=0
  : > "$build/fuzz-logs/$t.log"
  while [ $SECONDS -lt $end ]; do
    run=$((run + 1))
    echo "=== run $run" >> "$build/fuzz-logs/$t.log"
    # -timeout: an input taking longer than 10 s is a hang (the issue asks for answers within
    # seconds); -rss_limit_mb / -malloc_limit_mb: a blow-up past 2 GiB is a finding.
    nice -n 19 "$build/fuzz/$t" -max_total_time=$((end - SECONDS)) -timeout=10 \
      -rss_limit_mb=2048 -malloc_limit_mb=2048 -max_len=262144 -use_value_profile=1 \
      -print_final_stats=1 -print_pcs=0 -artifact_prefix="$build/fuzz-findings/$t/" \
      "$build/fuzz-corpus/$t" "$(seed_dir "$t")" >> "$build/fuzz-logs/$t.log" 2>&1
  done
}

pids=()
start=$SECONDS
for t in "${targets[@]}"; do
  mkdir -p "$build/fuzz-corpus/$t" "$build/fuzz-findings/$t" "$build/fuzz-logs"
  fuzz_for "$t" &
  pids+=($!)
done
for p in "${pids[@]}"; do wait "$p"; done

{
  echo "wall time $((SECONDS - start)) s per target, ${#targets[@]} targets at once, nice 15"
  printf '%-18s %6s %12s %8s %8s %s\n' target runs executions cov corpus findings
  for t in "${targets[@]}"; do
    log="$build/fuzz-logs/$t.log"
    # Executions per run: its final stat line, or its last status line ("#N ...") when it
    # stopped at a finding; summed over runs.
    read -r runs execs cov < <(awk '
      /^=== run/ { total += last; last = 0; runs++ }
      /^#[0-9]+/ { n = substr($1, 2) + 0; if (n > last) last = n
                   for (i = 1; i < NF; i++) if ($i == "cov:") cov = $(i + 1) }
      /^stat::number_of_executed_units:/ { last = $2 + 0 }
      END { print runs + 0, total + last, cov + 0 }' "$log")
    corpus=$(find "$build/fuzz-corpus/$t" -type f | wc -l)
    found=$(find "$build/fuzz-findings/$t" -type f | wc -l)
    printf '%-18s %6s %12s %8s %8s %s\n' "$t" "$runs" "$execs" "$cov" "$corpus" "$found"
  done
} | tee "$build/fuzz-summary.txt"
