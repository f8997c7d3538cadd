#!/usr/bin/env python3
"""Writes numpy_compressed.npz the way numpy.savez_compressed does (zipfile, ZIP_DEFLATED,
force_zip64 entries, .npy format 1.0 headers padded to 64 bytes), without needing numpy.
Run once; the output is committed so the .npz reader is tested without Python."""
import struct
import sys
import zipfile


def npy(descr, shape, fmt, values):
    shape_text = "(" + ", ".join(str(s) for s in shape) + ("," if len(shape) == 1 else "") + ")"
    header = "{'descr': '%s', 'fortran_order': False, 'shape': %s, }" % (descr, shape_text)
    pad = (64 - (10 + len(header) + 1) % 64) % 64
    header = header + " " * pad + "\n"
    return b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode("latin1") + \
        struct.pack("<" + fmt * len(values), *values)


arrays = {
    "coords": npy("<i4", (4, 3), "i", [0, 1, 2, 3, 4, 5, 6, 7, 8, 63, 0, 31]),
    "features": npy("<f4", (2, 3), "f", [0.5, -1.25, 3.0, 0.125, 2.0, -0.0]),
    "resolution": npy("<i8", (), "q", [64]),
    "mask": npy("|b1", (3,), "?", [True, False, True]),
    "grid": npy("|u1", (2, 2, 2), "B", list(range(8))),
    "values": npy("<f8", (2,), "d", [3.141592653589793, -2.5]),
}
out = sys.argv[1] if len(sys.argv) > 1 else "numpy_compressed.npz"
with zipfile.ZipFile(out, mode="w", compression=zipfile.ZIP_DEFLATED, allowZip64=True) as z:
    for key, data in arrays.items():
        with z.open(key + ".npy", "w", force_zip64=True) as f:
            f.write(data)
