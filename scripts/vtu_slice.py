#!/usr/bin/env python3
"""Plots a point field of a ductile-contact .pvtu (or .vtu) output on the
face z = z_min of its cells (e.g. the crack field s of a thin-slab scene),
deformed by the displacement times a factor, as a PNG, without ParaView.
Reads deal.II's binary, zlib-compressed VTU pieces.

Usage: vtu_slice.py FILE.pvtu FIELD OUT.png [WARP] [TITLE]
"""
import base64
import os
import re
import struct
import sys
import zlib

import numpy as np

DTYPES = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32,
          "Int64": np.int64, "UInt8": np.uint8, "UInt32": np.uint32}


HEX_FACES = ((0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))


def decode(text, dtype):
    """A binary DataArray: base64 header (block count, block size, last
    block size, compressed sizes, UInt32) and base64 zlib blocks."""
    text = text.strip()
    first = base64.b64decode(text[:8])
    n_blocks = struct.unpack("<I", first[:4])[0]
    header_chars = 4 * ((4 * (3 + n_blocks) + 2) // 3)
    header = struct.unpack(f"<{3 + n_blocks}I", base64.b64decode(text[:header_chars]))
    data = base64.b64decode(text[header_chars:])
    out, pos = [], 0
    for size in header[3:]:
        out.append(zlib.decompress(data[pos:pos + size]))
        pos += size
    return np.frombuffer(b"".join(out), dtype=DTYPES[dtype])


def read_vtu(path):
    xml = open(path).read()
    arrays = {}
    for m in re.finditer(r'<DataArray type="(\w+)"([^>]*)>(.*?)</DataArray>', xml, re.S):
        dtype, attributes, body = m.groups()
        name = re.search(r'Name="([^"]+)"', attributes)
        name = name.group(1) if name else "points"
        components = re.search(r'NumberOfComponents="(\d+)"', attributes)
        values = decode(body, dtype)
        if components:
            values = values.reshape(-1, int(components.group(1)))
        arrays[name] = values
    return arrays


def pieces(path):
    if path.endswith(".pvtu"):
        folder = os.path.dirname(path)
        return [os.path.join(folder, f) for f in re.findall(r'<Piece Source="([^"]+)"', open(path).read())]
    return [path]


def draw(ax, path, field, warp=0.0, cmap="viridis"):
    """Draws FIELD of a .pvtu/.vtu on the face z = z_min of its cells into
    the matplotlib axes AX (displacement times WARP added); returns the
    PolyCollection (for a colour bar)."""
    from matplotlib.collections import PolyCollection

    polygons, values = [], []
    for piece in pieces(path):
        a = read_vtu(piece)
        x = a["points"].astype(float)
        if "displacement" in a:
            x = x + warp * a["displacement"]
        f = a[field].reshape(len(x), -1)[:, 0]
        offsets = a["offsets"]
        starts = np.concatenate([[0], offsets[:-1]])
        for s, e in zip(starts, offsets):
            cell = a["connectivity"][s:e]
            if len(cell) != 8:
                continue
            # the hexahedron's face with the smallest z (VTK face loops)
            bottom = min((cell[list(face)] for face in HEX_FACES),
                         key=lambda v: a["points"][v, 2].max())
            polygons.append(x[bottom, :2])
            values.append(f[bottom].mean())
    collection = PolyCollection(polygons, array=np.array(values), cmap=cmap,
                                edgecolors="none")
    ax.add_collection(collection)
    ax.autoscale()
    ax.set_aspect("equal")
    return collection


def main():
    path, field, out = sys.argv[1:4]
    warp = float(sys.argv[4]) if len(sys.argv) > 4 else 0.0
    title = sys.argv[5] if len(sys.argv) > 5 else f"{field}: {os.path.basename(path)}"
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 5.4))
    collection = draw(ax, path, field, warp)
    fig.colorbar(collection, ax=ax, label=field)
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    fig.tight_layout()
    fig.savefig(out, dpi=130)


if __name__ == "__main__":
    main()
