"""lagoon.World (issue 38): a controller steers and places vehicles, a Renderer built with world= draws them
where the world put them, and a hull's water is the sea WaveQuery gives there. Checked against closed forms
(the ordered arc), against the frame's own camera model, and against WaveQuery."""
import json
import math
import os

import numpy as np
import pytest

import lagoon

SOURCE = os.environ.get("LAGOON_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
HARBOUR = os.path.join(SOURCE, "scenes", "harbour.json")


def vehicle_pose(world, name):
    (pose,) = [p for p in world.poses() if p.get("vehicle") == name]
    return pose


def test_a_placed_vehicle_runs_the_ordered_arc():
    world = lagoon.World(lagoon.Scene.load(HARBOUR))
    assert world.vehicles == ["boat", "auv"]
    world.advance(1.0)
    # Put the boat at (4, -3) heading north (-z) at 3 m/s turning to starboard at 30 deg/s: a circle of
    # radius v / w = 5.73 m, clockwise seen from above, so a quarter turn later it is r east and r north of
    # the start, and half a turn later 2r east.
    v, w = 3.0, math.radians(30.0)
    r = v / w
    world.set_pose("boat", [4.0, -3.0], 0.0, speed_mps=v, yaw_rate_degps=30.0)
    world.advance(1.0 + (math.pi / 2) / w)
    x, _, z = vehicle_pose(world, "boat")["origin"]
    assert (x, z) == pytest.approx((4.0 + r, -3.0 - r), abs=1e-6)
    world.advance(1.0 + math.pi / w)
    x, _, z = vehicle_pose(world, "boat")["origin"]
    assert (x, z) == pytest.approx((4.0 + 2 * r, -3.0), abs=1e-6)
    # Then straight on (helm: no turn) at 2 m/s: heading south now, so +z.
    t = world.time
    world.helm("boat", 2.0)
    world.advance(t + 2.5)
    x2, _, z2 = vehicle_pose(world, "boat")["origin"]
    assert (x2, z2) == pytest.approx((x, z + 5.0), abs=1e-6)
    # The submerged AUV keeps its depth wherever it is put.
    world.set_pose(1, [0.0, 0.0], 90.0, speed_mps=1.0)
    world.advance(world.time + 2.0)
    assert vehicle_pose(world, "auv")["origin"] == pytest.approx([2.0, -4.4, 0.0], abs=1e-6)


def test_bad_orders_are_refused_with_what_to_do():
    world = lagoon.World(lagoon.Scene.load(HARBOUR))
    world.advance(2.0)
    with pytest.raises(KeyError, match="boat, auv"):
        world.helm("tug", 1.0)
    with pytest.raises(IndexError, match="has 2"):
        world.helm(5, 1.0)
    with pytest.raises(ValueError, match="world's time"):
        world.helm("boat", 1.0, time=1.0)
    with pytest.raises(ValueError, match=r"\[x, z\]"):
        world.set_pose("boat", [1.0, 2.0, 3.0], 0.0)
    with pytest.raises(ValueError, match="speed_mps"):
        world.helm("boat", float("nan"))
    with pytest.raises(KeyError, match="neither a floating object"):
        world.water_under("rocks")
    with pytest.raises(KeyError, match="neither a floating object"):
        world.water_under("auv")  # submerged: no surface to feel


def project(meta, point):
    """Pixel (u, v) of a world point through the frame's own camera model (OpenCV axes)."""
    camera_from_world = np.linalg.inv(np.array(meta["camera"]["world_from_camera"]))
    p = camera_from_world @ np.append(point, 1.0)
    K = np.array(meta["camera"]["K"])
    return (K @ (p[:3] / p[2]))[:2], p[2]


def test_the_renderer_draws_the_vehicle_where_the_world_put_it():
    # No wakes: what is checked is where the boat is drawn, and a still frame would replay their history.
    scene = lagoon.Scene.load(HARBOUR, {"render.width": 128, "render.height": 72, "wakes.enabled": False})
    boat_id = len(scene.to_dict()["objects"]) + 1  # object_id of vehicles[0] (docs/datasets.md)
    world = lagoon.World(scene)
    renderer = lagoon.Renderer(scene, world=world)
    world.advance(3.0)
    world.set_pose("boat", [6.0, 14.0], 90.0)  # 30 m ahead of the camera at (0, 5, -16), a little right
    world.advance(4.0)
    frame = renderer.render(time=4.0, aovs=["object_id"])
    rows, cols = np.nonzero(frame["object_id"] == boat_id)
    assert len(rows) > 10, "the placed boat must be in view"
    (u, v), depth = project(frame["metadata"], np.array(vehicle_pose(world, "boat")["origin"]))
    assert depth > 0
    # Its pixels gather around where its origin projects (the hull is 2-3 m across: some pixels off).
    assert abs(cols.mean() - u) < 6 and abs(rows.mean() - v) < 6, (cols.mean(), rows.mean(), u, v)
    # A renderer without the world keeps the boat on its path: elsewhere.
    alone = lagoon.Renderer(scene).render(time=4.0, aovs=["object_id"])
    r2, c2 = np.nonzero(alone["object_id"] == boat_id)
    assert len(r2) == 0 or abs(c2.mean() - u) > 10 or abs(r2.mean() - v) > 10
    # Put behind the camera, it is gone from the frame.
    world.set_pose("boat", [0.0, -60.0], 0.0)
    world.advance(5.0)
    assert not np.any(renderer.render(time=5.0, aovs=["object_id"])["object_id"] == boat_id)
    with pytest.raises(ValueError, match="same vehicles"):
        lagoon.Renderer(lagoon.Scene.load(os.path.join(SOURCE, "scenes", "default.json")), world=world)


def test_the_water_under_a_hull_is_the_sea_it_floats_on():
    scene = lagoon.Scene.load(HARBOUR, {"wakes.enabled": False})
    world = lagoon.World(scene)
    world.advance(5.0)
    water = world.water_under("buoy")
    points = water["points"]
    assert points.shape[1] == 3 and len(points) == len(water["water_height_m"]) > 100
    # The bodies step at 120 Hz and feel the water at each step's start; they resolve waves down to 2 m
    # (ocean/local_heights.h: lattice spacing 0.5 m), so the sea they feel is WaveQuery's with k <= pi.
    last_step = (math.floor(5.0 * 120 + 1e-9) - 1) / 120
    query = lagoon.WaveQuery(scene, max_wavenumber=math.pi)
    sea = query.sample(last_step, points[:, [0, 2]])["height"]
    assert np.max(np.abs(water["water_height_m"] - sea)) < 0.01
    # A quarter of a second off is several centimetres off: the comparison can tell.
    later = query.sample(last_step + 0.25, points[:, [0, 2]])["height"]
    assert np.max(np.abs(water["water_height_m"] - later)) > 0.03
    # It floats: the water carries it, pushing up, over a wetted part of its hull.
    assert water["force_n"][1] > 0 and water["wetted_area_m2"] > 0
    assert np.allclose(water["centre_of_mass"], [p for p in world.poses() if p.get("object") == "buoy"][0]["centre_of_mass"])
