#!/usr/bin/env python3
"""How many objects of a dataset share their geometry with another (a colour variant, the same model
in another material or format): the GUI carries a curated object's points to such twins
(ui/document/twin_points.h). Runs `sagrid info MESH --geometry-id --json` on every object folder's
mesh (the file labels.json names, else the folder's one mesh file), groups the objects by the
identity's shape, and prints each group of two or more and the count.

  tests/benchmarks/geometry_twins.py build/sagrid DATASET [--json OUT]

DATASET: a dataset folder (DIR/<split>/<id>/ or DIR/<id>/, as `sagrid corpus wild` writes) or a
pool of object folders (shared/data/wild-pool).
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
    parser.add_argument("dataset", type=pathlib.Path)
    parser.add_argument("--json", type=pathlib.Path, help="also write the groups here")
    args = parser.parse_args()
    if not args.dataset.is_dir():
        sys.exit(f"{args.dataset}: not a folder")

    by_shape = collections.defaultdict(list)
    failed = []
    folders = list(object_folders(args.dataset))
    for folder in folders:
        mesh = mesh_of(folder)
        run = subprocess.run([args.sagrid, "info", str(mesh), "--geometry-id", "--json", "--resolution", "8"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            failed.append(f"{mesh}: {run.stderr.strip() or run.stdout.strip()}")
            continue
        identity = json.loads(run.stdout).get("geometry_id")
        if identity:
            by_shape[identity["shape"]].append((folder.name, identity["triangle_order"], mesh.name))
    groups = [sorted(members) for members in by_shape.values() if len(members) > 1]
    twins = sum(len(g) for g in groups)
    for g in sorted(groups):
        same_order = len({order for _, order, _ in g}) == 1
        print(f"{len(g)} of one geometry ({'same' if same_order else 'other'} triangle order): " +
              ", ".join(f"{name} ({mesh})" for name, _, mesh in g))
    for line in failed:
        print(f"not read: {line}")
    print(f"{len(folders)} objects, {len(folders) - len(failed)} read: {twins} have a same-geometry twin "
          f"({len(groups)} groups)")
    if args.json:
        args.json.write_text(json.dumps({"objects": len(folders), "read": len(folders) - len(failed),
                                         "with_twin": twins,
                                         "groups": [[name for name, _, _ in g] for g in sorted(groups)]},
                                        indent=2) + "\n")


if __name__ == "__main__":
    main()
