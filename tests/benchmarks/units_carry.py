#!/usr/bin/env python3
"""Units actions a curator needs over a queue under three rules for the units set on one object of
a source (repository: the id's part before "__") and the other objects of that source:
none (each object shows its own size guess), always (the source's units replace the guess),
unless_sure (they replace it unless only one unit fits the object's size). An object needs an
action where the units it shows are off the curated ones by more than 1.5x; the curator then sets
the curated units, which become the source's. Objects are taken in id order, as the GUI's queue.

  tests/benchmarks/units_carry.py PRED TRUTH
PRED: an `annotate --out` folder (labels with object.meters_per_unit_guess); TRUTH: curated
<id>/labels.json folders (object.meters_per_unit, else metres)."""
import json
import sys
from pathlib import Path


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
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
        return max(a, b) / min(a, b) > 1.5

    for rule in ("none", "always", "unless_sure"):
        carried, needed = {}, []
        for i in sorted(own):
            shown, sure = own[i]
            source = i.split("__")[0]
            if source in carried and (rule == "always" or (rule == "unless_sure" and not sure)):
                shown = carried[source]
            if off(shown, truth[i]):
                needed.append(i)
                carried[source] = truth[i]
        print(f"{rule}: {len(needed)} units actions on {len(own)} objects ({', '.join(needed)})")


if __name__ == "__main__":
    main()
