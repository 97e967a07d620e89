#!/usr/bin/env python3
"""Renders the template exported by `bodyspace template --export DIR` with its landmarks.

Usage: python3 docs/tools/render_template.py DIR OUTDIR [--segments] [--zoom NAME,x0,x1,y0,y1,view]

Writes template_front.png, template_side.png, template_back.png (landmarks numbered by CAESAR
order and labelled) and, with --segments, template_segments.png (front/back coloured by segment
blend weights, overlap bands visible). Orthographic views, painter's algorithm, Lambert shading.
Needs numpy + matplotlib only.
"""
import csv
import struct
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

SEG_COLOURS = np.array([[0.95, 0.8, 0.2], [0.2, 0.6, 0.95], [0.95, 0.3, 0.3],
                        [0.6, 0.6, 0.6], [0.3, 0.8, 0.4], [0.7, 0.4, 0.9]])
SEGS = ["head", "left_arm", "right_arm", "torso", "left_leg", "right_leg"]
# (name, screen-right axis, depth axis toward camera)
VIEWS = {
    "front": (np.array([1.0, 0, 0]), np.array([0, 0, 1.0])),
    "side": (np.array([0, 0, 1.0]), np.array([-1.0, 0, 0])),
    "back": (np.array([-1.0, 0, 0]), np.array([0, 0, -1.0])),
    "left": (np.array([0, 0, -1.0]), np.array([1.0, 0, 0])),
}


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode()
    nv = int(header.split("element vertex ")[1].split()[0])
    nf = int(header.split("element face ")[1].split()[0])
    v = np.frombuffer(data, dtype=np.dtype([("p", "<f4", 3), ("f", "u1")]), count=nv, offset=end)
    f = np.frombuffer(data, dtype=np.dtype([("n", "u1"), ("i", "<i4", 3)]), count=nf,
                      offset=end + nv * 13)
    return v["p"].astype(float), f["i"].astype(int), v["f"]


def render(ax, pos, tri, right, toward, colours, landmarks, labels=True, box=None):
    up = np.array([0, 1.0, 0])
    sx, sy, depth = pos @ right, pos @ up, pos @ toward
    a, b, c = pos[tri[:, 0]], pos[tri[:, 1]], pos[tri[:, 2]]
    n = np.cross(b - a, c - a)
    n /= np.linalg.norm(n, axis=1, keepdims=True) + 1e-30
    facing = n @ toward
    keep = facing > 0
    if box is not None:
        cx = sx[tri].mean(1)
        cy = sy[tri].mean(1)
        keep &= (cx > box[0] - 0.05) & (cx < box[1] + 0.05) & (cy > box[2] - 0.05) & (cy < box[3] + 0.05)
    order = np.argsort(depth[tri].mean(1)[keep])
    t = tri[keep][order]
    shade = (0.35 + 0.65 * facing[keep][order])[:, None]
    col = colours[t].mean(1) * shade
    polys = np.stack([np.stack([sx[t[:, k]], sy[t[:, k]]], 1) for k in range(3)], 1)
    ax.add_collection(PolyCollection(polys, facecolors=np.clip(col, 0, 1), edgecolors="none"))
    vn = np.zeros_like(pos)
    for k in range(3):
        np.add.at(vn, tri[:, k], n)
    vn /= np.linalg.norm(vn, axis=1, keepdims=True) + 1e-30
    for i, (name, v) in enumerate(landmarks):
        if vn[v] @ toward < -0.05:
            continue
        if box is not None and not (box[0] < sx[v] < box[1] and box[2] < sy[v] < box[3]):
            continue
        ax.plot(sx[v], sy[v], "o", ms=3.5, mfc="red", mec="black", mew=0.4)
        if labels:
            ax.annotate(f"{i + 1} {name}", (sx[v], sy[v]), fontsize=4.2, xytext=(3, 1),
                        textcoords="offset points", color="navy")
    if box is None:
        ax.set_xlim(sx.min() - 0.05, sx.max() + 0.05)
        ax.set_ylim(-0.02, sy.max() + 0.03)
    else:
        ax.set_xlim(box[0], box[1])
        ax.set_ylim(box[2], box[3])
    ax.set_aspect("equal")
    ax.axis("off")


def main():
    src, out = sys.argv[1], sys.argv[2]
    pos, tri, flags = read_ply(f"{src}/template.ply")
    landmarks = []
    with open(f"{src}/landmarks.csv") as fh:
        for row in csv.DictReader(fh):
            landmarks.append((row["name"], int(row["vertex"])))
    skin = np.tile([0.93, 0.78, 0.66], (len(pos), 1))
    flag_col = {1: [0.6, 0.75, 0.95], 2: [0.95, 0.6, 0.8], 4: [0.6, 0.9, 0.6], 8: [0.3, 0.3, 0.3]}
    for bit, c in flag_col.items():
        skin[(flags & bit) != 0] = c
    args = sys.argv[3:]
    zooms = [a.split(",") for a in args if a.count(",") == 5]
    if zooms:
        for name, x0, x1, y0, y1, view in zooms:
            fig, ax = plt.subplots(figsize=(6, 6), dpi=150)
            right, toward = VIEWS[view]
            render(ax, pos, tri, right, toward, skin, landmarks,
                   box=[float(x0), float(x1), float(y0), float(y1)])
            fig.savefig(f"{out}/zoom_{name}.png", bbox_inches="tight")
            plt.close(fig)
        return
    for view in ["front", "side", "back"]:
        right, toward = VIEWS[view]
        fig, ax = plt.subplots(figsize=(5, 8), dpi=110)
        render(ax, pos, tri, right, toward, skin, landmarks)
        ax.set_title(f"BodySpace template, {view} (subject's right is x < 0)", fontsize=7)
        fig.savefig(f"{out}/template_{view}.png", bbox_inches="tight")
        plt.close(fig)
    if "--segments" in args:
        w = np.zeros((len(pos), 6))
        with open(f"{src}/segments.csv") as fh:
            for row in csv.DictReader(fh):
                w[int(row["vertex"]), SEGS.index(row["segment"])] = float(row["weight"])
        # Vertices in two segments get a striped darker tone so the overlap band stands out.
        col = w @ SEG_COLOURS
        overlap = (w > 0).sum(1) > 1
        col[overlap] *= 0.75
        fig, axes = plt.subplots(1, 2, figsize=(8, 7), dpi=100)
        for ax, view in zip(axes, ["front", "back"]):
            right, toward = VIEWS[view]
            render(ax, pos, tri, right, toward, col, [], labels=False)
            ax.set_title(f"segments, {view} (darker = overlap band)", fontsize=8)
        fig.savefig(f"{out}/template_segments.png", bbox_inches="tight")
        plt.close(fig)


if __name__ == "__main__":
    main()
