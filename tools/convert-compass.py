#!/usr/bin/env python3
"""Rewrites a Lagoon scene written for the old, mirrored compass (azimuths clockwise from +z toward +x)
for the right-handed one (clockwise from north = -z toward east = +x, docs/scene-format.md "Axes").

Every angle a becomes 180 - a, which names the same direction on the new compass, so the scene renders as
before: sun.azimuth_deg, ocean.spectrum.wind_direction_deg, the waves' and gusts' direction_deg,
camera.yaw_deg and the yaw (first element) of objects[].rotation_deg. The file is edited in place as text,
so its layout and comments stay; nothing else changes. An object without rotation_deg now faces north
where it faced south: the script names each one (add "rotation_deg": [180, 0, 0] to keep it as it was,
or leave it if the model looks the same from both sides).

Usage: tools/convert-compass.py SCENE.json [...]     (exit status 1 if a file could not be converted)
"""
import json
import os
import re
import sys

NUMBER = r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?"
# Fields whose range is 0..360 keep it; the others (-360..360) are written in (-180, 180].
FULL_TURN = {"azimuth_deg", "wind_direction_deg"}


def converted(name, text):
    value = 180.0 - float(text)
    value = value % 360.0 if name in FULL_TURN else (value + 180.0) % 360.0 - 180.0
    if value == -180.0 and name not in FULL_TURN:
        value = 180.0
    return str(int(value)) if value == int(value) else repr(round(value, 9))


def convert_text(text):
    def field(m):
        return m.group(1) + converted(m.group(2), m.group(3))

    text = re.sub(r'("(azimuth_deg|wind_direction_deg|direction_deg|yaw_deg)"\s*:\s*)(' + NUMBER + ")",
                  field, text)

    def rotation(m):
        return m.group(1) + converted("yaw_deg", m.group(2))

    return re.sub(r'("rotation_deg"\s*:\s*\[\s*)(' + NUMBER + ")", rotation, text)


def main(paths):
    failed = False
    for path in paths:
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
            scene = json.loads(text)
        except (OSError, ValueError) as e:
            print(f"{path}: not converted: {e}", file=sys.stderr)
            failed = True
            continue
        out = convert_text(text)
        json.loads(out)  # the edit touches numbers only; a failure here is a bug in this script
        with open(path + ".tmp", "w", encoding="utf-8") as f:
            f.write(out)
        os.replace(path + ".tmp", path)
        print(f"{path}: converted")
        for i, o in enumerate(scene.get("objects", []) if isinstance(scene, dict) else []):
            if isinstance(o, dict) and "rotation_deg" not in o:
                print(f"{path}: objects[{i}] ({o.get('name', 'unnamed')}) has no rotation_deg: it now faces "
                      "north; add \"rotation_deg\": [180, 0, 0] to keep its old heading")
    return 1 if failed else 0


if __name__ == "__main__":
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1:]))
