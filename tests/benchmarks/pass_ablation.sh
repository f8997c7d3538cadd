#!/bin/bash
# Each hand-set pass of core/annotate under the learned point decision, left out by source (issue
# 40, item 3): candidates made with one pass on and every other pass (and the crop pass) off, then
# `sagrid scorer cv` on them; "none" (every pass off) is the shipped decision's candidates, and
# "coarse-to-fine" has the crop pass as each card says. The summary counts, per source, whether
# each configuration needs fewer, more or as many edits as "none".
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
for pass in none coarse-to-fine $PASSES; do
  off=""
  for p in coarse-to-fine $PASSES; do [ "$p" != "$pass" ] && off="$off --no-$p"; done
  $S scorer candidates $off --models "$MODELS" --data "$REAL" --out "$pass-real.json" > "$pass-real.log" 2>&1
  $S scorer candidates $off --models "$MODELS" --data "$SH/real-train" --data "$SH/real-val" \
    --out "$pass-sh.json" > "$pass-sh.log" 2>&1
  $S scorer candidates $off --models "$MODELS" --data "$BENCH" --out "$pass-bench.json" > "$pass-bench.log" 2>&1
  $S scorer cv $T --candidates "$pass-real.json" --candidates "$pass-sh.json" \
    --candidates "$pass-bench.json" --out "cv-$pass" > "cv-$pass.log" 2>&1
done
python3 - $PASSES <<'PY' | tee summary.md
import json, sys
tuned = {'BlendSwap-CC-0', 'BlendSwap-CC-BY', 'KatorLegaz', 'Scopia', 'default', 'real-loso'}
def cells(f):
    return '%.2f / %.0f %% / %.1f cm' % (f['edits_per_hand_point'], 100 * f['one_key_share'], 100 * f['single_error_m'])
base = json.load(open('cv-none/scorer_cv.json'))
print('| on | unseen: edits / one key / error | all | unseen sources fewer / more / as many edits than none | tuned-on sources |')
print('|---|---|---|---|---|')
for name in ['none', 'coarse-to-fine'] + sys.argv[1:]:
    cv = json.load(open('cv-%s/scorer_cv.json' % name))
    counts = {True: [0, 0, 0], False: [0, 0, 0]}
    for a, b in zip(base['folds'], cv['folds']):
        ea, eb = a['with_curated']['edits'], b['with_curated']['edits']
        counts[a['source'] in tuned][0 if eb < ea else 1 if eb > ea else 2] += 1
    print('| %s | %s | %s | %s | %s |' % (name, cells(cv['unseen']['with_curated']), cells(cv['all']['with_curated']),
          ' / '.join(map(str, counts[False])), ' / '.join(map(str, counts[True]))))
PY
