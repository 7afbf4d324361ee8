#!/usr/bin/env python3
"""An AUV's camera loop in the style of a Gym environment: the agent gives the harbour's AUV a helm order
(speed, rate of turn), the world steps the vehicle, the camera on its nose renders colour, depth, the water
mask and object ids, and the reward comes from the ground truth (here: keep the sea floor in view, 2-8 m
ahead, while moving).

    python3 examples/python/auv_camera.py [--scene scenes/harbour.json] [--steps 10]
"""
import argparse
import math
import os
import sys

import numpy as np

try:
    import lagoon
except ImportError:  # in a source tree after `make test` the module is in build/python
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "build", "python"))
    import lagoon


class AuvCameraEnv:
    """reset() -> observation; step((speed_mps, yaw_rate_degps)) -> (observation, reward, done, info). An
    observation is the frame's dict: image (H x W x 3 uint8), depth (m, +inf for the sky), water_mask,
    object_id, metadata. The vehicle is the scene's `vehicle`, steered through lagoon.World; the Renderer
    shares the world's tracks, so the frame shows every vehicle where the world put it."""

    NOSE_M = 1.3  # ahead of the model's origin: the AUV is 2 m long, so the camera sits just off its nose
    PITCH_DEG = -20.0  # looking a little down, toward the floor

    def __init__(self, scene_path, vehicle="auv", width=160, height=90, dt_s=0.5, max_steps=100,
                 start_xz=(0.0, 6.0), start_heading_deg=0.0):
        self.scene = lagoon.Scene.load(scene_path, {"render.width": width, "render.height": height})
        self.vehicle, self.dt, self.max_steps = vehicle, dt_s, max_steps
        self.start_xz, self.start_heading = list(start_xz), start_heading_deg
        self.fov = self.scene.to_dict()["camera"].get("fov_deg", 55)

    def reset(self):
        self.world = lagoon.World(self.scene)  # a fresh world: the vehicles back on their paths
        self.renderer = lagoon.Renderer(self.scene, world=self.world)
        self.t, self.steps, self.heading = float(self.scene.time_s), 0, self.start_heading
        self.world.set_pose(self.vehicle, self.start_xz, self.start_heading, time=self.t)
        self.world.advance(self.t)
        return self._observe()

    def step(self, action):
        speed = float(np.clip(action[0], 0.0, 2.0))
        yaw_rate = float(np.clip(action[1], -30.0, 30.0))
        self.world.helm(self.vehicle, speed, yaw_rate, time=self.t)
        self.t += self.dt
        self.heading += yaw_rate * self.dt  # what the order does to the compass heading, exactly
        self.world.advance(self.t)
        self.steps += 1
        obs = self._observe()
        depth, mask = obs["depth"], obs["water_mask"]
        floor = obs["object_id"] == -1  # the ground truth's id of the sea floor
        in_band = floor & (depth > 2.0) & (depth < 8.0) & (mask == 2)
        reward = float(in_band.mean())  # the share of the view that is floor at a useful distance
        info = {"time_s": self.t, "position": self.position.copy(), "heading_deg": self.heading}
        return obs, reward, self.steps >= self.max_steps, info

    def _pose(self):
        (pose,) = [p for p in self.world.poses() if p.get("vehicle") == self.vehicle]
        return pose

    def _observe(self):
        self.position = np.array(self._pose()["origin"], dtype=float)
        h, pitch = math.radians(self.heading), math.radians(self.PITCH_DEG)
        ahead = np.array([math.sin(h), 0.0, -math.cos(h)])  # compass: 0 = north = -z, 90 = east = +x
        eye = self.position + self.NOSE_M * ahead
        look = ahead * math.cos(pitch) + np.array([0.0, math.sin(pitch), 0.0])
        camera = {"position": eye.tolist(), "look_at": (eye + look).tolist(), "fov_deg": self.fov}
        return self.renderer.render(time=self.t, camera=camera, aovs=["depth", "water_mask", "object_id"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="scenes/harbour.json")
    parser.add_argument("--vehicle", default="auv")
    parser.add_argument("--steps", type=int, default=10)
    args = parser.parse_args()
    env = AuvCameraEnv(args.scene, vehicle=args.vehicle, max_steps=args.steps)
    obs, done, total = env.reset(), False, 0.0
    while not done:
        # A simple policy: cruise at 1 m/s and turn toward the side of the image that shows more floor.
        floor = obs["object_id"] == -1
        half = floor.shape[1] // 2
        turn = 10.0 * np.sign(floor[:, half:].mean() - floor[:, :half].mean())
        obs, reward, done, info = env.step((1.0, turn))
        total += reward
        print(f"t {info['time_s']:5.1f} s  at {np.round(info['position'], 2)}  heading {info['heading_deg']:6.1f}"
              f"  reward {reward:.3f}")
    print(f"total reward {total:.3f} over {env.steps} steps")


if __name__ == "__main__":
    main()
