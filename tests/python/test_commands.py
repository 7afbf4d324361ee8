"""lagoon.export, lagoon.render_sequence, lagoon.verify_dataset and lagoon.run (issue 38): the `lagoon`
command's own code in the interpreter's process, so its files are the CLI's byte for byte, its shards verify
as the CLI's do, and its errors are the CLI's messages. Also the dataset example, checked by `lagoon dataset
verify` and against WaveQuery."""
import filecmp
import importlib.util
import json
import math
import os
import subprocess

import numpy as np
import pytest

import lagoon

SOURCE = os.environ.get("LAGOON_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
LAGOON = os.environ["LAGOON_BINARY"]
DEFAULT = os.path.join(SOURCE, "scenes", "default.json")
SMALL_SEA = {"ocean.cascades": [{"patch_size_m": 200, "resolution": 64}, {"patch_size_m": 20, "resolution": 64}]}
SMALL_FRAME = {"render.width": 48, "render.height": 27}


def cli(*args):
    return subprocess.run([LAGOON, *args], capture_output=True, text=True)


def sets(overrides):
    out = []
    for key, value in overrides.items():
        out += ["--set", f"{key}={json.dumps(value)}"]
    return out


def same_files(a, b, names):
    assert names, "nothing to compare"
    match, mismatch, errors = filecmp.cmpfiles(a, b, names, shallow=False)
    assert not mismatch and not errors, (mismatch, errors)


def test_export_writes_the_clis_files_byte_for_byte(tmp_path):
    meta = lagoon.export(DEFAULT, tmp_path / "py", frames=2, dt=0.25, t0=3.0, overrides=SMALL_SEA,
                         surface=[-10, -10, 10, 5], surface_spacing=2.5)
    r = cli("export", "--scene", DEFAULT, "--out", str(tmp_path / "cli"), "--frames", "2", "--dt", "0.25",
            "--t0", "3", "--surface", "-10,-10,10,5", "--surface-spacing", "2.5", *sets(SMALL_SEA))
    assert r.returncode == 0, r.stderr
    arrays = sorted(f for f in os.listdir(tmp_path / "cli") if f.endswith(".npy"))
    assert sorted(f for f in os.listdir(tmp_path / "py") if f.endswith(".npy")) == arrays
    same_files(tmp_path / "py", tmp_path / "cli", arrays + ["meta.json"])
    assert meta == json.load(open(tmp_path / "py" / "meta.json"))
    assert np.load(tmp_path / "py" / "cascade0_displacement.npy").shape[0] == 2
    assert np.load(tmp_path / "py" / "surface_height.npy").shape == (2, 7, 9)


def test_a_sequence_in_shards_is_the_clis_sequence_and_verifies(tmp_path):
    overrides = {**SMALL_FRAME, **SMALL_SEA}
    manifests = [lagoon.render_sequence(DEFAULT, tmp_path / "py" / "f.png", frames=3, fps=5, shard=shard,
                                        aovs=["depth", "water_mask"], overrides=overrides)
                 for shard in [(0, 2), "1/2"]]
    assert manifests == [str(tmp_path / "py" / "f.shard-0-of-2.jsonl"), str(tmp_path / "py" / "f.shard-1-of-2.jsonl")]
    lagoon.verify_dataset(tmp_path / "py")
    assert cli("dataset", "verify", str(tmp_path / "py")).returncode == 0
    r = cli("render", "--scene", DEFAULT, "--out", str(tmp_path / "cli" / "f.png"), "--frames", "3", "--fps", "5",
            "--aov", "depth,water_mask", *sets(overrides))
    assert r.returncode == 0, r.stderr
    frames = [f"f_{k:04d}{ext}" for k in range(3) for ext in (".png", ".depth.npy", ".water_mask.npy", ".json")]
    same_files(tmp_path / "py", tmp_path / "cli", frames)
    # A second call finds its frames finished and renders nothing, leaving the files as they were.
    before = os.stat(tmp_path / "py" / "f_0000.png").st_mtime_ns
    lagoon.render_sequence(DEFAULT, tmp_path / "py" / "f.png", frames=3, fps=5, shard=(0, 2),
                           aovs=["depth", "water_mask"], overrides=overrides)
    assert os.stat(tmp_path / "py" / "f_0000.png").st_mtime_ns == before


def test_a_sequence_of_one_frame_is_a_sequence_with_its_manifest(tmp_path):
    manifest = lagoon.render_sequence(DEFAULT, tmp_path / "one" / "f.png", overrides=SMALL_FRAME)
    # As `lagoon render --shard 0/1` writes it: f.png and f.json (one frame needs no number), in the manifest.
    assert os.path.isfile(manifest) and os.path.isfile(tmp_path / "one" / "f.json")
    assert "f.png" in open(manifest).read()
    lagoon.verify_dataset(tmp_path / "one")


def test_failures_raise_the_clis_message_and_exit_code(tmp_path):
    lagoon.render_sequence(DEFAULT, tmp_path / "set" / "f.png", frames=2, shard=(0, 2), overrides=SMALL_FRAME)
    with pytest.raises(lagoon.CommandError, match=r"shard 1 of 2 has no manifest; run it \(--shard 1/2\)") as e:
        lagoon.verify_dataset(tmp_path / "set")
    assert e.value.exit_code == 1
    bad = {"ocean.wind_speed_mps": -3}
    r = cli("export", "--scene", DEFAULT, "--out", str(tmp_path / "x"), *sets(bad))
    assert r.returncode == 1
    with pytest.raises(lagoon.CommandError) as e:
        lagoon.export(DEFAULT, tmp_path / "x", overrides=bad)
    assert str(e.value) == r.stderr.strip() and e.value.exit_code == 1
    assert "ocean.wind_speed_mps" in str(e.value)
    assert not os.path.exists(tmp_path / "x"), "a failed export leaves nothing"
    # A lagoon.Scene is accepted as well as a path, and its errors are caught when it is made.
    with pytest.raises(lagoon.CommandError, match="--fps"):
        lagoon.render_sequence(lagoon.Scene.load(DEFAULT, SMALL_FRAME), tmp_path / "s" / "f.png", frames=2, fps=-1)


def test_run_is_the_lagoon_command():
    assert lagoon.run(["render", "--help"]) == 0
    assert lagoon.run(["no-such-command"]) == 2
    assert lagoon.run(["render", "--scene"]) == 2
    assert lagoon.run(["dataset", "verify", "/nonexistent/folder"]) == 1
    # Comparing builds needs this build's executable, which the interpreter is not: refused, not run.
    assert lagoon.run(["bench", "render", "--baseline", LAGOON, "--scene", DEFAULT, "--rounds", "1"]) == 2


def test_the_dataset_example_back_projects_its_depth_onto_the_sea(tmp_path):
    spec = importlib.util.spec_from_file_location("dataset", os.path.join(SOURCE, "examples", "python", "dataset.py"))
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    out = str(tmp_path / "set")
    example.render(DEFAULT, out, frames=3, shards=2, width=96, height=54)
    assert cli("dataset", "verify", out).returncode == 0  # the set the example wrote is complete and intact
    summary = example.point_clouds(out, str(tmp_path / "points"))
    assert len(summary["time_s"]) == 3 and np.all(summary["surface_share"] > 0.2)
    # Each surface point, back-projected from its depth through K and the pose, lies on the sea WaveQuery
    # gives at the frame's time: the depth, the intrinsics and the pose agree with one another and with the
    # water. Measured: median 1.7 cm, 90th percentile 5.1 cm; reading the depth as the distance along the ray
    # instead of along the axis gives a median of 0.52 m, a focal length sqrt(2) too long 0.92 m.
    scene = lagoon.Scene.load(DEFAULT)
    query = lagoon.WaveQuery(scene)
    cloud = np.load(tmp_path / "points" / "points_0001.npy")
    meta = json.load(open(os.path.join(out, "frame_0001.json")))
    surface = cloud[cloud[:, 3] == 1]
    near = np.linalg.norm(surface[:, :3] - np.array(meta["camera"]["position"]), axis=1) < 40
    water = query.sample(meta["time_s"], surface[near][:, [0, 2]].astype(float))
    error = surface[near][:, 1] - water["height"]
    assert near.sum() > 300
    assert np.median(np.abs(error)) < 0.05, np.median(np.abs(error))
    assert np.percentile(np.abs(error), 90) < 0.15, np.percentile(np.abs(error), 90)
