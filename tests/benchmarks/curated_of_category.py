"""One dataset folder of every curated object of a category, for a learning curve of one network
(`sagrid eval --learning-curve --by-source --data OUT`): each object's folder is copied (the dataset
reader refuses links that leave the folder) and its manifest line kept with its source, so the
sources stay those of the datasets it came from. A folder without a manifest (real-dev) gives its
subfolders whose labels.json has the category; their source is then OUT's name.

    python3 tests/benchmarks/curated_of_category.py CATEGORY OUT DATASET [DATASET ...]
        [--only MANIFEST | --except MANIFEST]
        e.g. sink OUT W/wild-train W/wild-val SH2/real-train SH2/real-val ../shared/data/real-dev
        --only / --except: keep only the objects whose id a manifest.jsonl lists, or all but
        those (e.g. a learning curve's LC/work/foldN/test/manifest.jsonl: the fold's held-out
        objects, or the objects it trained on).
"""
import json
import os
import shutil
import sys


def entries(dataset):
    manifest = os.path.join(dataset, 'manifest.jsonl')
    if os.path.exists(manifest):
        for line in open(manifest):
            if line.strip():
                yield json.loads(line)
        return
    for name in sorted(os.listdir(dataset)):
        labels = os.path.join(dataset, name, 'labels.json')
        if not os.path.exists(labels):
            continue
        meshes = [f for f in os.listdir(os.path.join(dataset, name))
                  if f.endswith(('.obj', '.glb', '.gltf', '.dae', '.fbx', '.ply', '.stl'))]
        yield {'category': json.load(open(labels)).get('category', ''), 'id': name,
               'labels': name + '/labels.json', 'mesh': name + '/' + meshes[0]}


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    category, out, datasets, only, excluded = argv[0], argv[1], [], None, set()
    rest = iter(argv[2:])
    for arg in rest:
        if arg in ('--only', '--except'):
            ids = {json.loads(line)['id'] for line in open(next(rest)) if line.strip()}
            if arg == '--only':
                only = ids
            else:
                excluded = ids
        else:
            datasets.append(arg)
    if os.path.exists(out):
        sys.exit(out + ' exists: give a new folder')
    os.makedirs(out)
    kept = []
    for dataset in datasets:
        for entry in entries(dataset):
            if entry.get('category') != category or entry['id'] in excluded:
                continue
            if only is not None and entry['id'] not in only:
                continue
            folder = entry['labels'].split('/')[0]
            if os.path.exists(os.path.join(out, folder)):
                sys.exit('%s: object folder %s twice' % (dataset, folder))
            shutil.copytree(os.path.join(dataset, folder), os.path.join(out, folder))
            kept.append(entry)
    with open(os.path.join(out, 'manifest.jsonl'), 'w') as manifest:
        for entry in kept:
            manifest.write(json.dumps(entry, separators=(',', ':')) + '\n')
    print('%d %s objects of %d sources in %s' % (len(kept), category,
                                                len({e.get('source', out) for e in kept}), out))


if __name__ == '__main__':
    main(sys.argv[1:])
