"""Object by object, how one model's single point moves between two `sagrid eval` runs on the
same objects (e.g. a learning curve's held-out fold, before and after its fine-tune), which
`eval --compare` gives only as means.

    python3 tests/benchmarks/eval_object_changes.py MODEL BEFORE1,AFTER1 [BEFORE2,AFTER2 ...]
        [--exclude ID ...] [--margin CM]
        BEFORE / AFTER: eval output folders (their eval.json). Per object the paper's error in
        cm before and after; then, over the objects not excluded, the means and how many come
        closer or go farther by more than the margin (default 0.5 cm).
"""
import json
import sys


def errors(folder, model):
    objects = json.load(open(folder + '/eval.json'))['per_object']
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
    print(f"{len(kept)} objects: {sum(x for x, _ in kept) / len(kept):.1f} -> "
          f"{sum(y for _, y in kept) / len(kept):.1f} cm; closer {closer}, farther {farther}, "
          f"within {margin} cm {len(kept) - closer - farther}")


if __name__ == '__main__':
    main(sys.argv[1:])
