#!/usr/bin/env python3
"""Writes the scene-stripping tests' scenes: a sphere over a floor, both with Test/StripLight
material instances (the sidecars), under different lights (KHR_lights_punctual):

  sun.gltf        one directional light: ForwardBase only, no ForwardAdd, no vertex lights
  two_suns.gltf   two directional lights: one ForwardAdd variant, DIRECTIONAL
  lamps.gltf      a directional light and three point lights: with --pixel-lights 1, one
                  additive POINT pass per object and the rest as VERTEXLIGHT_ON vertex lights

Geometry and the glTF writer come from scenes/demo/make_demo.py. Deterministic: run it again after
changing it.
"""
import base64
import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[2] / "scenes" / "demo"))
import make_demo  # noqa: E402

SCENES = {
    "sun": [{"name": "Sun", "type": "directional", "intensity": 2.0}],
    "two_suns": [{"name": "Sun", "type": "directional", "intensity": 2.0},
                 {"name": "Rim", "type": "directional", "color": [0.4, 0.5, 1.0], "intensity": 1.0}],
    "lamps": [{"name": "Sun", "type": "directional", "intensity": 1.0},
              {"name": "Red", "type": "point", "color": [1, 0.2, 0.2], "intensity": 8.0},
              {"name": "Green", "type": "point", "color": [0.2, 1, 0.2], "intensity": 6.0},
              {"name": "Blue", "type": "point", "color": [0.2, 0.2, 1], "intensity": 4.0}],
}
LIGHT_NODES = {
    "Sun": {"matrix": make_demo.look_at((2.0, 5.0, 4.0), (0.0, 0.0, 0.0))},
    "Rim": {"matrix": make_demo.look_at((-3.0, 2.0, -4.0), (0.0, 0.0, 0.0))},
    "Red": {"translation": [-1.5, 1.2, 1.0]},
    "Green": {"translation": [1.5, 1.0, 1.0]},
    "Blue": {"translation": [0.0, 1.5, -1.5]},
}


def write(name, lights):
    buf = make_demo.Buffer()
    meshes = [buf.mesh("Ball", make_demo.sphere(24, 12, 0.6), 0),
              buf.mesh("Floor", make_demo.plane(2.5, 2.0), 1)]
    materials = [{"name": "Surface"}, {"name": "Floor"}]
    nodes = [{"name": "Ball", "mesh": 0, "translation": [0, 0.6, 0]},
             {"name": "Floor", "mesh": 1},
             {"name": "Camera", "camera": 0,
              "matrix": make_demo.look_at((0.0, 2.2, 4.0), (0.0, 0.4, 0.0))}]
    for i, light in enumerate(lights):
        nodes.append(dict(name=light["name"], extensions={"KHR_lights_punctual": {"light": i}},
                          **LIGHT_NODES[light["name"]]))
    gltf = {
        "asset": {"version": "2.0", "generator": "kiln tests/strip/data/make_scenes.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": lights}},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "cameras": [{"type": "perspective",
                     "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 50.0}}],
        "buffers": [{"byteLength": len(buf.data),
                     "uri": "data:application/octet-stream;base64," +
                            base64.b64encode(bytes(buf.data)).decode()}],
        "bufferViews": buf.views,
        "accessors": buf.accessors,
    }
    (HERE / (name + ".gltf")).write_text(json.dumps(gltf, indent=1) + "\n")
    sidecar = {"kiln_materials": 1,
               "materials": {"Surface": "surface.material", "Floor": "floor.material"}}
    (HERE / (name + ".kiln.json")).write_text(json.dumps(sidecar, indent=2) + "\n")


def main():
    for name, lights in SCENES.items():
        write(name, lights)


if __name__ == "__main__":
    main()
