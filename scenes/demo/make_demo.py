#!/usr/bin/env python3
"""Writes Kiln's demo scene: demo.gltf (glTF 2.0, one embedded buffer) and demo.kiln.json.

Ten spheres, one per shipped material (assigned by name in the sidecar), in two rows over a
floor plane with a glTF metallic-roughness material (rendered with Kiln/StandardMetallic), lit by
a directional, a point and a spot light (KHR_lights_punctual), seen by one perspective camera.
Run it again after changing it; the output is deterministic.
"""
import base64
import json
import math
import struct
from pathlib import Path

MATERIALS = ["Unlit", "Lambert", "LambertAmbient", "BlinnPhong", "BlinnPhongTextured",
             "EnergyConserving", "Standard", "StandardMetallic", "MultiLight", "Deferred"]


def sphere(segments=48, rings=24, radius=0.45):
    pos, nrm, uv, idx = [], [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            pos.append(tuple(radius * c for c in n))
            nrm.append(n)
            uv.append((s / segments, r / rings))
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            idx += [a, b, a + 1, a + 1, b, b + 1]  # counter-clockwise seen from outside
    return pos, nrm, uv, idx


def plane(half=6.0, tiles=6.0):
    pos = [(-half, 0, -half), (-half, 0, half), (half, 0, half), (half, 0, -half)]
    nrm = [(0, 1, 0)] * 4
    uv = [(0, 0), (0, tiles), (tiles, tiles), (tiles, 0)]
    return pos, nrm, uv, [0, 1, 2, 0, 2, 3]


def look_at(eye, target):
    """Column-major node matrix whose -Z axis points from eye to target, +Y roughly up."""
    f = [t - e for t, e in zip(target, eye)]
    fl = math.sqrt(sum(c * c for c in f))
    f = [c / fl for c in f]
    up = (0, 1, 0) if abs(f[1]) < 0.99 else (0, 0, 1)
    x = [up[1] * -f[2] - up[2] * -f[1], up[2] * -f[0] - up[0] * -f[2], up[0] * -f[1] - up[1] * -f[0]]
    xl = math.sqrt(sum(c * c for c in x))
    x = [c / xl for c in x]
    z = [-c for c in f]
    y = [z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]]
    return [round(v, 6) for v in x + [0] + y + [0] + z + [0] + list(eye) + [1]]


class Buffer:
    def __init__(self):
        self.data = bytearray()
        self.views, self.accessors = [], []

    def add(self, values, fmt, kind, target, minmax=False):
        while len(self.data) % 4:
            self.data.append(0)
        offset = len(self.data)
        flat = [c for v in values for c in (v if isinstance(v, tuple) else (v,))]
        self.data += struct.pack("<%d%s" % (len(flat), fmt), *flat)
        self.views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(self.data) - offset,
                           "target": target})
        acc = {"bufferView": len(self.views) - 1, "componentType": 5126 if fmt == "f" else 5125,
               "count": len(values), "type": kind}
        if minmax:
            acc["min"] = [min(v[i] for v in values) for i in range(3)]
            acc["max"] = [max(v[i] for v in values) for i in range(3)]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def mesh(self, name, geometry, material):
        pos, nrm, uv, idx = geometry
        return {"name": name, "primitives": [{
            "attributes": {"POSITION": self.add(pos, "f", "VEC3", 34962, True),
                           "NORMAL": self.add(nrm, "f", "VEC3", 34962),
                           "TEXCOORD_0": self.add(uv, "f", "VEC2", 34962)},
            "indices": self.add(idx, "I", "SCALAR", 34963), "material": material}]}


def main():
    here = Path(__file__).resolve().parent
    buf = Buffer()
    ball = sphere()
    meshes, nodes, materials = [], [], []
    for i, name in enumerate(MATERIALS):
        materials.append({"name": name, "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]}})
        meshes.append(buf.mesh(name, ball, i))
        row, col = divmod(i, 5)
        nodes.append({"name": name, "mesh": i,
                      "translation": [(col - 2) * 1.2, 0.45, -0.7 + row * 1.4]})
    materials.append({"name": "Floor", "pbrMetallicRoughness": {
        "baseColorFactor": [0.35, 0.35, 0.37, 1], "metallicFactor": 0.0, "roughnessFactor": 0.75}})
    meshes.append(buf.mesh("Floor", plane(), len(materials) - 1))
    nodes.append({"name": "Floor", "mesh": len(meshes) - 1})
    nodes.append({"name": "Camera", "camera": 0, "matrix": look_at((0.0, 3.4, 6.2), (0.0, 0.2, 0.0))})
    lights = [
        {"name": "Sun", "type": "directional", "color": [1.0, 0.95, 0.85], "intensity": 1.2},
        {"name": "Blue point", "type": "point", "color": [0.35, 0.55, 1.0], "intensity": 6.0,
         "range": 9.0},
        {"name": "Pink spot", "type": "spot", "color": [1.0, 0.35, 0.6], "intensity": 14.0,
         "range": 12.0, "spot": {"innerConeAngle": 0.25, "outerConeAngle": 0.45}},
    ]
    nodes.append({"name": "Sun", "matrix": look_at((2.0, 5.0, 4.0), (0.0, 0.0, 0.0)),
                  "extensions": {"KHR_lights_punctual": {"light": 0}}})
    nodes.append({"name": "Blue point", "translation": [-2.6, 1.4, 1.6],
                  "extensions": {"KHR_lights_punctual": {"light": 1}}})
    nodes.append({"name": "Pink spot", "matrix": look_at((2.4, 3.2, 1.2), (1.2, 0.0, 0.0)),
                  "extensions": {"KHR_lights_punctual": {"light": 2}}})
    gltf = {
        "asset": {"version": "2.0", "generator": "kiln scenes/demo/make_demo.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": lights}},
        "scene": 0,
        "scenes": [{"name": "Kiln demo", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "cameras": [{"name": "Main", "type": "perspective",
                     "perspective": {"yfov": 0.75, "znear": 0.1, "zfar": 100.0}}],
        "buffers": [{"byteLength": len(buf.data),
                     "uri": "data:application/octet-stream;base64," +
                            base64.b64encode(bytes(buf.data)).decode()}],
        "bufferViews": buf.views,
        "accessors": buf.accessors,
    }
    (here / "demo.gltf").write_text(json.dumps(gltf, indent=1) + "\n")
    sidecar = {"kiln_materials": 1,
               "description": "Each sphere shows one shipped material instance",
               "ambient": [0.05, 0.055, 0.07],
               "materials": {n: "../../materials/%s.material" % n for n in MATERIALS}}
    (here / "demo.kiln.json").write_text(json.dumps(sidecar, indent=2) + "\n")


if __name__ == "__main__":
    main()
