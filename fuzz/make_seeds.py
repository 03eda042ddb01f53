#!/usr/bin/env python3
"""Writes the hand-made seed inputs of the glTF loader fuzzer into fuzz/seeds/.

Each seed is a small valid skinned character exercising one group of features, so that mutations
start close to every path of the loader: LINEAR/STEP/CUBICSPLINE channels, sparse accessors, byte and
short joints and weights, a second influence set, strips and fans, missing normals and indices,
node matrices, nodes above the skeleton, materials and an embedded PNG texture, and GLB.
Run it again after changing it; the seeds are committed.
"""
import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def png_2x2():
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    rows = b"".join(b"\x00" + bytes(px) for px in ([255, 0, 0, 255, 0, 255, 0, 255], [0, 0, 255, 255, 255, 255, 255, 255]))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


class Builder:
    def __init__(self):
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0"}, "bufferViews": [], "accessors": []}

    def view(self, data):
        while len(self.bin) % 4:
            self.bin.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)})
        self.bin += data
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, fmt, values, component, kind, normalized=False, minmax=False):
        data = struct.pack("<" + fmt * len(values), *values)
        size = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}[kind]
        acc = {"bufferView": self.view(data), "componentType": component, "count": len(values) // size, "type": kind}
        if normalized:
            acc["normalized"] = True
        if minmax:
            acc["min"] = [min(values[i::size]) for i in range(size)]
            acc["max"] = [max(values[i::size]) for i in range(size)]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def floats(self, values, kind, **kw):
        return self.accessor("f", values, 5126, kind, **kw)

    def gltf(self):
        doc = dict(self.doc)
        doc["buffers"] = [{"byteLength": len(self.bin),
                           "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.bin)).decode()}]
        return json.dumps(doc, indent=1).encode()

    def glb(self):
        doc = dict(self.doc)
        doc["buffers"] = [{"byteLength": len(self.bin)}]
        text = json.dumps(doc).encode()
        text += b" " * (-len(text) % 4)
        binary = bytes(self.bin) + b"\0" * (-len(self.bin) % 4)
        body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(binary), 0x004E4942) + binary
        return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


def quat_z(degrees):
    h = math.radians(degrees) / 2
    return [0.0, 0.0, math.sin(h), math.cos(h)]


def strip_character(b, mode=4, indexed=True, normals=True, byte_joints=False, second_set=False):
    """A 1 x 2 m strip of three rows bound to a root joint and a tip joint 1 m above it."""
    positions = [x for y in (0, 1, 2) for x in (-0.5, y, 0, 0.5, y, 0)]
    attributes = {"POSITION": b.floats(positions, "VEC3", minmax=True)}
    if normals:
        attributes["NORMAL"] = b.floats([0, 0, 1] * 6, "VEC3")
    attributes["TEXCOORD_0"] = b.floats([0, 0, 1, 0, 0, 0.5, 1, 0.5, 0, 1, 1, 1], "VEC2")
    joints = [0, 0, 0, 0] * 2 + [0, 1, 0, 0] * 2 + [1, 0, 0, 0] * 2
    weights = [1, 0, 0, 0] * 2 + [0.5, 0.5, 0, 0] * 2 + [1, 0, 0, 0] * 2
    if byte_joints:
        attributes["JOINTS_0"] = b.accessor("B", joints, 5121, "VEC4")
        attributes["WEIGHTS_0"] = b.accessor("B", [round(w * 255) for w in weights], 5121, "VEC4", normalized=True)
    else:
        attributes["JOINTS_0"] = b.accessor("H", joints, 5123, "VEC4")
        attributes["WEIGHTS_0"] = b.floats(weights, "VEC4")
    if second_set:
        attributes["JOINTS_1"] = b.accessor("H", [1, 0, 0, 0] * 6, 5123, "VEC4")
        attributes["WEIGHTS_1"] = b.accessor("H", [6553, 0, 0, 0] * 6, 5123, "VEC4", normalized=True)
    primitive = {"attributes": attributes, "material": 0, "mode": mode}
    if indexed:
        if mode == 4:
            indices = [0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4]
        else:
            indices = [0, 1, 2, 3, 4, 5] if mode == 5 else [0, 1, 3, 5, 4, 2]
        primitive["indices"] = b.accessor("H", indices, 5123, "SCALAR")
    b.doc["meshes"] = [{"primitives": [primitive]}]
    b.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.2, 0.1, 1.0]}}]
    ibm = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1] + [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1]
    b.doc["skins"] = [{"joints": [1, 2], "inverseBindMatrices": b.floats(ibm, "MAT4")}]
    b.doc["nodes"] = [
        {"name": "world", "children": [1, 3], "translation": [2, 0, 0], "rotation": quat_z(0)},
        {"name": "root", "children": [2]},
        {"name": "tip", "translation": [0, 1, 0]},
        {"name": "body", "mesh": 0, "skin": 0, "translation": [5, 5, 5]},
    ]
    b.doc["scenes"] = [{"nodes": [0]}]
    b.doc["scene"] = 0


