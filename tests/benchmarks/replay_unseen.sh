#!/usr/bin/env bash
# Curation replayed on labelled objects that no decision was made on (issues 40 and 41): a models
# folder (default the shipped one) predicts every object of the given datasets with no category
# given, as `sagrid annotate` does; the objects are then reviewed through the GUI's session
# (`sagrid replay-curation`, the curator who knows their labels) in one session, and `sagrid eval
# --curation` reports the log. No folds: use it only for objects the models were not fitted on,
# e.g. a package curated after the shipped decisions were made (resources/models/README.md
# "Session 49"); for the pool, whose objects the shipped decisions were fitted on, replay_loso.sh.
#
#   tests/benchmarks/replay_unseen.sh BUILD_DIR WORK_DIR DATASET...
#
# DATASET: a labelled dataset folder (manifest.jsonl, <id>/labels.json beside the mesh). In the
# environment: MODELS, the models folder (default resources/models); PACKAGE, only the objects
# whose provenance.json names this package (e.g. sweethome3d-furniture-nonfree in a `sagrid corpus
# sweethome3d --non-free` folder). About a minute for 32 objects.
set -euo pipefail

. "$(dirname "$0")/bench_dirs.sh" replay-unseen "${1:-}" "${2:-}"
shift 2 || { echo "usage: replay_unseen.sh BUILD_DIR WORK_DIR DATASET..." >&2; exit 2; }
[ $# -gt 0 ] || { echo "replay_unseen.sh: give at least one dataset folder" >&2; exit 2; }
[ -x "$sagrid" ] || { echo "replay_unseen.sh: no $sagrid (build it first)" >&2; exit 1; }
models=${MODELS:-$root/resources/models}

# Each object's folder copied without its labels (the truth goes to truth/<id>/labels.json).
rm -rf "$work/objects" "$work/truth" "$work/predictions" "$work/curation.jsonl"
python3 - "$work" "${PACKAGE:-}" "$@" <<'PY'
import json, os, shutil, sys
work, package, datasets = sys.argv[1], sys.argv[2], sys.argv[3:]
for dataset in datasets:
    for line in open(os.path.join(dataset, 'manifest.jsonl')):
        if not line.strip():
            continue
        entry = json.loads(line)
        source = os.path.join(dataset, os.path.dirname(entry['mesh']) or entry['id'])
        provenance = os.path.join(source, 'provenance.json')
        if package and (not os.path.isfile(provenance) or
                        json.load(open(provenance)).get('package') != package):
            continue
        target = os.path.join(work, 'objects', entry['id'])
        shutil.copytree(source, target, ignore=shutil.ignore_patterns('labels.json', '.sagrid-cache'))
        os.makedirs(os.path.join(work, 'truth', entry['id']))
        shutil.copy(os.path.join(source, 'labels.json'), os.path.join(work, 'truth', entry['id']))
PY

"$sagrid" annotate "$work/objects" --models "$models" --out "$work/predictions" \
  > "$work/annotate.log" 2>&1
# Each object's predictions beside its mesh, where the GUI looks for them.
python3 "$root/tests/benchmarks/place_predictions.py" "$work/predictions"
"$sagrid" replay-curation "$work"/objects/*/ --truth "$work/truth" --models "$models" \
  --curation-log "$work/curation.jsonl" > "$work/replay.log" 2>&1
"$sagrid" eval --curation "$work/curation.jsonl" --out "$work/report" > "$work/eval.log" 2>&1
"$sagrid" eval --units "$work/predictions" --truth "$work/truth" --out "$work/units" \
  > "$work/units.log" 2>&1
cat "$work/report/curation.md"
head -6 "$work/units/units.md"
