#!/usr/bin/env python3
"""Units actions a curator needs over a queue under three rules for the units set on one object of
a source (repository: the id's part before "__") and the other objects of that source:
none (each object shows its own size guess), always (the source's units replace the guess),
unless_sure (they replace it unless only one unit fits the object's size). An object needs an
action where the units it shows are off the curated ones by more than TOLERANCE (a ratio, default
1.5: `sagrid eval --units`'s "right"; 1.001 is the replayed curator's); the curator then sets
the curated units, which become the source's. Objects are taken in id order, as the GUI's queue.

  tests/benchmarks/units_carry.py PRED TRUTH [TOLERANCE]
PRED: an `annotate --out` folder (labels with object.meters_per_unit_guess); TRUTH: curated
<id>/labels.json folders (object.meters_per_unit, else metres)."""
import json
import sys
from pathlib import Path


TOLERANCE = 1.5


def main():
    global TOLERANCE
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    if len(sys.argv) == 4:
        TOLERANCE = float(sys.argv[3])
    guesses = {}
    for f in Path(sys.argv[1]).glob("*/labels.json"):
        o = json.loads(f.read_text())["object"]
        g = o.get("meters_per_unit_guess") or {}
        guesses[f.parent.name] = (float(g.get("meters_per_unit", o.get("meters_per_unit", 1.0))),
                                  bool(g.get("sure", False)))
    truth = {f.parent.name: float(json.loads(f.read_text())["object"].get("meters_per_unit", 1.0))
             for f in Path(sys.argv[2]).glob("*/labels.json")}
    # An annotate folder names an object <id> or <id>__<mesh stem>.
    own = {}
    for name, g in guesses.items():
        for i in truth:
            if name == i or name.startswith(i + "__"):
                own[i] = g
    missing = sorted(set(truth) - set(own))
    if missing:
        print("no guess for", ", ".join(missing))

    def off(a, b):
        return max(a, b) / min(a, b) > TOLERANCE

    def carries(rule, carried, guess, sure):
        if rule == "always":
            return True
        if rule == "unless_sure":
            return not sure
        if rule == "unless_sure_and_far":  # a sure guess more than 2x from the source's units
            return not sure or max(carried, guess) / min(carried, guess) <= 2.0
        return False

    for rule in ("none", "always", "unless_sure", "unless_sure_and_far"):
        carried, needed = {}, []
        for i in sorted(own):
            shown, sure = own[i]
            source = i.split("__")[0]
            if source in carried and carries(rule, carried[source], shown, sure):
                shown = carried[source]
            if off(shown, truth[i]):
                needed.append(i)
                carried[source] = truth[i]
        print(f"{rule}: {len(needed)} units actions on {len(own)} objects ({', '.join(needed)})")


if __name__ == "__main__":
    main()
