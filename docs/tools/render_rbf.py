#!/usr/bin/env python3
"""Before/after pictures of the RBF warp per kernel (paper Figures 4-7), for docs/rbf.md.

Usage: python3 docs/tools/render_rbf.py BODYSPACE SCAN LANDMARKS TRUTH TEMPLATE_PLY OUT.png

Runs `BODYSPACE align --rough-only` with each kernel on SCAN/LANDMARKS (a synth subject: mm,
z up, facing -y), and draws, seen from the front: the scan; the template after Procrustes only
(the similarity from the report applied to TEMPLATE_PLY, e.g. from `bodyspace template
--export`); and the warped template for each kernel, coloured by the distance of every vertex
from its true position (TRUTH: the subject's truth_ID.ply). Needs numpy + matplotlib only.
"""
import gzip
import json
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402


def read_ply(path):
    """Binary little-endian PLY: float/double xyz (+ optional uchar/float extras), triangles."""
    data = open(path, "rb").read()
    if data[:2] == b"\x1f\x8b":
        data = gzip.decompress(data)
    end = data.index(b"end_header\n") + len(b"end_header\n")
    head = data[:end].decode()
    nv = int(head.split("element vertex ")[1].split()[0])
    nf = int(head.split("element face ")[1].split()[0]) if "element face" in head else 0
    props = [ln.split()[1:] for ln in head.split("element vertex")[1].split("element")[0].splitlines()
             if ln.startswith("property")]
    sizes = {"float": "<f4", "double": "<f8", "uchar": "u1", "int": "<i4", "uint": "<u4"}
    dt = np.dtype([(p[1], sizes[p[0]]) for p in props])
    v = np.frombuffer(data, dtype=dt, count=nv, offset=end)
    pos = np.stack([v["x"], v["y"], v["z"]], 1).astype(float)
    faces = np.zeros((0, 3), int)
    if nf:
        fdt = np.dtype([("n", "u1"), ("i", "<i4", 3)])
        faces = np.frombuffer(data, dtype=fdt, count=nf, offset=end + nv * dt.itemsize)["i"]
    return pos, faces


def draw(ax, pos, faces, colours, title):
    """Front view (viewer at -y looking +y; screen right = +x, up = +z), painter's algorithm."""
    tri = pos[faces]
    normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    normal /= np.linalg.norm(normal, axis=1, keepdims=True) + 1e-12
    shade = 0.35 + 0.65 * np.abs(normal[:, 1])
    order = np.argsort(-tri[:, :, 1].mean(1))
    c = colours[faces].mean(1)[:, :3] * shade[:, None]
    ax.add_collection(PolyCollection(tri[order][:, :, [0, 2]], facecolors=np.clip(c[order], 0, 1),
                                     edgecolors="none"))
    ax.set_xlim(pos[:, 0].min() - 50, pos[:, 0].max() + 50)
    ax.set_ylim(pos[:, 2].min() - 30, pos[:, 2].max() + 30)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(title, fontsize=9)


def main():
    exe, scan, landmarks, truth_path, template_ply, out = sys.argv[1:7]
    truth, _ = read_ply(truth_path)
    scan_pos, scan_faces = read_ply(scan)
    template, faces = read_ply(template_ply)
    cmap = plt.get_cmap("viridis")
    runs = [("thin-plate", None), ("multiquadric", 0.01), ("gaussian", 0.1), ("gaussian", 0.3)]
    fig, axes = plt.subplots(1, 2 + len(runs), figsize=(3 * (2 + len(runs)), 6.2))
    draw(axes[0], scan_pos, scan_faces, np.full((len(scan_pos), 3), 0.75), "scan")
    with tempfile.TemporaryDirectory() as tmp:
        first = True
        for ax, (kernel, param) in zip(axes[2:], runs):
            cmd = [exe, "align", "--scan", scan, "--landmarks", landmarks, "--rough-only",
                   "--out", f"{tmp}/w.ply", "--kernel", kernel]
            if param is not None:
                cmd += ["--kernel-param", str(param)]
            report = json.loads(subprocess.run(cmd, check=True, capture_output=True).stdout)
            if first:
                s = report["similarity"]
                before = s["scale"] * template @ np.array(s["rotation"]).T + np.array(s["translation"])
                err = np.linalg.norm(before - truth, axis=1)
                draw(axes[1], before, faces, cmap(np.clip(err / 30.0, 0, 1)),
                     f"Procrustes only\nmean {err.mean():.1f} mm")
                first = False
            warped, _ = read_ply(f"{tmp}/w.ply")
            err = np.linalg.norm(warped - truth, axis=1)
            label = kernel + ("" if param is None else f" {param} m")
            draw(ax, warped, faces, cmap(np.clip(err / 30.0, 0, 1)),
                 f"{label}\nmean {err.mean():.1f} mm")
    sm = plt.cm.ScalarMappable(cmap=cmap, norm=plt.Normalize(0, 30))
    fig.colorbar(sm, ax=axes, shrink=0.5, label="distance to true position (mm)")
    fig.savefig(out, dpi=90, bbox_inches="tight")


if __name__ == "__main__":
    main()
