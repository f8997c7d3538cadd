#!/usr/bin/env python3
"""Units actions a curator needs over a queue under rules for the units set on one object of a
source (repository: the id's part before "__") and the other objects of that source: never (each
object shows its own size guess), always (the source's units replace the guess), unless_sure (they
replace it unless only one unit fits the object's size), unless_sure_and_far (unless only one unit
fits and the source's units are more than FACTOR from the guess; the GUI's rule, FACTOR 2). An
object needs an action where the units it shows are off the curated ones by more than TOLERANCE
(a ratio, default 1.5: `sagrid eval --units`'s "right"; 1.001 is the replayed curator's); the
curator then sets the curated units, which become the source's. Objects are taken in id order, as
the GUI's queue. The last line chooses FACTOR among 1.5, 2, 3, 5 leaving each repository out (the
factor with the fewest actions on the other repositories, ties to the smallest) and counts the
held-out repository's actions under it.

  tests/benchmarks/units_carry.py PRED TRUTH [TOLERANCE]
PRED: an `annotate --out` folder (labels with object.meters_per_unit_guess), e.g. WORK/predictions
of `tests/benchmarks/replay_loso.sh BUILD WORK`; TRUTH: curated <id>/labels.json folders
(object.meters_per_unit, else metres)."""
import json
import sys
from pathlib import Path

FACTORS = (1.5, 2.0, 3.0, 5.0)


def ratio(a, b):
    return max(a, b) / min(a, b)


def rule(name, factor=2.0):
    """Whether the source's units replace an object's own guess."""
    return {
        "never": lambda carried, guess, sure: False,
        "always": lambda carried, guess, sure: True,
        "unless_sure": lambda carried, guess, sure: not sure,
        "unless_sure_and_far": lambda carried, guess, sure: not sure or ratio(carried, guess) <= factor,
    }[name]


def needed_by_source(own, truth, carries, tolerance):
    """The objects needing a units action, per source, replaying the queue under one rule."""
    carried, needed = {}, {}
    for i in sorted(own):
        shown, sure = own[i]
        source = i.split("__")[0]
        if source in carried and carries(carried[source], shown, sure):
            shown = carried[source]
        if ratio(shown, truth[i]) > tolerance:
            needed.setdefault(source, []).append(i)
            carried[source] = truth[i]
    return needed


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    tolerance = float(sys.argv[3]) if len(sys.argv) == 4 else 1.5
    truth = {f.parent.name: float(json.loads(f.read_text())["object"].get("meters_per_unit", 1.0))
             for f in Path(sys.argv[2]).glob("*/labels.json")}
    own = {}  # an annotate folder names an object <id> or <id>__<mesh stem>
    for f in Path(sys.argv[1]).glob("*/labels.json"):
        i = next((t for t in truth if f.parent.name == t or f.parent.name.startswith(t + "__")), None)
        if i is None:
            continue
        o = json.loads(f.read_text())["object"]
        g = o.get("meters_per_unit_guess") or {}
        own[i] = (float(g.get("meters_per_unit", o.get("meters_per_unit", 1.0))), bool(g.get("sure", False)))
    missing = sorted(set(truth) - set(own))
    if missing:
        print("no guess for", ", ".join(missing))

    for name in ("never", "always", "unless_sure", "unless_sure_and_far"):
        needed = needed_by_source(own, truth, rule(name), tolerance)
        objects = sorted(i for ids in needed.values() for i in ids)
        print(f"{name}: {len(objects)} units actions on {len(own)} objects ({', '.join(objects)})")

    per_factor = {f: needed_by_source(own, truth, rule("unless_sure_and_far", f), tolerance) for f in FACTORS}
    sources = sorted({i.split("__")[0] for i in own})
    total, chosen = 0, []
    for held_out in sources:
        cost = {f: sum(len(ids) for s, ids in per_factor[f].items() if s != held_out) for f in FACTORS}
        best = min(FACTORS, key=lambda f: (cost[f], f))
        chosen.append(best)
        total += len(per_factor[best].get(held_out, []))
    print(f"unless_sure_and_far, factor chosen leaving each of {len(sources)} repositories out: "
          f"{total} units actions (factors chosen: " +
          ", ".join(f"{f:g} x{chosen.count(f)}" for f in FACTORS if chosen.count(f)) + ")")


if __name__ == "__main__":
    main()
