#!/usr/bin/env python3
"""Leave-one-source-out test of the units guess (issue 41 item 5) on curated real objects.

Compares, on every curated object (its largest extent and the product's own guess from
`sagrid info --units-for CATEGORY`, its curated meters_per_unit and category), today's rule
(core/mesh/unit_guess.cpp: one hand-set size range per category, the commoner unit on ties) with a size prior learned from the other sources
(log-normal largest extent per category, unit shares counted, a log-uniform "game units"
alternative over DECADES decades). A guess is right within a factor 1.5 of the curated value.

  python3 tests/benchmarks/unit_guess_loso.py build/sagrid W/wild-train W/wild-val SH/real-train \
      SH/real-val SH/distractors ../shared/data/real-dev
"""
import collections, json, math, os, subprocess, sys

UNITS = [('m', 1.0), ('cm', 0.01), ('mm', 0.001), ('in', 0.0254)]


def objects(sagrid, folders):
    for folder in folders:
        for name in sorted(os.listdir(folder)):
            labels_file = os.path.join(folder, name, 'labels.json')
            if not os.path.isfile(labels_file):
                continue
            labels = json.load(open(labels_file))
            o = labels['object'] if isinstance(labels['object'], dict) else {'id': labels['object']}
            mesh = o.get('mesh') or next(f for f in sorted(os.listdir(os.path.dirname(labels_file)))
                                         if f.split('.')[-1].lower() in ('obj', 'glb', 'gltf', 'ply', 'stl', 'dae', 'fbx'))
            category = o.get('category', labels.get('category', ''))
            info = subprocess.run([sagrid, 'info', os.path.join(folder, name, mesh), '--up', o.get('up', 'z'),
                                   '--units-for', category, '--json'], capture_output=True, text=True)
            if info.returncode != 0:
                continue
            report = json.loads(info.stdout)
            # As core/dataset/object_source.h: the repository, else the library, else the folder.
            provenance = o.get('provenance') or {}
            beside = os.path.join(folder, name, 'provenance.json')
            if not provenance and os.path.isfile(beside):
                provenance = json.load(open(beside))
            source = provenance.get('repo') or provenance.get('library') or folder
            box = report['bounds']
            yield dict(id=o['id'], category=category,
                       extent=max(hi - lo for lo, hi in zip(box['min'], box['max'])),
                       mpu=o.get('meters_per_unit', 1.0), source=source,
                       today=report['units_guess']['meters_per_unit'])


def unit_class(mpu):
    return next((n for n, m in UNITS if max(mpu / m, m / mpu) <= 1.5), 'other')


def fit(train):
    logs = collections.defaultdict(list)
    for r in train:
        logs[r['category']].append(math.log10(r['extent'] * r['mpu']))
    sizes = {}
    for c, v in logs.items():
        mean = sum(v) / len(v)
        sd = (sum((x - mean) ** 2 for x in v) / max(1, len(v) - 1)) ** 0.5
        sizes[c] = (mean, max(sd, 0.05))
    count = collections.Counter(unit_class(r['mpu']) for r in train)
    share = {n: (count[n] + 1) / (len(train) + 5) for n in ['m', 'cm', 'mm', 'in', 'other']}
    return sizes, share


def learned(decades):
    def guess(r, prior):
        extent, category = r['extent'], r['category']
        sizes, share = prior
        mean, sd = sizes.get(category, sizes.get('none'))
        best = max((share[n] * math.exp(-((math.log10(extent * m) - mean) / sd) ** 2 / 2) /
                    (sd * math.sqrt(2 * math.pi)), m) for n, m in UNITS)
        return 10 ** mean / extent if share['other'] / decades > best[0] else best[1]
    return guess


def loso(rows, guess):
    right = not_metres = not_metres_right = 0
    wrong = []
    for source in sorted(set(r['source'] for r in rows)):
        prior = fit([r for r in rows if r['source'] != source])
        for r in (r for r in rows if r['source'] == source):
            g = guess(r, prior)
            ok = max(g / r['mpu'], r['mpu'] / g) <= 1.5
            right += ok
            if max(r['mpu'], 1 / r['mpu']) > 1.5:
                not_metres += 1
                not_metres_right += ok
            if not ok:
                wrong.append('%s (%s): %.4g vs curated %.4g' % (r['id'], r['source'], g, r['mpu']))
    return right, not_metres_right, not_metres, wrong


def main():
    rows = list(objects(sys.argv[1], sys.argv[2:]))
    print('%d curated objects, %d sources\n' % (len(rows), len(set(r['source'] for r in rows))))
    print('| guess | right | files not in metres right |\n|---|---|---|')
    methods = [('hand-set ranges (today, the product\'s guess)', lambda r, _: r['today'])]
    methods += [('learned size prior, game units over %g decades' % d, learned(d)) for d in (3, 6)]
    methods += [('learned size prior, no game units', learned(float('inf')))]
    for name, guess in methods:
        right, nmr, nm, wrong = loso(rows, guess)
        print('| %s | %d / %d | %d / %d |' % (name, right, len(rows), nmr, nm))
    for name, guess in (methods[0], methods[2]):
        print('\nwrong with %s:\n  %s' % (name, '\n  '.join(loso(rows, guess)[3])))


if __name__ == '__main__':
    main()
