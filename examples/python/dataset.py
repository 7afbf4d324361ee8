#!/usr/bin/env python3
"""A camera dataset from Python: a sequence of the harbour rendered in shards, as a cluster's tasks would
render it (lagoon.render_sequence, the code of `lagoon render --frames --shard`), checked complete and intact
(lagoon.verify_dataset, the code of `lagoon dataset verify`), then read with numpy and turned into what a
robotics pipeline trains on: each frame's depth back-projected through its intrinsics K and camera pose into
a world-space point cloud of the water's surface, the floor and the objects (POINTS/points_KKKK.npy: x, y, z,
class with class 1 the surface, 2 the floor, 3 an object or vehicle) and a summary table (POINTS/summary.npz).

    python3 examples/python/dataset.py --out out/harbour-set [--frames 6] [--shards 2]
"""
import argparse
import glob
import json
import os
import sys

import numpy as np

try:
    import lagoon
except ImportError:  # in a source tree after `make test` the module is in build/python
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "build", "python"))
    import lagoon


def render(scene_path, out, frames, shards, width, height, fps=10.0):
    """Every shard of the sequence: frames i, i + shards, ... each; a shard already finished is skipped."""
    for i in range(shards):
        lagoon.render_sequence(scene_path, os.path.join(out, "frame.png"), frames=frames, fps=fps,
                               shard=(i, shards), aovs=["depth", "water_mask", "object_id"],
                               overrides={"render.width": width, "render.height": height})
    lagoon.verify_dataset(out)  # raises lagoon.CommandError naming what is missing or damaged


def back_project(meta, depth):
    """World-space points of the pixels with a finite depth (m along the optical axis), as an H*W x 3 array
    with NaN rows where there is none: the pinhole model of the frame's metadata (OpenCV axes: x right, y
    down, z forward; world_from_camera maps them to the world)."""
    K = np.array(meta["camera"]["K"])
    world_from_camera = np.array(meta["camera"]["world_from_camera"])
    h, w = depth.shape
    v, u = np.mgrid[0:h, 0:w].astype(float)
    z = np.where(np.isfinite(depth), depth, np.nan)
    cam = np.stack([(u - K[0, 2]) / K[0, 0] * z, (v - K[1, 2]) / K[1, 1] * z, z, np.ones_like(z)], axis=-1)
    return (cam.reshape(-1, 4) @ world_from_camera.T)[:, :3]


def point_clouds(out, points_dir):
    """One .npy point cloud per frame and a summary; returns the summary's arrays."""
    os.makedirs(points_dir, exist_ok=True)
    times, shares, surface_y = [], [], []
    for meta_path in sorted(glob.glob(os.path.join(out, "frame_*.json"))):
        meta = json.load(open(meta_path))
        aov = {name: np.load(os.path.join(out, file)) for name, file in meta["aov"].items()}
        points = back_project(meta, aov["depth"])
        surface = (aov["water_mask"] == 1).reshape(-1)
        ids = aov["object_id"].reshape(-1)
        cls = np.select([surface, ids == -1, ids > 0], [1.0, 2.0, 3.0], 0.0)
        keep = (cls > 0) & np.all(np.isfinite(points), axis=1)
        cloud = np.column_stack([points[keep], cls[keep]]).astype(np.float32)
        np.save(os.path.join(points_dir, os.path.basename(meta_path).replace("frame_", "points_")[:-5] + ".npy"),
                cloud)
        times.append(meta["time_s"])
        shares.append([np.mean(cls == c) for c in (1.0, 2.0, 3.0)])
        surface_y.append(np.median(cloud[cloud[:, 3] == 1, 1]) if np.any(cloud[:, 3] == 1) else np.nan)
    shares = np.array(shares).reshape(-1, 3)
    summary = {"time_s": np.array(times), "surface_share": shares[:, 0], "floor_share": shares[:, 1],
               "object_share": shares[:, 2], "median_surface_y_m": np.array(surface_y)}
    np.savez(os.path.join(points_dir, "summary.npz"), **summary)
    return summary


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="scenes/harbour.json")
    parser.add_argument("--out", required=True, help="the dataset's folder")
    parser.add_argument("--points", help="where the point clouds go (default: OUT-points)")
    parser.add_argument("--frames", type=int, default=6)
    parser.add_argument("--shards", type=int, default=2)
    parser.add_argument("--width", type=int, default=160)
    parser.add_argument("--height", type=int, default=90)
    args = parser.parse_args()
    render(args.scene, args.out, args.frames, args.shards, args.width, args.height)
    summary = point_clouds(args.out, args.points or args.out.rstrip("/") + "-points")
    for row in zip(*summary.values()):
        print("t {:6.2f} s  surface {:5.1%}  floor {:5.1%}  objects {:5.1%}  surface at y {:6.2f} m".format(*row))


if __name__ == "__main__":
    main()
