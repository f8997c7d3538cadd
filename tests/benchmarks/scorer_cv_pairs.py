"""Paired comparisons of `sagrid scorer cv` runs that `sagrid scorer compare` does not print.

    python3 tests/benchmarks/scorer_cv_pairs.py held-out A B [--exclude-source S ...]
        Two full runs' held-out decisions on the (object, model) pairs both decided: edits per
        hand point, the first point's mean error over those decisions, per model; with
        --exclude-source, only the other sources' decisions (e.g. the tuned-on ones left out).
    python3 tests/benchmarks/scorer_cv_pairs.py repeats NEW1,NEW2 OLD1,OLD2
        Two sets of `--repeats` runs, repeat by repeat (paired by seed), for every curated object
        and for the sources not passed as --tuned-on: edits per hand point, one key and the best
        point's error, with how many repeats moved each way; then per model, each repeat's edits
        and its decisions whose first point is more than 5 cm off.
"""
import json
import math
import statistics
import sys


def held_out(path):
    runs = json.load(open(path + '/scorer_cv.json'))['held_out_decisions']
    return {(d['object'], d['model']): d for d in runs}


def edits(d):
    return d['drags'] + d['additions'] + d['deletions']


def first_point_off(d):
    return d['best_point_error_m'] is not None and d['best_point_error_m'] > 0.05


def compare_held_out(a_path, b_path, excluded):
    a, b = held_out(a_path), held_out(b_path)
    keys = sorted(k for k in set(a) & set(b) if a[k]['source'] not in excluded)
    points = sum(a[k]['truth_points'] for k in keys)
    objects = len({k[0] for k in keys})
    print(f'{len(keys)} decisions on {objects} objects, {points} true points')
    for name, runs in ((a_path, a), (b_path, b)):
        errors = [runs[k]['best_point_error_m'] for k in keys if runs[k]['best_point_error_m'] is not None]
        total = sum(edits(runs[k]) for k in keys)
        print(f'  {name}: {total} edits, {total / points:.3f} per hand point; first point '
              f'{100 * statistics.mean(errors):.2f} cm (mean over {len(errors)} decisions)')
    for model in sorted({k[1] for k in keys}):
        mk = [k for k in keys if k[1] == model]
        print(f'  {model}: {sum(edits(a[k]) for k in mk)} -> {sum(edits(b[k]) for k in mk)} edits '
              f'of {sum(a[k]["truth_points"] for k in mk)}')


def repeats(paths):
    by_seed = {}
    for path in paths.split(','):
        for r in json.load(open(path + '/scorer_cv.json'))['spread']['repeats']:
            by_seed[r['seed']] = r
    return by_seed


def compare_repeats(new_paths, old_paths):
    new, old = repeats(new_paths), repeats(old_paths)
    seeds = sorted(set(new) & set(old))
    for group in ('with_curated', 'unseen_with_curated'):
        n = [new[s][group] for s in seeds]
        o = [old[s][group] for s in seeds]
        print(f'{group}: {len(seeds)} repeats, {o[0]["objects"]} -> {n[0]["objects"]} objects')
        for field, scale, unit in (('edits_per_hand_point', 1, ''), ('one_key_share', 100, ' %'),
                                   ('single_error_m', 100, ' cm')):
            diff = [scale * (x[field] - y[field]) for x, y in zip(n, o)]
            sd = statistics.stdev(diff) if len(diff) > 1 else 0.0
            se = sd / math.sqrt(len(diff))
            ratio = f'{statistics.mean(diff) / se:+.2f}' if se > 0 else 'no'
            print(f'  {field}: {statistics.mean(scale * y[field] for y in o):.3f} -> '
                  f'{statistics.mean(scale * x[field] for x in n):.3f}{unit} (difference '
                  f'{statistics.mean(diff):+.3f}, sd {sd:.3f}, se {se:.3f}, {ratio} standard errors; '
                  f'lower in {sum(d < 0 for d in diff)}, higher in {sum(d > 0 for d in diff)})')
    print('per model, mean over the repeats:')
    for model in sorted({d['model'] for s in seeds for d in new[s]['held_out_decisions']}):
        def per_repeat(runs, count):
            return [sum(count(d) for d in runs[s]['held_out_decisions'] if d['model'] == model)
                    for s in seeds]
        for name, count in (('edits', edits), ('first point off', first_point_off)):
            o, n = per_repeat(old, count), per_repeat(new, count)
            print(f'  {model} {name}: {statistics.mean(o):.1f} -> {statistics.mean(n):.1f} '
                  f'(fewer in {sum(y < x for x, y in zip(o, n))}, more in {sum(y > x for x, y in zip(o, n))})')


if __name__ == '__main__':
    if len(sys.argv) >= 4 and sys.argv[1] == 'held-out':
        rest = sys.argv[4:]
        excluded = {rest[i + 1] for i in range(len(rest) - 1) if rest[i] == '--exclude-source'}
        compare_held_out(sys.argv[2], sys.argv[3], excluded)
    elif len(sys.argv) == 4 and sys.argv[1] == 'repeats':
        compare_repeats(sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)
