"""Candidate files whose curated objects are each read by a network that never trained on them:
every (object, model) set of the base files that a fold's file also holds is replaced by the
fold's (made with `sagrid scorer candidates --models FOLD_MODELS --data FOLD_DIR`, FOLD_MODELS a
learning curve's fine-tune without that fold). `scorer cv` on the output then measures the point
decision on networks fine-tuned on curated real data without leaking the held-out objects.

    python3 tests/benchmarks/fold_candidates.py OUT_DIR BASE.json [BASE.json ...]
        --fold FOLD.json [--fold FOLD.json ...]
        Writes OUT_DIR/<base name>.json per base file and prints how many sets were replaced.

A replaced set keeps the base set's source (a fold folder of links names no source) and its
network_weights: `scorer cv` refuses a model's sets made by different weights, which guards the
product against mixing models folders; here the mix is the point of the measurement.
"""
import json
import os
import sys


def main(argv):
    out, bases, folds = argv[0], [], []
    rest = iter(argv[1:])
    for arg in rest:
        if arg == '--fold':
            folds.append(next(rest))
        else:
            bases.append(arg)
    replacement = {}
    for fold in folds:
        for s in json.load(open(fold))['sets']:
            replacement[(s['object'], s['model'])] = s
    os.makedirs(out, exist_ok=True)
    for base in bases:
        data = json.load(open(base))
        replaced = 0
        for i, s in enumerate(data['sets']):
            fold_set = replacement.get((s['object'], s['model']))
            if fold_set is None:
                continue
            data['sets'][i] = dict(fold_set, source=s['source'],
                                   network_weights=s['network_weights'])
            replaced += 1
        json.dump(data, open(os.path.join(out, os.path.basename(base)), 'w'))
        print(f'{base}: {replaced} of {len(data["sets"])} sets replaced')


if __name__ == '__main__':
    main(sys.argv[1:])
