"""The Python module `lagoon` (issue 38) against the CLI it must agree with: the same scene checks and
messages, the same frame, the same water at points. Run by ctest (tests/CMakeLists.txt) with PYTHONPATH set
to the build's python/ folder and LAGOON_BINARY to the `lagoon` command."""
import os
import struct
import subprocess
import threading
import time
import zlib
import json

import numpy as np
import pytest

import lagoon

SOURCE = os.environ.get("LAGOON_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
LAGOON = os.environ["LAGOON_BINARY"]
DEFAULT = os.path.join(SOURCE, "scenes", "default.json")
SMALL = {"render.width": 96, "render.height": 54}


def cli(*args):
    return subprocess.run([LAGOON, *args], capture_output=True, text=True)


def read_png(path):
    """Decodes an 8-bit, non-interlaced RGB or RGBA PNG with the standard library (zlib): a reader
    independent of Lagoon's writer, for comparing its PNG with the module's array."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and colour in (2, 6) and interlace == 0, header
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows = np.zeros((height, stride), dtype=np.int32)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=y * (stride + 1) + 1).astype(np.int32)
        out = np.zeros(stride, dtype=np.int32)
        for x in range(stride):
            a = out[x - channels] if x >= channels else 0
            b = prev[x]
            c = prev[x - channels] if x >= channels else 0
            if kind == 0:
                p = 0
            elif kind == 1:
                p = a
            elif kind == 2:
                p = b
            elif kind == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            out[x] = (line[x] + p) & 0xFF
        rows[y] = out
        prev = out
    return rows.reshape(height, width, channels)[:, :, :3].astype(np.uint8)


def test_scene_round_trips_through_a_dict():
    scene = lagoon.Scene.load(DEFAULT, SMALL)
    assert (scene.width, scene.height) == (96, 54)
    d = scene.to_dict()
    again = lagoon.Scene.from_dict(d)
    assert again.to_dict() == d
    d["render"]["width"] = 64
    assert lagoon.Scene.from_dict(d).width == 64


def test_a_bad_field_raises_the_clis_message():
    with pytest.raises(lagoon.SceneError) as python_error:
        lagoon.Scene.load(DEFAULT, {"ocean.depth_m": -3})
    message = str(python_error.value)
    assert "ocean.depth_m" in message and "default.json" in message
    r = cli("render", "--scene", DEFAULT, "--set", "ocean.depth_m=-3", "--out", "/nonexistent/x.png")
    assert r.returncode != 0
    assert message in r.stderr, (message, r.stderr)
    with pytest.raises(lagoon.SceneError, match="file not found"):
        lagoon.Scene.load(os.path.join(SOURCE, "scenes", "no-such-scene.json"))
    with pytest.raises(lagoon.SceneError, match="render.width"):
        lagoon.Scene.from_dict({"render": {"width": -5}})


def test_a_models_override_warns_what_it_also_changed():
    with pytest.warns(UserWarning, match="choppiness"):
        lagoon.Scene.load(os.path.join(SOURCE, "scenes", "harbour.json"), {"ocean.model": "sines", **SMALL})


def test_the_frame_is_the_pixels_lagoon_render_writes(tmp_path):
    scene = lagoon.Scene.load(DEFAULT, SMALL)
    renderer = lagoon.Renderer(scene)
    image = renderer.render(time=2.0)["image"]
    assert renderer.validation_errors == 0
    assert image.shape == (54, 96, 3) and image.dtype == np.uint8
    png = tmp_path / "frame.png"
    r = cli("render", "--scene", DEFAULT, "--width", "96", "--height", "54", "--time", "2", "--out", str(png))
    assert r.returncode == 0, r.stderr
    written = read_png(png)
    assert np.array_equal(image, written), np.abs(image.astype(int) - written.astype(int)).max()


def test_a_first_render_of_the_build_compiles_on_a_second_device_and_draws_the_same(tmp_path, monkeypatch):
    # An empty result cache: this build has not drawn here (render/cold_compile.h). On a CPU device the first
    # render starts a second device, and after it the marker that stops the next run starting one.
    monkeypatch.setenv("LAGOON_PIPELINE_CACHE", str(tmp_path / "cold"))
    scene = lagoon.Scene.load(DEFAULT, SMALL)
    renderer = lagoon.Renderer(scene)
    cold = renderer.render(time=2.0)["image"]
    assert renderer.validation_errors == 0
    markers = list((tmp_path / "cold" / "results").glob("drawn-*.bin"))
    assert len(markers) == (1 if renderer.device["type"] == "CPU" else 0), markers
    monkeypatch.setenv("LAGOON_PIPELINE_CACHE", str(tmp_path / "without"))
    monkeypatch.setenv("LAGOON_COLD_COMPILE", "0")
    alone = lagoon.Renderer(scene).render(time=2.0)["image"]
    assert not list((tmp_path / "without" / "results").glob("drawn-*.bin"))  # no second device, no marker
    assert np.array_equal(cold, alone), np.abs(cold.astype(int) - alone.astype(int)).max()


def test_a_camera_moves_the_view_and_a_bad_one_is_refused():
    renderer = lagoon.Renderer(lagoon.Scene.load(DEFAULT, SMALL))
    assert renderer.device["name"]
    devices = renderer.devices()
    (used,) = [d for d in devices if d["in_use"]]
    assert used["name"] == renderer.device["name"] and used["usable"] and used["index"] == devices.index(used)
    # The same device chosen by its index, as LAGOON_DEVICE would.
    again = lagoon.Renderer(lagoon.Scene.load(DEFAULT, SMALL), device=str(used["index"]))
    assert again.device["name"] == used["name"]
    with pytest.raises(RuntimeError, match="no-such-gpu"):
        lagoon.Renderer(lagoon.Scene.load(DEFAULT, SMALL), device="no-such-gpu")
    ahead = renderer.render(time=1.0, camera={"position": [0, 3, -10], "look_at": [0, 0, 20], "fov_deg": 55})["image"]
    down = renderer.render(time=1.0, camera={"position": [0, 3, -10], "look_at": [0, -5, -9], "fov_deg": 55})["image"]
    # Looking at the horizon the top half is sky; looking down it is water: the frames differ a lot.
    assert np.abs(ahead.astype(int) - down.astype(int)).mean() > 10
    with pytest.raises(lagoon.SceneError, match="camera.fov_deg"):
        renderer.render(camera={"position": [0, 3, -10], "look_at": [0, 0, 20], "fov_deg": 500})
    assert renderer.validation_errors == 0


def test_the_aovs_are_the_arrays_lagoon_render_writes(tmp_path):
    harbour = os.path.join(SOURCE, "scenes", "harbour.json")
    names = ["depth", "normal", "water_mask", "object_id"]
    frame = lagoon.Renderer(lagoon.Scene.load(harbour, SMALL)).render(time=3.0, aovs=names)
    out = tmp_path / "frame.png"
    r = cli("render", "--scene", harbour, "--width", "96", "--height", "54", "--time", "3", "--aov", ",".join(names),
            "--out", str(out))
    assert r.returncode == 0, r.stderr
    written = sorted(p.name for p in tmp_path.glob("*.npy"))
    assert len(written) == len(names), written
    for name in names:
        (npy,) = [p for p in tmp_path.glob(f"*.{name}.npy")]
        expected = np.load(npy)
        assert frame[name].dtype == np.float32 and frame[name].shape == expected.shape, name
        assert np.array_equal(frame[name], expected, equal_nan=True), name
    assert np.array_equal(frame["image"], read_png(next(tmp_path.glob("*.png"))))
    # The metadata is the JSON the CLI writes beside the frame, less the file names and the frame's index.
    (meta_file,) = [p for p in tmp_path.glob("*.json") if "manifest" not in p.name]
    written_meta = json.loads(meta_file.read_text())
    for key in ("frame", "image", "aov"):
        written_meta.pop(key)
    assert frame["metadata"] == written_meta
    k = np.array(frame["metadata"]["camera"]["K"])
    assert k[0, 2] == pytest.approx((96 - 1) / 2) and k[1, 2] == pytest.approx((54 - 1) / 2)
    # The harbour's view holds water, floor or objects and sky: the mask and the ids are not one value.
    assert len(np.unique(frame["water_mask"])) >= 2 and len(np.unique(frame["object_id"])) >= 2
    with pytest.raises(ValueError, match="no AOV named 'colour'"):
        lagoon.Renderer(lagoon.Scene.load(DEFAULT, SMALL)).render(aovs=["colour"])


def test_rendering_lets_other_python_threads_run():
    renderer = lagoon.Renderer(lagoon.Scene.load(DEFAULT, {"render.width": 320, "render.height": 180}))
    renderer.render(time=0.5)  # compile the pipelines first
    ticks, done = [0], threading.Event()

    def count():
        while not done.is_set():
            ticks[0] += 1
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    started = time.perf_counter()
    renderer.render(time=1.5)
    elapsed = time.perf_counter() - started
    done.set()
    counter.join()
    assert renderer.validation_errors == 0
    # Holding the GIL for the whole frame would leave the counter at most a tick or two.
    assert ticks[0] >= min(20, int(elapsed / 0.002)), (ticks[0], elapsed)


def test_the_water_at_points_is_what_lagoon_probe_prints():
    harbour = os.path.join(SOURCE, "scenes", "harbour.json")  # vehicles: the wakes are part of the answer
    points = np.array([[0.0, 0.0], [12.5, -40.0], [-20.0, 35.0], [3.0, 30.0]])
    water = lagoon.WaveQuery(lagoon.Scene.load(harbour)).sample(6.5, points)
    args = ["probe", "--scene", harbour, "--time", "6.5"]
    for x, z in points:
        args += ["--at", f"{x!r},{z!r}"]
    r = cli(*args)
    assert r.returncode == 0, r.stderr
    lines = [json.loads(line) for line in r.stdout.splitlines()]
    assert len(lines) == len(points)
    for i, line in enumerate(lines):
        assert water["height"][i] == pytest.approx(line["height_m"], abs=1e-12)
        assert water["wake_height"][i] == pytest.approx(line["wake_height_m"], abs=1e-12)
        assert water["normal"][i] == pytest.approx(line["normal"], abs=1e-12)
        assert water["velocity"][i] == pytest.approx(line["velocity_mps"], abs=1e-12)
        assert water["error_bound"][i] == pytest.approx(line["error_bound_m"], abs=1e-12)
    assert np.any(water["wake_height"] != 0.0), "a point in the boats' wakes must feel them"
    assert np.allclose(np.linalg.norm(water["normal"], axis=1), 1.0)


def test_a_wavelength_cut_leaves_the_short_waves_out():
    scene = lagoon.Scene.load(DEFAULT)
    points = np.random.default_rng(1).uniform(-50, 50, size=(200, 2))
    full = lagoon.WaveQuery(scene).sample(3.0, points)["height"]
    long_only = lagoon.WaveQuery(scene, max_wavenumber=0.5).sample(3.0, points)["height"]
    # The cut sea is smoother: the short waves' share of the height's variance is gone.
    assert np.std(np.diff(long_only)) < np.std(np.diff(full))
    assert not np.allclose(full, long_only)


def test_bad_points_and_times_are_refused():
    query = lagoon.WaveQuery(lagoon.Scene.load(DEFAULT))
    with pytest.raises(ValueError, match="N x 2"):
        query.sample(1.0, np.zeros((3, 3)))
    with pytest.raises(ValueError, match="not finite"):
        query.sample(1.0, np.array([[np.nan, 0.0]]))
    with pytest.raises(ValueError, match="time"):
        query.sample(float("inf"), np.zeros((1, 2)))
    with pytest.raises(ValueError, match="max_wavenumber"):
        lagoon.WaveQuery(lagoon.Scene.load(DEFAULT), max_wavenumber=-1)


def test_a_time_out_of_bounds_or_too_far_for_the_bodies_is_refused_with_the_fix():
    # The harbour's three hulls (buoy, moored boat, boat): a frame or a World step may ask for at most 300
    # hull-seconds of physics from where the bodies are (docs/physics.md), as the scene file's time_s may.
    scene = lagoon.Scene.load(os.path.join(SOURCE, "scenes", "harbour.json"), {"render.width": 32, "render.height": 18})
    renderer = lagoon.Renderer(scene)
    for bad in (float("nan"), -1.0, 1e9):
        with pytest.raises(lagoon.SceneError, match="time_s: .*(finite|out of range)"):
            renderer.render(time=bad)
    with pytest.raises(lagoon.SceneError, match="600 hull-seconds to reach 200 s.*bodies_start_s"):
        renderer.render(time=200.0)
    assert renderer.render(time=2.0)["image"].shape == (18, 32, 3)  # refused frames leave it usable
    with pytest.raises(lagoon.SceneError, match="set bodies_start_s to 500 or later"):
        scene.time_s = 600.0
    with pytest.raises(lagoon.SceneError, match="World.advance.*hull-seconds"):
        lagoon.World(scene).advance(150.0)


def test_the_buoy_example_follows_the_water():
    import importlib.util

    spec = importlib.util.spec_from_file_location("buoy", os.path.join(SOURCE, "examples", "python", "buoy.py"))
    buoy = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(buoy)
    times, heave, surface, period = buoy.simulate(DEFAULT, 15.0)
    settled = times > 3.0
    # Its natural period is far below the waves' (a quasi-static follower): heave tracks the water's height,
    # neither amplified (resonance) nor left behind; a sign or stiffness mistake breaks either bound.
    assert period < 1.0
    ratio = heave[settled].std() / surface[settled].std()
    assert 0.8 < ratio < 1.3, ratio
    assert np.corrcoef(surface[settled], heave[settled])[0, 1] > 0.85


def test_the_worlds_bodies_move_as_lagoon_probe_steps_them():
    harbour = os.path.join(SOURCE, "scenes", "harbour.json")
    world = lagoon.World(lagoon.Scene.load(harbour))
    r = cli("probe", "--scene", harbour, "--object", "buoy", "--time", "4", "--frames", "3", "--fps", "10")
    assert r.returncode == 0, r.stderr
    expected = [json.loads(line) for line in r.stdout.splitlines()]
    for i, line in enumerate(expected):
        world.advance(4.0 + i / 10)
        (buoy,) = [p for p in world.poses() if p.get("object") == "buoy"]
        assert buoy == line, (buoy, line)
    names = [p.get("object") or p.get("vehicle") for p in world.poses()]
    assert "buoy" in names and len(names) >= 2, names
    # Going back in time replays from 0 and lands on the same pose.
    world.advance(4.0)
    assert [p for p in world.poses() if p.get("object") == "buoy"][0] == expected[0]
    with pytest.raises(ValueError, match="time"):
        world.advance(-1.0)


def test_the_auv_camera_example_steers_the_auv_renders_and_rewards_from_the_ground_truth():
    import importlib.util

    spec = importlib.util.spec_from_file_location("auv", os.path.join(SOURCE, "examples", "python", "auv_camera.py"))
    auv = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(auv)
    env = auv.AuvCameraEnv(os.path.join(SOURCE, "scenes", "harbour.json"), width=64, height=36, max_steps=3)
    obs = env.reset()
    assert obs["image"].shape == (36, 64, 3) and obs["depth"].shape == (36, 64)
    start = env.position.copy()
    assert start == pytest.approx([0.0, -4.4, 6.0], abs=1e-6)  # where reset() put it, at its depth_m
    done, rewards = False, []
    while not done:
        obs, reward, done, info = env.step((1.0, 0.0))  # straight ahead at 1 m/s
        rewards.append(reward)
        # The frame was drawn from the AUV's nose: the metadata's camera is the vehicle's pose.
        nose = info["position"] + env.NOSE_M * np.array([0.0, 0.0, -1.0])
        assert obs["metadata"]["camera"]["position"] == pytest.approx(nose.tolist(), abs=1e-5)
    # Heading north (-z) at 1 m/s for 3 steps of 0.5 s, as the helm ordered.
    assert env.position - start == pytest.approx([0.0, 0.0, -1.5], abs=1e-6)
    # Under the harbour's water, looking down at the floor: some of the view is floor 2-8 m away, not all.
    assert all(0.0 < r < 1.0 for r in rewards), rewards
    # The camera is under the water: every ray starts in it (2), or meets the surface from below (1); none in air.
    assert set(np.unique(obs["water_mask"])) <= {1.0, 2.0} and np.all(obs["water_mask"][-1] == 2)


def test_the_auv_example_runs_from_the_source_folder_as_the_readme_says():
    # After `make test`, `python3 examples/python/auv_camera.py` from the source folder finds the module in
    # build/python by itself: no PYTHONPATH, nothing installed.
    module_dir = os.path.dirname(os.path.realpath(lagoon.__file__))
    if module_dir != os.path.realpath(os.path.join(SOURCE, "build", "python")):
        pytest.skip(f"the module was built in {module_dir}, not in the source folder's build/")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    r = subprocess.run(["/usr/bin/python3", "examples/python/auv_camera.py", "--steps", "1"], cwd=SOURCE, env=env,
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert "total reward" in r.stdout, r.stdout
