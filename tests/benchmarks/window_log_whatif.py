#!/usr/bin/env python3
"""What a curation log made in the window would have been with a later fix, for `sagrid eval
--curation` before/after figures of fixes no replay exercises (session 51):

  --twin CARRIED=FROM   the object CARRIED opens with FROM's points (same-geometry carry): its
                        looks and edits go, its open names FROM, its accept_all stays.
  --drop-retypes        retype actions go: in the session-50 window log all three were the
                        curator's slip of the global number key 2 (fluidsource, not togglebutton,
                        on a stove), which the category's own key order now prevents.

  python3 tests/benchmarks/window_log_whatif.py resources/datasets/sweethome3d/curation_window.jsonl \\
      OUT.jsonl --twin mobilettoLavaboWenge=mobilettoLavaboBlu --drop-retypes
  build/sagrid eval --curation OUT.jsonl --out DIR

Logged seconds are left as they were: only the edit counts and the keystroke-level estimate mean
anything in the result.
"""
import argparse, json

EDITS = {'look', 'drag', 'add', 'delete', 'delete_rest', 'retype', 'copies', 'edit', 'accept', 'undo', 'redo'}

parser = argparse.ArgumentParser()
parser.add_argument('log')
parser.add_argument('out')
parser.add_argument('--twin', action='append', default=[], help='CARRIED=FROM')
parser.add_argument('--drop-retypes', action='store_true')
args = parser.parse_args()
twins = dict(t.split('=', 1) for t in args.twin)
kept = dropped = 0
with open(args.log) as log, open(args.out, 'w') as out:
    for line in log:
        if not line.strip():
            continue
        action = json.loads(line)
        carried_from = twins.get(action.get('object'))
        if (carried_from and action['action'] in EDITS) or (args.drop_retypes and action['action'] == 'retype'):
            dropped += 1
            continue
        if carried_from and action['action'] == 'open':
            action['carried_from'] = carried_from
        out.write(json.dumps(action) + '\n')
        kept += 1
print(f'{kept} actions kept, {dropped} dropped -> {args.out}')
