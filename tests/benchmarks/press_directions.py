#!/usr/bin/env python3
"""Which way the buttons of curated real stoves and sinks are pressed in their MJCF exports.

Exports every stove and sink of the given dataset folders (true labels) with `sagrid export
--format mjcf` and, for every slide joint (a pressed button or key), says whether a press moves
it towards the middle of the object's box (into the body: a key on a top goes down, one on a
front panel goes back) or away from it (out of the body). Run it with two builds to compare.

  python3 tests/benchmarks/press_directions.py build/sagrid OUT W/wild-train W/wild-val \
      ../shared/data/real-dev
"""
import json, os, re, shutil, subprocess, sys

BODY = re.compile(r'<body name="([^"]*)" pos="([^"]*)">\s*<inertial[^>]*>\s*'
                  r'<joint name="[^"]*" type="slide"[^>]*axis="([^"]*)"')
BOX = re.compile(r'name="reg_main" type="box" pos="([^"]*)"')


def category_of(labels):
    o = labels.get('object')
    return o.get('category', '') if isinstance(o, dict) else labels.get('category', '')


def numbers(text):
    return [float(t) for t in text.split()]


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    sagrid, out, folders = sys.argv[1], sys.argv[2], sys.argv[3:]
    shutil.rmtree(out, ignore_errors=True)
    inward = slides = 0
    for folder in folders:
        for name in sorted(os.listdir(folder)):
            labels_file = os.path.join(folder, name, 'labels.json')
            if not os.path.isfile(labels_file):
                continue
            if category_of(json.load(open(labels_file))) not in ('stove', 'sink'):
                continue
            target = os.path.join(out, name)
            run = subprocess.run([sagrid, 'export', labels_file, '--format', 'mjcf', '--collision',
                                  'hull', '--out', target], capture_output=True, text=True)
            if run.returncode != 0:
                print(f'{name}: export failed: {run.stderr.strip()}')
                continue
            for sub in os.listdir(target):
                xml = open(os.path.join(target, sub, sub + '.xml')).read()
                centre = numbers(BOX.search(xml).group(1))
                for body, pos, axis in BODY.findall(xml):
                    p, a = numbers(pos), numbers(axis)
                    towards = sum(a[i] * (centre[i] - p[i]) for i in range(3)) > 0
                    slides += 1
                    inward += towards
                    print(f'{name} {body}: axis {axis}: {"into" if towards else "OUT OF"} the body')
    print(f'{inward} of {slides} buttons are pressed towards the middle of their object')


if __name__ == '__main__':
    main()
