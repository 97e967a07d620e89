#!/usr/bin/env python3
"""The peer: trimesh.registration.nricp_amberg (Amberg et al. 2007, non-rigid ICP) on the same
synthetic subjects as ours (crate/examples/align_accuracy.rs).

Start: the SAME RBF-warped template ours starts fine alignment from (warped_XXX.ply, metres,
written by `align_accuracy --export DIR`), with the same landmark anchors (anchors_XXX.json:
template vertex indices as `source_landmarks`, their targets in metres as `target_positions`).
Frame and units: the scan's frame, metres (scans and truth are read in mm and scaled).
Metrics, as ours: RMS of the scan-to-template distance (every scan vertex to the fitted template
surface) and mean correspondence error (fitted vertex vs truth), mm; time of the nricp call.
Writes each fit as EXPORT_DIR/peer_XXX.ply (the template's triangles, metres), so that the
common / own split of its correspondence error is computed by our code
(crate/examples/correspondence_split.rs), the same way as for ours.

usage: nricp.py DATA_DIR EXPORT_DIR N
"""
import json
import sys
import time

import numpy as np
import trimesh
from trimesh.registration import nricp_amberg


def load_mm(path):
    return trimesh.load(path, process=False, force="mesh")


def main():
    data, export, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
    rows = []
    print(f"trimesh {trimesh.__version__}, nricp_amberg default steps")
    print("subject  RMS_mm  corr_mm  seconds")
    for i in range(1, n + 1):
        scan = load_mm(f"{data}/scan_{i:03}.ply")
        scan = trimesh.Trimesh(scan.vertices * 1e-3, scan.faces, process=False)
        # The truth is a point cloud (template vertices, no faces).
        truth = np.asarray(trimesh.load(f"{data}/truth_{i:03}.ply", process=False).vertices) * 1e-3
        start = load_mm(f"{export}/warped_{i:03}.ply")
        anchors = json.load(open(f"{export}/anchors_{i:03}.json"))
        t0 = time.perf_counter()
        fitted = nricp_amberg(
            start,
            scan,
            source_landmarks=np.asarray(anchors["vertices"], dtype=np.int64),
            target_positions=np.asarray(anchors["targets"], dtype=np.float64),
        )
        seconds = time.perf_counter() - t0
        fit_mesh = trimesh.Trimesh(fitted, start.faces, process=False)
        fit_mesh.export(f"{export}/peer_{i:03}.ply", encoding="binary")
        _, dist, _ = trimesh.proximity.closest_point(fit_mesh, scan.vertices)
        rms = float(np.sqrt(np.mean(dist**2))) * 1e3
        corr = float(np.mean(np.linalg.norm(fitted - truth, axis=1))) * 1e3
        rows.append((rms, corr, seconds))
        print(f"{i:>7}  {rms:6.3f}  {corr:7.2f}  {seconds:7.1f}", flush=True)
    m = np.mean(np.asarray(rows), axis=0)
    print(f"{'mean':>7}  {m[0]:6.3f}  {m[1]:7.2f}  {m[2]:7.1f}")


if __name__ == "__main__":
    main()
