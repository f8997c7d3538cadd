"""Object by object, how one model's single point (or the curator's edits) moves between
`sagrid eval` runs on the same objects, pooled over several pairs of runs: e.g. each fold of a
learning curve before and after its fine-tune, each with its own models, which one `eval
--compare` cannot pool (it pairs the sets of one run).

    python3 tests/benchmarks/eval_object_changes.py MODEL BEFORE1,AFTER1 [BEFORE2,AFTER2 ...]
        [--exclude ID ...] [--margin CM]
        MODEL: a model name (the paper's error in cm) or `edits` (the object's point edits, all
        its models summed). BEFORE / AFTER: eval output folders (their eval.json; for an
        `eval --compare` run, OUT and OUT/compare-1). Per object the figure before and after;
        then, over the objects not excluded, the means, the standard error of the per-object
        differences (the noise the product's guards adopt beyond) and how many go down or up by
        more than the margin (default 0.5).
"""
import json
import math
import sys


def errors(folder, model):
    objects = json.load(open(folder + '/eval.json'))['per_object']
    if model == 'edits':
        return {o['id']: sum(n for kinds in o.get('edits', {}).values() for n in kinds.values())
                for o in objects}
    return {o['id']: o['paper_error_m'][model] * 100 for o in objects
            if model in o.get('paper_error_m', {})}


def main(argv):
    model, pairs, exclude, margin = argv[0], [], set(), 0.5
    rest = iter(argv[1:])
    for arg in rest:
        if arg == '--exclude':
            exclude.add(next(rest))
        elif arg == '--margin':
            margin = float(next(rest))
        else:
            pairs.append(arg.split(','))
    rows = []
    for before, after in pairs:
        a, b = errors(before, model), errors(after, model)
        rows += [(i, a[i], b[i]) for i in sorted(a) if i in b]
    for i, x, y in rows:
        print(f"{i:40s} {x:6.1f} -> {y:6.1f}{'  (excluded)' if i in exclude else ''}")
    kept = [(x, y) for i, x, y in rows if i not in exclude]
    if not kept:
        print('no object measured in both runs')
        return
    closer = sum(y < x - margin for x, y in kept)
    farther = sum(y > x + margin for x, y in kept)
    n = len(kept)
    change = [y - x for x, y in kept]
    mean = sum(change) / n
    noise = (math.sqrt(sum((d - mean) ** 2 for d in change) / (n - 1) / n) if n > 1
             else float('nan'))
    print(f"{n} objects: {sum(x for x, _ in kept) / n:.2f} -> {sum(y for _, y in kept) / n:.2f} "
          f"(noise {noise:.2f}); sums {sum(x for x, _ in kept):.1f} -> "
          f"{sum(y for _, y in kept):.1f}; lower {closer}, higher {farther}, "
          f"within {margin} {n - closer - farther}")


if __name__ == '__main__':
    main(sys.argv[1:])
