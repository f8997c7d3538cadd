#!/bin/bash
# Each hand-set pass of core/annotate under the learned point decision, left out by source (issue
# 40, item 3): candidates made with one pass on and every other pass (and the crop pass) off, then
# `sagrid scorer cv` on them; the passes-off baseline is the shipped decision's candidates.
#   tests/benchmarks/pass_ablation.sh build/sagrid MODELS REAL SH BENCH OUT
# MODELS: a models folder without point_scorer.json (the passes asked for are the passes run);
# REAL: curated wild-pool stoves and sinks + real-dev in one folder; SH: the Sweet Home 3D corpus
# (its real-train and real-val); BENCH: the generated bench (its val split). OUT/cv-<pass>/scorer_cv.md
# per pass, and OUT/summary.md.
set -euo pipefail
S=$1 MODELS=$2 REAL=$3 SH=$4 BENCH=$5 OUT=$6
PASSES="printed-marks mirror-pairs repeated-parts spout-controls spout-outlets part-ownership"
T="--tuned-on BlendSwap-CC-0 --tuned-on BlendSwap-CC-BY --tuned-on KatorLegaz --tuned-on Scopia --tuned-on default --tuned-on real-loso"
mkdir -p "$OUT"
cd "$OUT"
for pass in none $PASSES; do
  off="--no-coarse-to-fine"
  for p in $PASSES; do [ "$p" != "$pass" ] && off="$off --no-$p"; done
  $S scorer candidates $off --models "$MODELS" --data "$REAL" --out "$pass-real.json" > "$pass-real.log" 2>&1
  $S scorer candidates $off --models "$MODELS" --data "$SH/real-train" --data "$SH/real-val" \
    --out "$pass-sh.json" > "$pass-sh.log" 2>&1
  $S scorer candidates $off --models "$MODELS" --data "$BENCH" --out "$pass-bench.json" > "$pass-bench.log" 2>&1
  $S scorer cv $T --candidates "$pass-real.json" --candidates "$pass-sh.json" \
    --candidates "$pass-bench.json" --out "cv-$pass" > "cv-$pass.log" 2>&1
done
{
  echo "| pass on | all: edits / one key / error | unseen: edits / one key / error |"
  echo "|---|---|---|"
  for pass in none $PASSES; do
    all=$(grep -F '| **all** |' "cv-$pass/scorer_cv.md" | awk -F'|' '{print $10"/"$11"/"$12}')
    unseen=$(grep -F '| **sources no pass was made on** |' "cv-$pass/scorer_cv.md" | awk -F'|' '{print $10"/"$11"/"$12}')
    echo "| $pass | $all | $unseen |"
  done
} > summary.md
cat summary.md
