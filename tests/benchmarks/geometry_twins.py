#!/usr/bin/env python3
"""How many objects of a dataset share their geometry with another (a colour variant, the same model
in another material or format): the GUI carries a curated object's points to such twins
(ui/document/twin_points.h). Runs `sagrid info MESH --geometry-id --json` on every object folder's
mesh (the file labels.json names, else the folder's one mesh file), groups the objects by the
identity's shape (blind to where the object lies in its file: twins' points carry moved by the
offset of their origins), and prints each group of two or more and the count; then the objects that
share a triangle count and a box size (to 0.1 % of the extent) with another but not its shape: twins
the identity may miss (a file that re-encodes coordinates, e.g. prints them to 4 decimals after
moving the object, rounds a few corners into the next cell).

  tests/benchmarks/geometry_twins.py build/sagrid DATASET [DATASET ...] [--json OUT]

DATASET: a dataset folder (DIR/<split>/<id>/ or DIR/<id>/, as `sagrid corpus wild` writes) or a
pool of object folders (shared/data/wild-pool). Several are counted together, as one queue (a
library's train and validation splits and its distractors): objects are named by folder, and by
DATASET/folder where two datasets hold a folder of one name.
"""
import argparse
import collections
import json
import pathlib
import subprocess
import sys

MESH_ENDINGS = {".glb", ".gltf", ".obj", ".fbx", ".ply", ".stl", ".off", ".dae", ".3ds"}


def mesh_of(folder):
    labels = folder / "labels.json"
    if labels.is_file():
        name = json.loads(labels.read_text()).get("object", {}).get("mesh", "")
        if name and (folder / name).is_file():
            return folder / name
    meshes = sorted(p for p in folder.iterdir() if p.suffix.lower() in MESH_ENDINGS)
    return meshes[0] if len(meshes) == 1 else None


def object_folders(root):
    for folder in sorted(root.rglob("*")):
        if folder.is_dir() and mesh_of(folder) is not None:
            yield folder


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("sagrid")
    parser.add_argument("datasets", type=pathlib.Path, nargs="+", metavar="dataset")
    parser.add_argument("--json", type=pathlib.Path, help="also write the groups here")
    args = parser.parse_args()
    for dataset in args.datasets:
        if not dataset.is_dir():
            sys.exit(f"{dataset}: not a folder")

    by_shape = collections.defaultdict(list)
    by_outline = collections.defaultdict(list)
    failed = []
    folders = [(dataset, folder) for dataset in args.datasets for folder in object_folders(dataset)]
    names = collections.Counter(folder.name for _, folder in folders)
    for dataset, folder in folders:
        name = folder.name if names[folder.name] == 1 else f"{dataset.name}/{folder.name}"
        mesh = mesh_of(folder)
        run = subprocess.run([args.sagrid, "info", str(mesh), "--geometry-id", "--json", "--resolution", "8"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            failed.append(f"{mesh}: {run.stderr.strip() or run.stdout.strip()}")
            continue
        info = json.loads(run.stdout)
        identity = info.get("geometry_id")
        if identity:
            by_shape[identity["shape"]].append((name, identity["triangle_order"], mesh.name))
            sizes = [hi - lo for lo, hi in zip(info["bounds"]["min"], info["bounds"]["max"])]
            step = max(sizes) / 1000
            outline = (info["triangles"], tuple(round(size / step) for size in sizes))
            by_outline[outline].append((name, identity["shape"], mesh.name))
    groups = [sorted(members) for members in by_shape.values() if len(members) > 1]
    twins = sum(len(g) for g in groups)
    for g in sorted(groups):
        same_order = len({order for _, order, _ in g}) == 1
        print(f"{len(g)} of one geometry ({'same' if same_order else 'other'} triangle order): " +
              ", ".join(f"{name} ({mesh})" for name, _, mesh in g))
    near = [sorted(m) for m in by_outline.values() if len({shape for _, shape, _ in m}) > 1]
    for g in sorted(near):
        print(f"{len(g)} of one triangle count and box, {len({s for _, s, _ in g})} shapes: " +
              ", ".join(f"{name} ({mesh}, {shape[:8]})" for name, shape, mesh in g))
    for line in failed:
        print(f"not read: {line}")
    print(f"{len(folders)} objects, {len(folders) - len(failed)} read: {twins} have a same-geometry twin "
          f"({len(groups)} groups); {sum(len(g) for g in near)} share a triangle count and box with "
          f"an object of another shape ({len(near)} groups)")
    if args.json:
        args.json.write_text(json.dumps({"objects": len(folders), "read": len(folders) - len(failed),
                                         "with_twin": twins,
                                         "near_twin_groups": [[name for name, _, _ in g] for g in sorted(near)],
                                         "groups": [[name for name, _, _ in g] for g in sorted(groups)]},
                                        indent=2) + "\n")


if __name__ == "__main__":
    main()
