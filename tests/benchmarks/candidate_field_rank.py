"""Where a model's field ranks the candidate nearest each true point, read from `sagrid scorer
candidates` files: whether a miss is the field's (the nearest candidate is not its best) or the
ranking's.

    python3 tests/benchmarks/candidate_field_rank.py MODEL CANDIDATES.json [...] --object ID [...]
        Per true point of each named object: the nearest candidate's distance (cm) and rank by
        the field (0 = the field's best), its height in the object, and the field's best: its
        distance to that true point and its height.
"""
import json
import math
import sys


def main(argv):
    model, files, objects = argv[0], [], []
    target = files
    for arg in argv[1:]:
        if arg == '--object':
            target = objects
        else:
            target.append(arg)
    sets, height = {}, None
    for path in files:
        data = json.load(open(path))
        height = data['features'].index('height')
        sets.update({s['object']: s for s in data['sets'] if s['model'] == model})
    for name in objects:
        s = sets.get(name)
        if s is None or not s['truth']:
            print(f'{name}: no {model} candidates with true points')
            continue
        by_field = sorted(range(len(s['distances'])), key=lambda i: s['distances'][i])
        best = by_field[0]
        for truth in s['truth']:
            cm = [math.dist(p, truth) * s['meters_per_unit'] * 100 for p in s['surface']]
            near = min(range(len(cm)), key=cm.__getitem__)
            print(f"{name[:34]:34s} {len(cm):3d} candidates; nearest {cm[near]:5.1f} cm, field rank "
                  f"{by_field.index(near):2d}, height {s['features'][near][height]:.2f} | field's "
                  f"best {cm[best]:5.1f} cm, height {s['features'][best][height]:.2f}")


if __name__ == '__main__':
    main(sys.argv[1:])
