#!/usr/bin/env python3
"""Renders the template with the tapes of its girths (docs/measurements.md's figure).

Usage: python3 docs/tools/render_measurements.py TEMPLATE_DIR PATHS_CSV OUT.png

TEMPLATE_DIR from `bodyspace template --export DIR`; PATHS_CSV from
`cargo run --release --example measure_paths -- DIR` (DIR/tape_paths.csv). Front and side views,
each girth's tape (convex hull of its section) as a coloured closed line, the landmarks the
measurements are anchored on as red dots. Needs numpy + matplotlib (and Pillow) only.
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from render_template import VIEWS, read_ply, render, save  # noqa: E402

# Landmarks named in crate/src/measure/definitions.rs.
ANCHORS = {
    "Cervicale", "Rt. Acromion", "Lt. Acromion", "Crotch", "Rt. Femoral Lateral Epicn",
    "Rt. Femoral Medial Epicn", "Rt. Axilla, Ant.", "Lt. Axilla, Ant.", "Rt. Axilla, Post.",
    "Lt. Axilla, Post.", "Rt. Thelion/Bustpoint", "Lt. Thelion/Bustpoint", "Substernale",
    "Rt. 10th Rib", "Lt. 10th Rib", "Rt. Iliocristale", "Lt. Iliocristale", "Rt. Trochanterion",
    "Lt. Trochanterion", "Rt. Olecranon", "Rt. Radiale", "Rt. Radial Styloid", "Suprasternale",
    "Sellion", "Rt. Tragion", "Lt. Tragion",
}


def main():
    src, paths_csv, out = sys.argv[1:4]
    pos, tri, _ = read_ply(f"{src}/template.ply")
    with open(f"{src}/landmarks.csv") as fh:
        landmarks = [(r["name"], int(r["vertex"])) for r in csv.DictReader(fh)
                     if r["name"] in ANCHORS]
    tapes = {}
    with open(paths_csv) as fh:
        for r in csv.DictReader(fh):
            tapes.setdefault(r["measure"], []).append([float(r["x"]), float(r["y"]), float(r["z"])])
    skin = np.tile([0.93, 0.85, 0.78], (len(pos), 1))
    colours = plt.cm.tab10(np.linspace(0, 1, 10))
    fig, axes = plt.subplots(1, 2, figsize=(8, 7), dpi=90)
    for ax, view in zip(axes, ["front", "side"]):
        right, toward = VIEWS[view]
        render(ax, pos, tri, right, toward, skin, landmarks, labels=False)
        for i, (name, pts) in enumerate(tapes.items()):
            p = np.array(pts + pts[:1])
            ax.plot(p @ right, p[:, 1], "-", lw=1.2, color=colours[i % 10],
                    label=name.replace("_", " ") if view == "front" else None)
        ax.set_title(f"tapes of the girths, {view}", fontsize=8)
    fig.legend(loc="lower center", ncol=5, fontsize=6, frameon=False)
    save(fig, out)


if __name__ == "__main__":
    main()
