"""Screens of what words the category decision could read beside the shape, on the left-out shape
probabilities of one `category cv --by-source --decisions FILE` run (resources/models/README.md,
"Session 65's file"; the product weighs the names since "The shipped file (session 66)"). Each
object's words are counted from the other sources' curated objects only, as the product's
cross-validation does (core/annotate/name_evidence.h: naive Bayes,
add-one smoothing, each word once per object; objects whose labels hold no file sha256 or carry a
generator record teach nothing), and multiplied into its shape probabilities raised to a weight;
decided at the threshold given (default 0.5, the shipped file's). The weight is the one the run's
fold learned for the object (`name_weight` in the decisions file, core/annotate/name_weight_fit.h;
1 in files written before session 66) unless a row says otherwise.

    python3 tests/benchmarks/category_name_screen.py DECISIONS.jsonl [--threshold T]

First how often the run's decision differs from its shape's alone, and how often it is right
there, the range of its folds' weights, and the objects it decides otherwise than the Bayes rule. Rows: the shape alone; the file's words by the Bayes rule (weight 1); as the run decided (the
same figures as the run); at half the learned weight; the words of the mesh's material names (OBJ
`usemtl`, glTF binary material names, COLLADA material names) alone, in one bag with the file's,
and as a second likelihood; each object given the file name of a random object of another class
(three draws: what a misleading name costs).
"""
import collections
import json
import math
import os
import random
import re
import struct
import sys

CLASSES = ['stove', 'sink', 'none']


def words(text):
    """The product's fileNameWords on one piece of text (no folder or extension)."""
    out = set()
    for part in re.split(r'[^A-Za-z\x80-\uffff]+', text):
        for word in re.split(r'(?<=[a-z])(?=[A-Z])', part):
            if len(word) >= 3:
                out.add(word.lower())
    return out


def material_names(mesh):
    ext = os.path.splitext(mesh)[1].lower()
    try:
        if ext == '.obj':
            return [line.split(None, 1)[1].strip() for line in open(mesh, errors='ignore')
                    if line.startswith('usemtl') and len(line.split()) > 1]
        if ext == '.glb':
            data = open(mesh, 'rb').read()
            length = struct.unpack('<I', data[12:16])[0]
            return [m.get('name', '') for m in json.loads(data[20:20 + length]).get('materials', [])]
        if ext == '.dae':
            return re.findall(r'<material[^>]*name="([^"]*)"', open(mesh, errors='ignore').read())
    except (OSError, ValueError, struct.error):
        pass
    return []


def load(path):
    objects = []
    for line in open(path):
        d = json.loads(line)
        labels = json.load(open(os.path.join(os.path.dirname(d['mesh']), 'labels.json')))
        info = labels['object'] if isinstance(labels.get('object'), dict) else {}
        published = bool(info.get('sha256')) and 'generator' not in info
        material = set()
        for name in material_names(d['mesh']):
            material |= words(name)
        objects.append({'id': d['id'], 'source': d['source'], 'truth': d['truth'],
                        'shape': d['shape_probabilities'], 'published': published,
                        'weight': d.get('name_weight', 1.0), 'decided': d['decided'],
                        'file': words(os.path.splitext(os.path.basename(d['mesh']))[0]),
                        'material': material})
    return objects


def log_likelihoods(objects, held, key, words_of_held):
    """Naive Bayes over `key` words, counted from the published objects of other sources."""
    teach = [o for o in objects if o['source'] != held['source'] and o['published'] and o[key]]
    counts = {c: collections.Counter() for c in CLASSES}
    for o in teach:
        counts[o['truth']].update(o[key])
    vocabulary = set(w for c in CLASSES for w in counts[c])
    totals = {c: sum(counts[c].values()) for c in CLASSES}
    ll = {c: 0.0 for c in CLASSES}
    for w in words_of_held & vocabulary:
        for c in CLASSES:
            ll[c] += math.log((counts[c][w] + 1) / (totals[c] + len(vocabulary)))
    return ll


def decide(p, threshold):
    best = max((c for c in CLASSES if c != 'none'), key=lambda c: p[c])
    rejected = max(p, key=p.get) == 'none' or p[best] < threshold
    return 'none' if rejected else best


def weighed(o, ll):
    """The object's shape probabilities times the likelihoods exp(ll), normalised."""
    top = max(ll.values())
    p = {c: o['shape'][c] * math.exp(ll[c] - top) for c in CLASSES}
    s = sum(p.values())
    return {c: v / s for c, v in p.items()}


def row(objects, name, evidence, threshold):
    right, total = collections.Counter(), collections.Counter()
    for o in objects:
        total[o['truth']] += 1
        right[o['truth']] += decide(weighed(o, evidence(o)), threshold) == o['truth']
    share = sum(right[c] / total[c] for c in CLASSES if total[c]) / 3
    print('| %s | %d / %d | %d / %d | %d / %d | %.3f |' % (
        name, right['stove'], total['stove'], right['sink'], total['sink'], right['none'],
        total['none'], share))


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    threshold = float(argv[argv.index('--threshold') + 1]) if '--threshold' in argv else 0.5
    objects = load(argv[1])
    for o in objects:
        o['both'] = o['file'] | o['material']
    ll = lambda key, scale=1.0: (lambda o: {c: scale * o['weight'] * v for c, v in
                                            log_likelihoods(objects, o, key, o[key]).items()})
    bayes_rule = lambda o: log_likelihoods(objects, o, 'file', o['file'])
    overruled = [o for o in objects if decide(o['shape'], threshold) != o['decided']]
    print('The run\'s name overruled the shape on %d of %d objects, right on %d; its folds weighed '
          'the names %.2f to %.2f.' % (
              len(overruled), len(objects), sum(o['decided'] == o['truth'] for o in overruled),
              min(o['weight'] for o in objects), max(o['weight'] for o in objects)))
    print('Decided otherwise than by the Bayes rule (weight 1):')
    for o in objects:
        bayes = decide(weighed(o, log_likelihoods(objects, o, 'file', o['file'])), threshold)
        if bayes != o['decided']:
            print('  %s (%s): %s -> %s, truly %s' % (o['id'], o['source'], bayes, o['decided'],
                                                   o['truth']))
    print()
    print('| words read beside the shape | stoves right | sinks right | look-alikes rejected | share |')
    print('|---|---:|---:|---:|---:|')
    row(objects, 'none (the shape alone)', lambda o: {c: 0.0 for c in CLASSES}, threshold)
    row(objects, "the file's name by the Bayes rule (weight 1)", bayes_rule, threshold)
    row(objects, "the file's name as the run weighed it", ll('file'), threshold)
    row(objects, "the file's name at half that weight", ll('file', 0.5), threshold)
    row(objects, 'the material names', ll('material'), threshold)
    row(objects, "the file's and the material names, one bag", ll('both'), threshold)
    both = lambda o: {c: ll('file')(o)[c] + ll('material')(o)[c] for c in CLASSES}
    row(objects, "the file's and the material names, two likelihoods", both, threshold)
    for seed in (1, 2, 3):
        rng = random.Random(seed)
        other = {o['id']: rng.choice([x for x in objects if x['truth'] != o['truth']])['file']
                 for o in objects}
        row(objects, "each file named as a random object of another class (draw %d)" % seed,
            lambda o: {c: o['weight'] * v for c, v in
                       log_likelihoods(objects, o, 'file', other[o['id']]).items()}, threshold)


if __name__ == '__main__':
    main(sys.argv)
