#!/usr/bin/env python3
"""Issue 38's budgets for the Python module, measured side by side in one process (never asserted in a
test: these machines are noisy):

- a frame rendered from Python (lagoon.Renderer.render, returning numpy) against the same frame through the
  CLI's in-process path (`lagoon bench render`'s "render/frame", wall time with readback), run in this very
  process through lagoon.run; budget: within 5 %;
- lagoon.WaveQuery.sample of 1,000,000 points at one time, each at a new time (the fields evaluated first)
  and again at a cached time; budget: <= 1 s.

    PYTHONPATH=build/python python3 tools/bench-python.py [--scene scenes/default.json] [--width 1280]
        [--height 720] [--rounds 10] [--json out/bench-python.json]
"""
import argparse
import json
import os
import statistics
import tempfile
import time

import numpy as np

import lagoon


def cli_frame_ms(scene, width, height, rounds):
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "bench.json")
        code = lagoon.run(["bench", "render", "--scene", scene, "--width", str(width), "--height", str(height),
                           "--rounds", str(rounds), "--json", path])
        if code != 0:
            raise SystemExit(f"lagoon bench render failed ({code})")
        (frame,) = [b for b in json.load(open(path))["benchmarks"] if b["name"] == "render/frame"]
        return frame["real_time"]


def python_frame_ms(scene, width, height, rounds):
    renderer = lagoon.Renderer(lagoon.Scene.load(scene, {"render.width": width, "render.height": height}))
    for _ in range(3):  # the warm-up, as the bench's: lavapipe compiles pipelines at their first use
        renderer.render()
    times = []
    for _ in range(rounds):
        start = time.perf_counter()
        renderer.render()
        times.append((time.perf_counter() - start) * 1e3)
    return statistics.median(times)


def wave_query_s(scene, points, rounds=3):
    query = lagoon.WaveQuery(lagoon.Scene.load(scene))
    xz = np.random.default_rng(0).uniform(-200, 200, size=(points, 2))
    fresh, cached = [], []
    for k in range(rounds):
        start = time.perf_counter()
        query.sample(1.0 + k, xz)
        fresh.append(time.perf_counter() - start)
        start = time.perf_counter()
        query.sample(1.0 + k, xz)
        cached.append(time.perf_counter() - start)
    return statistics.median(fresh), statistics.median(cached)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="scenes/default.json")
    parser.add_argument("--width", type=int, default=1280)
    parser.add_argument("--height", type=int, default=720)
    parser.add_argument("--rounds", type=int, default=10)
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--json", help="also write the figures here")
    args = parser.parse_args()
    # Alternated, so a drift of the machine's speed touches both sides alike.
    cli, py = [], []
    for _ in range(2):
        cli.append(cli_frame_ms(args.scene, args.width, args.height, args.rounds))
        py.append(python_frame_ms(args.scene, args.width, args.height, args.rounds))
    cli_ms, py_ms = min(cli), min(py)
    fresh, cached = wave_query_s(args.scene, args.points)
    device = lagoon.Renderer(lagoon.Scene.load(args.scene, {"render.width": 16, "render.height": 16})).device
    rows = {"device": device["name"], "scene": args.scene, "size": f"{args.width}x{args.height}",
            "cli_frame_ms": cli_ms, "python_frame_ms": py_ms, "python_over_cli": py_ms / cli_ms,
            "wave_query_points": args.points, "wave_query_new_time_s": fresh, "wave_query_cached_time_s": cached}
    print(f"{args.scene} at {args.width}x{args.height} on {device['name']}")
    print(f"frame, CLI in-process path      {cli_ms:9.2f} ms")
    print(f"frame, lagoon.Renderer.render   {py_ms:9.2f} ms   ratio {py_ms / cli_ms:.3f} (budget 1.05)")
    print(f"WaveQuery, {args.points} points, new time    {fresh:7.3f} s (budget 1 s)")
    print(f"WaveQuery, {args.points} points, cached time {cached:7.3f} s")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=2)


if __name__ == "__main__":
    main()
