"""The point decision's held-out figures when each fold of objects has its own networks: every
object's decisions are read from the `scorer cv` run of its fold (candidate files made with the
networks fine-tuned without that fold), and the figures are pooled over the folds as `scorer cv`
pools its sources.

    python3 tests/benchmarks/fold_decisions.py --lc LC/learning_curve.json [--lc ...]
        [--baseline CV/scorer_cv.json] CV1/scorer_cv.json CV2/scorer_cv.json ...
        [--per-model] [--repeat SEED]
        --lc: learning curves whose "folds" say which objects each fold holds (fold n of every
        --lc is the n-th CV file's; objects of no --lc fold are left out, so one --lc alone gives
        that curve's objects, e.g. the sinks); --baseline: one run over the same objects, beside.
        Prints objects, edits per hand point, one key and the single-point error (cm); with
        --per-model also each model's edits and the mean error of its first point (cm). With
        --repeat, every file's decisions are those of its `scorer cv --repeats` repeat of that
        seed (the same generated objects left out in each run), not its full run's.
"""
import json
import sys
from collections import defaultdict

from scorer_cv_pairs import edits as decision_edits


def figures(decisions):
    edits, hand, errors = defaultdict(int), 0, []
    for d in decisions:
        edits[d['object']] += decision_edits(d)
        hand += d['truth_points']
        if d['truth_points'] > 0 and d['best_point_error_m'] is not None:
            errors.append(d['best_point_error_m'] * 100)
    one_key = sum(1 for e in edits.values() if e == 0)
    return (f"{len(edits)} objects: {sum(edits.values()) / hand:.2f} edits per hand point, "
            f"{100 * one_key / len(edits):.0f} % one key, "
            f"{sum(errors) / len(errors):.1f} cm")


def per_model(decisions):
    by_model = defaultdict(list)
    for d in decisions:
        by_model[d['model']].append(d)
    lines = []
    for model, ds in sorted(by_model.items()):
        errors = [d['best_point_error_m'] * 100 for d in ds
                  if d['truth_points'] > 0 and d['best_point_error_m'] is not None]
        lines.append(f"  {model}: {sum(decision_edits(d) for d in ds)} edits, first point "
                     f"{sum(errors) / len(errors):.1f} cm" if errors else f"  {model}: no points")
    return '\n'.join(lines)


def decisions_of(path, seed):
    report = json.load(open(path))
    if seed is None:
        return report['held_out_decisions']
    for r in report.get('spread', {}).get('repeats', []):
        if r['seed'] == seed:
            return r['held_out_decisions']
    sys.exit(f'{path}: no repeat of seed {seed}')


def main(argv):
    curves, runs, baseline, models, seed = [], [], None, False, None
    for i, arg in enumerate(argv):
        if arg == '--repeat':
            seed = int(argv[i + 1])
    rest = iter(argv)
    for arg in rest:
        if arg == '--lc':
            curves.append(json.load(open(next(rest)))['folds'])
        elif arg == '--per-model':
            models = True
        elif arg == '--repeat':
            next(rest)
        elif arg == '--baseline':
            baseline = decisions_of(next(rest), seed)
        else:
            runs.append(decisions_of(arg, seed))
    if not curves or not runs:
        sys.exit(__doc__)
    fold_of = {}
    for folds in curves:
        for n, objects in enumerate(folds):
            for o in objects:
                fold_of[o] = n
    pooled = [d for n, run in enumerate(runs) for d in run if fold_of.get(d['object']) == n]
    if not pooled:
        sys.exit('no decision of a --lc fold in its CV file: are the files in fold order?')
    print('each fold its own networks:', figures(pooled))
    if models:
        print(per_model(pooled))
    if baseline is not None:
        kept = {d['object'] for d in pooled}
        same = [d for d in baseline if d['object'] in kept]
        print('baseline, the same objects:', figures(same))
        if models:
            print(per_model(same))


if __name__ == '__main__':
    main(sys.argv[1:])
