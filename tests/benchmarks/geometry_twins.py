#!/usr/bin/env python3
"""How many objects of a dataset share their geometry with another (a colour variant, the same model
in another material or format, placed elsewhere in its file): the GUI carries a curated object's
points to such twins (ui/document/twin_points.h). Runs `sagrid info MESH --json` on every object
folder's mesh (the file labels.json names, else the folder's one mesh file); objects of one triangle
count and box size (sorted, to 1e-3 of the extent: the GUI's candidates, screened loosely here as the
box is read in each file's detected up axis) are compared with `sagrid info A --same-geometry-as B`
(the same triangles up to a translation, within 1e-4 of the size: core/mesh/geometry_identity.h).
Prints each group of twins and the count, then the candidates that are not the same geometry.

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

    objects = []  # (name, mesh, triangles, sorted box sizes)
    failed = []
    folders = [(dataset, folder) for dataset in args.datasets for folder in object_folders(dataset)]
    names = collections.Counter(folder.name for _, folder in folders)
    for dataset, folder in folders:
        name = folder.name if names[folder.name] == 1 else f"{dataset.name}/{folder.name}"
        mesh = mesh_of(folder)
        run = subprocess.run([args.sagrid, "info", str(mesh), "--json", "--resolution", "8"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            failed.append(f"{mesh}: {run.stderr.strip() or run.stdout.strip()}")
            continue
        info = json.loads(run.stdout)
        sizes = sorted(hi - lo for lo, hi in zip(info["bounds"]["min"], info["bounds"]["max"]))
        if info["triangles"] > 0 and sizes[-1] > 0:
            objects.append((name, mesh, info["triangles"], sizes))

    group_of = {}  # name -> representative (union-find)
    def root(name):
        while group_of.get(name, name) != name:
            name = group_of[name]
        return name
    candidates, near = 0, []
    for i, (name_a, mesh_a, count_a, sizes_a) in enumerate(objects):
        for name_b, mesh_b, count_b, sizes_b in objects[i + 1:]:
            within = 1e-3 * max(sizes_a[-1], sizes_b[-1])
            if count_a != count_b or any(abs(x - y) > within for x, y in zip(sizes_a, sizes_b)):
                continue
            candidates += 1
            run = subprocess.run([args.sagrid, "info", str(mesh_a), "--json", "--resolution", "8",
                                  "--same-geometry-as", str(mesh_b)], capture_output=True, text=True)
            if run.returncode != 0:
                failed.append(f"{mesh_a} against {mesh_b}: {run.stderr.strip() or run.stdout.strip()}")
                continue
            same = json.loads(run.stdout)["same_geometry"]
            if same["same"]:
                group_of[root(name_b)] = root(name_a)
                offset = " ".join(f"{x:g}" for x in same["offset"])
                print(f"twins: {name_a} ({mesh_a.name}), {name_b} ({mesh_b.name}), offset {offset}, "
                      f"{'same' if same['same_triangle_order'] else 'other'} triangle order")
            else:
                near.append([name_a, name_b])
    members = collections.defaultdict(list)
    for name, *_ in objects:
        members[root(name)].append(name)
    groups = sorted(sorted(g) for g in members.values() if len(g) > 1)
    twins = sum(len(g) for g in groups)
    for g in groups:
        print(f"{len(g)} of one geometry: " + ", ".join(g))
    for a, b in near:
        print(f"same triangle count and box, other geometry: {a}, {b}")
    for line in failed:
        print(f"not read: {line}")
    print(f"{len(folders)} objects, {len(objects)} read with an extent: {twins} have a same-geometry twin "
          f"({len(groups)} groups); {candidates} pairs share a triangle count and box, {len(near)} of "
          f"them not the same geometry")
    if args.json:
        args.json.write_text(json.dumps({"objects": len(folders), "read": len(objects),
                                         "with_twin": twins, "candidate_pairs": candidates,
                                         "near_pairs": near, "groups": groups}, indent=2) + "\n")


if __name__ == "__main__":
    main()
