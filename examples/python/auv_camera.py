#!/usr/bin/env python3
"""An AUV's camera loop in the style of a Gym environment: the agent sets the vehicle's heading change, the
environment moves the camera, renders colour, depth and the water mask, and computes a reward from the
ground truth (here: keep the sea floor in view, 2-8 m ahead, while moving forward).

    PYTHONPATH=build/python python3 examples/python/auv_camera.py [--scene scenes/reef-dive.json] [--steps 10]
"""
import argparse
import math

import numpy as np

import lagoon


class AuvCameraEnv:
    """reset() -> observation; step(turn_rad) -> (observation, reward, done, info). An observation is the
    frame's dict: image (H x W x 3 uint8), depth (m, +inf for the sky), water_mask, object_id, metadata."""

    def __init__(self, scene_path, width=160, height=90, speed_mps=0.5, dt_s=0.5, max_steps=100):
        self.scene = lagoon.Scene.load(scene_path, {"render.width": width, "render.height": height})
        self.renderer = lagoon.Renderer(self.scene)
        self.speed, self.dt, self.max_steps = speed_mps, dt_s, max_steps

    def reset(self):
        camera = self.scene.to_dict()["camera"]
        self.position = np.array(camera["position"], dtype=float)
        look = np.array(camera["look_at"], dtype=float) - self.position
        self.heading = math.atan2(look[0], look[2])  # about +y, 0 = +z
        self.pitch = math.atan2(look[1], math.hypot(look[0], look[2]))
        self.t, self.steps = self.scene.time_s, 0
        return self._observe()

    def step(self, turn_rad):
        self.heading += float(np.clip(turn_rad, -0.3, 0.3))
        self.position += self.speed * self.dt * np.array([math.sin(self.heading), 0.0, math.cos(self.heading)])
        self.t += self.dt
        self.steps += 1
        obs = self._observe()
        depth, mask = obs["depth"], obs["water_mask"]
        floor = obs["object_id"] == -1  # the ground truth's id of the sea floor
        in_band = floor & (depth > 2.0) & (depth < 8.0) & (mask == 2)
        reward = float(in_band.mean())  # the share of the view that is floor at a useful distance
        return obs, reward, self.steps >= self.max_steps, {"time_s": self.t, "position": self.position.copy()}

    def _observe(self):
        direction = np.array([math.sin(self.heading) * math.cos(self.pitch), math.sin(self.pitch),
                              math.cos(self.heading) * math.cos(self.pitch)])
        camera = {"position": self.position.tolist(), "look_at": (self.position + direction).tolist(),
                  "fov_deg": self.scene.to_dict()["camera"].get("fov_deg", 55)}
        return self.renderer.render(time=self.t, camera=camera, aovs=["depth", "water_mask", "object_id"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="scenes/reef-dive.json")
    parser.add_argument("--steps", type=int, default=10)
    args = parser.parse_args()
    env = AuvCameraEnv(args.scene, max_steps=args.steps)
    obs, done, total = env.reset(), False, 0.0
    while not done:
        # A simple policy: turn toward the side of the image that shows more floor.
        floor = obs["object_id"] == -1
        half = floor.shape[1] // 2
        turn = 0.1 * np.sign(floor[:, half:].mean() - floor[:, :half].mean())
        obs, reward, done, info = env.step(turn)
        total += reward
        print(f"t {info['time_s']:5.1f} s  at {np.round(info['position'], 2)}  reward {reward:.3f}")
    print(f"total reward {total:.3f} over {env.steps} steps")


if __name__ == "__main__":
    main()
