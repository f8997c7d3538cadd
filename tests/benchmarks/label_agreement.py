#!/usr/bin/env python3
"""Agreement of two curations of the same objects (e.g. labels made in the GUI against labels made
from geometry and renders): per object, the category and, per point type, the points paired
nearest first (in metres, by each object's meters_per_unit), the points only one side has.

  tests/benchmarks/label_agreement.py A B   # A, B: folders of <object>/labels.json (same folder names)

Prints one row per object, the objects only one side has (by category) and the totals; objects
are paired by folder name."""
import json
import math
import statistics
import sys
from pathlib import Path


def read(folder):
    out = {}
    for f in sorted(Path(folder).glob("*/labels.json")):
        out[f.parent.name] = json.loads(f.read_text())
    return out


def metres_per_unit(labels):
    return float(labels.get("object", {}).get("meters_per_unit", 1.0))


def points(labels):
    by_type = {}
    for a in labels.get("affordances", []):
        by_type.setdefault(a["type"], []).append(a["position"])
    return by_type


def pair(a, b, scale):
    """Greedy nearest pairs between two point lists; returns distances (m), unpaired in a, in b."""
    cand = sorted((math.dist(p, q) * scale, i, j) for i, p in enumerate(a) for j, q in enumerate(b))
    used_a, used_b, dists = set(), set(), []
    for d, i, j in cand:
        if i in used_a or j in used_b:
            continue
        used_a.add(i), used_b.add(j), dists.append(d)
    return dists, len(a) - len(used_a), len(b) - len(used_b)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = read(sys.argv[1]), read(sys.argv[2])
    common = sorted(set(a) & set(b))
    if not common:
        sys.exit("no object folder in both")
    all_d, only_a, only_b, same_cat = [], 0, 0, 0
    print("| object | category A / B | pairs | median cm | max cm | only A | only B |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for name in common:
        la, lb = a[name], b[name]
        ca, cb = la.get("object", {}).get("category", ""), lb.get("object", {}).get("category", "")
        same_cat += ca == cb
        scale = metres_per_unit(lb)
        pa, pb = points(la), points(lb)
        d, na, nb = [], 0, 0
        for t in sorted(set(pa) | set(pb)):
            dt, ua, ub = pair(pa.get(t, []), pb.get(t, []), scale)
            d += dt
            na += ua
            nb += ub
        all_d += d
        only_a += na
        only_b += nb
        med = f"{100 * statistics.median(d):.1f}" if d else ""
        mx = f"{100 * max(d):.1f}" if d else ""
        print(f"| {name} | {ca} / {cb} | {len(d)} | {med} | {mx} | {na} | {nb} |")
    print()
    for side, mine, other in (("A", a, b), ("B", b, a)):
        alone = sorted(set(mine) - set(other))
        if alone:
            cats = {}
            for name in alone:
                c = mine[name].get("object", {}).get("category", "")
                cats[c] = cats.get(c, 0) + 1
            print(f"objects only in {side}: {len(alone)} (" +
                  ", ".join(f"{c or 'no category'} {n}" for c, n in sorted(cats.items())) + ")")
    print(f"objects {len(common)}, same category {same_cat}; pairs {len(all_d)}, median "
          f"{100 * statistics.median(all_d):.1f} cm, within 2 cm {sum(x <= 0.02 for x in all_d)}, "
          f"within 5 cm {sum(x <= 0.05 for x in all_d)}; only in A {only_a}, only in B {only_b}")


if __name__ == "__main__":
    main()
