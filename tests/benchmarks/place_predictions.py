"""Each object's predictions of an `annotate --out` folder written beside the mesh they describe,
where the GUI looks for them (ui/document/review_queue.cpp, labelsPathFor), as `sagrid
replay-curation --predictions` writes them.

    python3 tests/benchmarks/place_predictions.py PREDICTIONS_DIR
"""
import json
import os
import sys

MESHES = ('.obj', '.gltf', '.glb', '.fbx', '.dae', '.ply', '.stl')

predictions = sys.argv[1]
for name in sorted(os.listdir(predictions)):
    file = os.path.join(predictions, name, 'labels.json')
    if not os.path.isfile(file):
        continue
    labels = json.load(open(file))
    mesh = os.path.normpath(os.path.join(predictions, name, labels['object']['mesh']))
    folder, base = os.path.split(mesh)
    labels['object']['mesh'] = base
    meshes = [f for f in os.listdir(folder) if f.lower().endswith(MESHES)]
    target = 'labels.json' if len(meshes) <= 1 else os.path.splitext(base)[0] + '.labels.json'
    json.dump(labels, open(os.path.join(folder, target), 'w'), indent=2)
