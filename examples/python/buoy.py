#!/usr/bin/env python3
"""A buoy whose heave is integrated in Python from lagoon.WaveQuery: the water's height under it each step,
a linear buoyancy spring and a damper, semi-implicit Euler at 25 Hz. A buoy this small and light (1 m across,
10 cm draught: natural period 0.63 s) follows the bay's waves (periods of 2-4 s), so its heave tracks the
water's height.

    python3 examples/python/buoy.py [--scene scenes/default.json] [--seconds 30]
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

RHO, G = 1025.0, 9.81  # sea water kg/m³, m/s²


def simulate(scene_path, seconds, rate_hz=25.0, at=(0.0, 0.0), radius_m=0.5, draught_m=0.1):
    scene = lagoon.Scene.load(scene_path)
    # A hull of 1 m averages out waves shorter than about twice its size: leave them out of the query.
    water = lagoon.WaveQuery(scene, max_wavenumber=2 * math.pi / (4 * radius_m))
    area = math.pi * radius_m**2                 # waterplane area, m²
    mass = RHO * area * draught_m                # floating at its draught in still water
    stiffness = RHO * G * area                   # N/m
    damping = 0.2 * 2 * math.sqrt(stiffness * mass)  # 20 % of critical
    dt = 1.0 / rate_hz
    z, w = 0.0, 0.0  # the buoy's heave (m, from its still-water position) and its vertical velocity
    times, heave, surface = [], [], []
    point = np.array([at])
    for step in range(int(seconds * rate_hz)):
        t = step * dt
        eta = water.sample(t, point)["height"][0]
        force = stiffness * (eta - z) - damping * w
        w += force / mass * dt
        z += w * dt
        times.append(t)
        heave.append(z)
        surface.append(eta)
    return np.array(times), np.array(heave), np.array(surface), 2 * math.pi * math.sqrt(mass / stiffness)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="scenes/default.json")
    parser.add_argument("--seconds", type=float, default=30.0)
    args = parser.parse_args()
    times, heave, surface, period = simulate(args.scene, args.seconds)
    settled = times > 5.0  # past the start from rest
    print(f"natural period {period:.2f} s; water height std {surface[settled].std():.3f} m, buoy heave std "
          f"{heave[settled].std():.3f} m, correlation {np.corrcoef(surface[settled], heave[settled])[0, 1]:.3f}")
    for t, z, eta in list(zip(times, heave, surface))[:: int(len(times) / 10) or 1]:
        print(f"t {t:6.2f} s  water {eta:+.3f} m  buoy {z:+.3f} m")


if __name__ == "__main__":
    main()
