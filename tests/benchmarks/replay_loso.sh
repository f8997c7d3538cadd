#!/usr/bin/env bash
# Curation of the wild pool replayed leave one source out (issues 40 and 41): for each wild-pool
# repository, a models folder whose category classifier and learned point decision were fitted
# without any of its objects (the networks and confidence.json are the shipped ones: no network
# was trained on the pool) predicts that repository's objects; each repository is then replayed
# through the GUI's session (`sagrid replay-curation`, the curator who knows the curated labels)
# in a session of its own, whose category switches predict with the same models; `sagrid eval
# --curation` reports the log. With IN_SAMPLE=1 the shipped models do all of it instead (the
# figure earlier notes gave, in sample: the shipped files were fitted on these objects).
#
#   tests/benchmarks/replay_loso.sh [BUILD_DIR [WORK_DIR]]
#
# Environment (the inputs of resources/models/README.md's recipes, all required but IN_SAMPLE):
# POOL (../shared/data/wild-pool), WILD (`sagrid corpus wild` with the curated labels), SH (`sagrid
# corpus sweethome3d`), BENCH, DIST and GEN (generated data, "Category classifier": GEN/stoves,
# GEN/sinks, GEN/none and, since session 60, GEN/glass-stoves), CANDIDATES_REAL,
# CANDIDATES_SH, CANDIDATES_BENCH (`sagrid scorer candidates` files, "point_scorer.json").
# SCORER_OPTIONS (optional): more options for each repository's `scorer train` (e.g.
# "--feature-share 1", the decision before session 53), to replay two decisions side by side.
# CATEGORY_INPUTS (optional): what each repository's classifier reads (default the shipped file's
# "--top-relief --part-statistics --file-name"; without --file-name: the classifier before session
# 65), to replay two classifiers side by side.
# About 6 minutes on 2 cores with cached features (IN_SAMPLE=1: 2).
set -euo pipefail

. "$(dirname "$0")/bench_dirs.sh" replay-loso "${1:-}" "${2:-}"
shipped=$root/resources/models
[ -x "$sagrid" ] || { echo "replay_loso.sh: no $sagrid (build it first)" >&2; exit 1; }
for v in POOL WILD SH BENCH DIST GEN CANDIDATES_REAL CANDIDATES_SH CANDIDATES_BENCH; do
  [ -e "${!v:-}" ] || { echo "replay_loso.sh: set $v (see the header)" >&2; exit 1; }
done
log() { echo "replay_loso.sh: $*" >&2; }

# The pool, unlabelled, with one object list and one held-out split per repository.
mkdir -p "$work/empty"
"$sagrid" corpus wild --from "$POOL" --labels "$work/empty" --out "$work/pool" > "$work/corpus.log" 2>&1
python3 - "$work" "$CANDIDATES_REAL" "${IN_SAMPLE:-0}" <<'PY'
import collections, json, os, sys
work, real_file, in_sample = sys.argv[1], sys.argv[2], sys.argv[3] == '1'
pool = os.path.join(work, 'pool', 'unlabelled')
by_source = collections.defaultdict(list)
for line in open(os.path.join(pool, 'manifest.jsonl')):
    entry = json.loads(line)
    by_source[entry['source']].append(entry)
real = None if in_sample else json.load(open(real_file))  # the shipped decision in sample
for i, (source, entries) in enumerate(sorted(by_source.items())):
    d = os.path.join(work, 'sources', '%02d' % i)
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, 'source.txt'), 'w').write(source + '\n')
    json.dump({'source': 'replay_loso.sh', 'rule': 'one wild-pool repository held out',
               'train': [], 'val': [e['id'] for e in entries]}, open(os.path.join(d, 'split.json'), 'w'))
    with open(os.path.join(d, 'objects.list'), 'w') as f:
        for e in entries:  # the ids `annotate` gives a folder's objects
            stem = os.path.splitext(os.path.basename(e['mesh']))[0]
            f.write('%s__%s\t%s\n' % (e['id'], stem, os.path.join(pool, e['mesh'])))
    if real:
        kept = dict(real)
        kept['sets'] = [s for s in real['sets'] if s['source'] != source]
        json.dump(kept, open(os.path.join(d, 'candidates.json'), 'w'))
PY

for d in "$work"/sources/*/; do
  models=$shipped
  if [ "${IN_SAMPLE:-0}" != 1 ]; then
    models=$d/models
    rm -rf "$models"
    "$sagrid" scorer train --candidates "$d/candidates.json" --candidates "$CANDIDATES_SH" \
      --candidates "$CANDIDATES_BENCH" ${SCORER_OPTIONS:-} --out "$models" > "$d/scorer.log" 2>&1
    "$sagrid" category train --data "$BENCH/train" --data "$DIST/train" --data "$GEN/stoves" \
      --data "$GEN/sinks" --data "$GEN/none" --data "$GEN/glass-stoves" \
      --data "$WILD/wild-train@3" --data "$WILD/wild-val@3" \
      --data "$SH/real-train@3" --data "$SH/real-val@3" --data "$SH/distractors@3" \
      --data "$root/../shared/data/real-dev@3" ${CATEGORY_INPUTS:---top-relief --part-statistics --file-name} --trees \
      --tree-depth 2 --threshold 0.5 --exclude-split "$d/split.json" --out "$models" \
      > "$d/category.log" 2>&1
  fi
  "$sagrid" annotate "$d/objects.list" --models "$models" --out "$work/predictions" > "$d/annotate.log" 2>&1
  echo "$models" > "$d/models.txt"
  log "$(cat "$d/source.txt") predicted"
done

# Each object's predictions beside its mesh (as replay-curation --predictions writes them), then
# one replay session per repository.
python3 "$root/tests/benchmarks/place_predictions.py" "$work/predictions"
rm -f "$work/curation.jsonl"
for d in "$work"/sources/*/; do
  mapfile -t folders < <(cut -f2 "$d/objects.list" | xargs -n1 dirname)
  "$sagrid" replay-curation "${folders[@]}" --truth "$root/resources/datasets/wild" \
    --models "$(cat "$d/models.txt")" --curation-log "$work/curation.jsonl" >> "$work/replay.log" 2>&1
done
"$sagrid" eval --curation "$work/curation.jsonl" --out "$work/report" > "$work/eval.log" 2>&1
cat "$work/report/curation.md"

# The same per curated category (the log names objects as annotate does: <folder>__<mesh stem>).
python3 - "$work/report/curation.json" "$root/resources/datasets/wild" <<'PY'
import collections, json, os, sys
report, truth = json.load(open(sys.argv[1])), sys.argv[2]
category = {}
for name in os.listdir(truth):
    file = os.path.join(truth, name, 'labels.json')
    if os.path.isfile(file):
        category[name] = json.load(open(file))['object']['category']
rows = collections.defaultdict(list)
for o in report['objects']:
    rows[category.get(o['object'].rsplit('__', 1)[0], '?')].append(o)
print('\n## By curated category\n\n| category | objects | edits / object | one key | KLM s / object |')
print('|---|---:|---:|---:|---:|')
for c, objects in sorted(rows.items()):
    n = len(objects)
    print('| %s | %d | %.2f | %.0f %% | %.1f |' % (c, n, sum(o['edits'] for o in objects) / n,
          100.0 * sum(o['one_key'] for o in objects) / n, sum(o['klm_seconds'] for o in objects) / n))
PY
