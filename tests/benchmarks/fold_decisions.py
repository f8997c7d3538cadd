"""The point decision's held-out figures when each fold of objects has its own networks: every
object's decisions are read from the `scorer cv` run of its fold (candidate files made with the
networks fine-tuned without that fold), and the figures are pooled over the folds as `scorer cv`
pools its sources.

    python3 tests/benchmarks/fold_decisions.py --lc LC/learning_curve.json [--lc ...]
        [--baseline CV/scorer_cv.json] CV1/scorer_cv.json CV2/scorer_cv.json ...
        [--per-model] [--repeats SEED,SEED,...]
        --lc: learning curves whose "folds" say which objects each fold holds (fold n of every
        --lc is the n-th CV file's; objects of no --lc fold are left out, so one --lc alone gives
        that curve's objects, e.g. the sinks); --baseline: one run over the same objects, beside.
        Prints objects, edits per hand point, one key and the single-point error (cm); with
        --per-model also each model's edits and the mean error of its first point (cm). With
        --repeats, the same for each of those `scorer cv --repeats` repeats of every file (the
        same generated objects left out in each run) instead of the full runs, then the means
        over them and, with --baseline, the mean paired difference and how many repeats are
        lower / higher than the baseline's.
"""
import json
import sys
from collections import defaultdict

from scorer_cv_pairs import edits as decision_edits


def numbers(decisions):
    """Edits per hand point, one key (%) and the mean single-point error (cm) of the decisions."""
    edits, hand, errors = defaultdict(int), 0, []
    for d in decisions:
        edits[d['object']] += decision_edits(d)
        hand += d['truth_points']
        if d['truth_points'] > 0 and d['best_point_error_m'] is not None:
            errors.append(d['best_point_error_m'] * 100)
    one_key = sum(1 for e in edits.values() if e == 0)
    return len(edits), sum(edits.values()) / hand, 100 * one_key / len(edits), sum(errors) / len(errors)


def figures(decisions):
    objects, edits, one_key, error = numbers(decisions)
    return (f"{objects} objects: {edits:.2f} edits per hand point, {one_key:.0f} % one key, "
            f"{error:.1f} cm")


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


def read_off(curves, runs, baseline, models, label=''):
    """Prints the figures of each object's own fold's run (and the baseline's on the same
    objects); returns both as numbers()."""
    fold_of = {}
    for folds in curves:
        for n, objects in enumerate(folds):
            for o in objects:
                fold_of[o] = n
    pooled = [d for n, run in enumerate(runs) for d in run if fold_of.get(d['object']) == n]
    if not pooled:
        sys.exit('no decision of a --lc fold in its CV file: are the files in fold order?')
    print(f'{label}each fold its own networks:', figures(pooled))
    if models:
        print(per_model(pooled))
    if baseline is None:
        return numbers(pooled), None
    kept = {d['object'] for d in pooled}
    same = [d for d in baseline if d['object'] in kept]
    print(f'{label}baseline, the same objects:', figures(same))
    if models:
        print(per_model(same))
    return numbers(pooled), numbers(same)


def main(argv):
    curves, files, baseline, models, seeds = [], [], None, False, None
    rest = iter(argv)
    for arg in rest:
        if arg == '--lc':
            curves.append(json.load(open(next(rest)))['folds'])
        elif arg == '--per-model':
            models = True
        elif arg == '--repeats':
            seeds = [int(s) for s in next(rest).split(',')]
        elif arg == '--baseline':
            baseline = next(rest)
        else:
            files.append(arg)
    if not curves or not files:
        sys.exit(__doc__)
    if seeds is None:
        read_off(curves, [decisions_of(f, None) for f in files],
                 baseline and decisions_of(baseline, None), models)
        return
    pairs = [read_off(curves, [decisions_of(f, seed) for f in files],
                      baseline and decisions_of(baseline, seed), models, f'repeat {seed}: ')
             for seed in seeds]
    names = ('edits per hand point', 'one key (%)', 'single-point error (cm)')
    for i, name in enumerate(names, 1):
        mine = [p[0][i] for p in pairs]
        line = f'mean of {len(seeds)} repeats, {name}: {sum(mine) / len(mine):.3f}'
        if baseline:
            theirs = [p[1][i] for p in pairs]
            diffs = [a - b for a, b in zip(mine, theirs)]
            line += (f' against {sum(theirs) / len(theirs):.3f} (difference '
                     f'{sum(diffs) / len(diffs):+.3f}; lower in {sum(d < 0 for d in diffs)}, '
                     f'higher in {sum(d > 0 for d in diffs)})')
        print(line)


if __name__ == '__main__':
    main(sys.argv[1:])