def animation(b, interpolation, path="rotation", node=2):
    times = b.floats([0, 0.5, 1], "SCALAR", minmax=True)
    if path == "rotation":
        keys = [quat_z(0), quat_z(45), quat_z(90)]
    else:
        keys = [[0, 1, 0], [0, 1.5, 0], [0, 1, 0]] if path == "translation" else [[1, 1, 1], [2, 2, 2], [1, 1, 1]]
    if interpolation == "CUBICSPLINE":
        zero = [0.0] * len(keys[0])
        keys = [k for key in keys for k in (zero, key, zero)]
    values = b.floats([v for key in keys for v in key], "VEC4" if path == "rotation" else "VEC3")
    return {"samplers": [{"input": times, "output": values, "interpolation": interpolation}],
            "channels": [{"sampler": 0, "target": {"node": node, "path": path}}]}


def main():
    out = os.path.join(HERE, "seeds")
    os.makedirs(out, exist_ok=True)

    b = Builder()
    strip_character(b)
    b.doc["animations"] = [dict(animation(b, "LINEAR"), name="bend"), animation(b, "STEP", "translation", 1),
                           dict(animation(b, "CUBICSPLINE", "scale"), name="pulse")]
    b.doc["images"] = [{"bufferView": b.view(png_2x2()), "mimeType": "image/png"}]
    b.doc["textures"] = [{"source": 0}]
    b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    open(os.path.join(out, "strip-textured.gltf"), "wb").write(b.gltf())
    open(os.path.join(out, "strip-textured.glb"), "wb").write(b.glb())

    b = Builder()
    strip_character(b, mode=5, byte_joints=True, second_set=True, normals=False)
    b.doc["nodes"][0] = {"name": "world", "children": [1, 3],
                         "matrix": [1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1]}
    b.doc["animations"] = [animation(b, "LINEAR", "rotation", 1)]
    open(os.path.join(out, "strip-bytes-two-sets.gltf"), "wb").write(b.gltf())

    b = Builder()
    strip_character(b, mode=6, indexed=True)
    # A sparse accessor: moves vertex 4 of a copy of the positions.
    acc = dict(b.doc["accessors"][b.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"]])
    acc["sparse"] = {"count": 1, "indices": {"bufferView": b.view(struct.pack("<H", 4) + b"\0\0"), "componentType": 5123},
                     "values": {"bufferView": b.view(struct.pack("<3f", -0.6, 2.1, 0))}}
    b.doc["accessors"].append(acc)
    b.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = len(b.doc["accessors"]) - 1
    open(os.path.join(out, "fan-sparse.gltf"), "wb").write(b.gltf())

    b = Builder()
    strip_character(b, indexed=False)
    del b.doc["skins"][0]["inverseBindMatrices"]
    open(os.path.join(out, "unindexed-no-ibm.glb"), "wb").write(b.glb())


if __name__ == "__main__":
    main()
