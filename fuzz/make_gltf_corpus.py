#!/usr/bin/env python3
"""Writes the seed corpus for fuzz_gltf into fuzz/corpus/gltf/: small valid
models covering the loader's features, and invalid ones near its checks.
Inputs the fuzzer found (crash-*, timeout-*, oom-*) live in the same folder
and are kept by this script. tests/cpu/test_gltf_loader_errors.cpp loads them
all. Standard library only:

    python3 fuzz/make_gltf_corpus.py
"""

import base64
import json
import pathlib
import struct

OUT = pathlib.Path(__file__).resolve().parent / "corpus" / "gltf"


def tri_bin():
    """Positions of one triangle, then u16 indices: the layout of the
    fuzzer's buffer.bin (which is padded to 64 bytes)."""
    return struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<3H", 0, 1, 2) + b"\0\0"


def tri_doc(buffer):
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "translation": [1, 2, 3]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [buffer],
        "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
            {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
        ],
    }


def data_uri(data):
    return "data:application/octet-stream;base64," + base64.b64encode(data).decode("ascii")


def text(doc):
    return json.dumps(doc, separators=(",", ":")).encode("utf-8")


def glb(doc, data):
    j = text(doc)
    j += b" " * (-len(j) % 4)
    data += b"\0" * (-len(data) % 4)
    chunks = struct.pack("<I4s", len(j), b"JSON") + j
    if data:
        chunks += struct.pack("<I4s", len(data), b"BIN\0") + data
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def seeds():
    data = tri_bin()
    # The same 64 bytes as the fuzzer's buffer.bin, so that the CPU tests can
    # load valid_external.gltf from this folder too.
    yield "buffer.bin", data + b"\0" * (64 - len(data))
    yield "valid_triangle.gltf", text(tri_doc({"byteLength": len(data), "uri": data_uri(data)}))
    yield "valid_triangle.glb", glb(tri_doc({"byteLength": len(data)}), data)
    yield "valid_external.gltf", text(tri_doc({"byteLength": 64, "uri": "buffer.bin"}))

    # Interleaved position + normal, u8 colours, a material, a matrix node
    # with a child, a triangle strip, and a sparse substitution.
    body = b"".join(struct.pack("<6f", x, y, 0, 0, 0, 1) for x, y in ((0, 0), (1, 0), (0, 1), (1, 1)))
    colors = bytes([200, 100, 50, 255] * 4)
    sparse = struct.pack("<B3x3f", 3, 2, 2, 0)
    data = body + colors + sparse
    doc = {
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"matrix": [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 5, 0, 0, 1], "children": [1]},
                  {"mesh": 0, "rotation": [0, 0.7071068, 0, 0.7071068], "scale": [1, -1, 1]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 1, 1]}}],
        "meshes": [{"primitives": [
            {"attributes": {"POSITION": 0, "NORMAL": 1, "COLOR_0": 2}, "mode": 5, "material": 0},
            {"attributes": {"POSITION": 0}, "mode": 1}]}],
        "buffers": [{"byteLength": len(data)}],
        "bufferViews": [{"buffer": 0, "byteLength": 96, "byteStride": 24},
                        {"buffer": 0, "byteOffset": 96, "byteLength": 16},
                        {"buffer": 0, "byteOffset": 112, "byteLength": 1},
                        {"buffer": 0, "byteOffset": 116, "byteLength": 12}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "sparse": {"count": 1, "indices": {"bufferView": 2, "componentType": 5121},
                        "values": {"bufferView": 3}}},
            {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 1, "componentType": 5121, "normalized": True, "count": 4, "type": "VEC4"},
        ],
    }
    yield "valid_features.glb", glb(doc, data)

    # Fan without a scene, u8 indices, float colours.
    data = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0) + bytes([0, 1, 2, 3]) + struct.pack("<12f", *[0.5] * 12)
    doc = {
        "asset": {"version": "2.0"},
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 2}, "indices": 1, "mode": 6}]}],
        "buffers": [{"byteLength": len(data), "uri": data_uri(data)}],
        "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 4},
                        {"buffer": 0, "byteOffset": 52, "byteLength": 48}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 1, "componentType": 5121, "count": 4, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC3"},
        ],
    }
    yield "valid_fan.gltf", text(doc)

    # Invalid, each one step from valid.
    data = tri_bin()
    bad = tri_doc({"byteLength": len(data), "uri": data_uri(data)})
    bad["accessors"][0]["count"] = 300
    yield "invalid_past_end.gltf", text(bad)
    bad = tri_doc({"byteLength": len(data), "uri": data_uri(data)})
    bad["nodes"] = [{"mesh": 0, "children": [1]}, {"children": [0]}]
    yield "invalid_cycle.gltf", text(bad)
    whole = glb(tri_doc({"byteLength": len(data)}), data)
    yield "invalid_truncated.glb", whole[: len(whole) - 20]
    broken = bytearray(data)
    broken[40] = 9
    yield "invalid_index.glb", glb(tri_doc({"byteLength": len(data)}), bytes(broken))


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    for name, content in seeds():
        (OUT / name).write_bytes(content)
        print("%s: %d bytes" % (name, len(content)))


if __name__ == "__main__":
    main()
