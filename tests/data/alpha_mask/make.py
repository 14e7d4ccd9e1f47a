#!/usr/bin/env python3
"""Writes alpha_mask.gltf, alpha_mask.bin and mask.png: the test scene of alpha-tested casters.

A 2 x 2 quad at height 1 whose base-colour texture is a 4 x 4 checker of alpha 0 and 1 (nearest
filtering, clamped), material alphaMode MASK with cutoff 0.5, over an 8 x 8 ground at height 0 whose
colour comes from COLOR_0 only. Run it again to make the files again (python3 make.py)."""
import json, struct, zlib
from pathlib import Path

here = Path(__file__).parent

def png(width, height, rgba_rows):
    raw = b"".join(b"\x00" + bytes(row) for row in rgba_rows)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))

rows = []
for y in range(4):
    row = []
    for x in range(4):
        row += [255, 255, 255, 255 if (x + y) % 2 == 0 else 0]
    rows.append(row)
(here / "mask.png").write_bytes(png(4, 4, rows))

def f32(values):
    return struct.pack("<%df" % len(values), *values)

# quad: 4 vertices (position, normal, uv), 6 indices; ground: 4 vertices (position, normal, colour), 6 indices
quad_pos = [-1, 1, -1, 1, 1, -1, 1, 1, 1, -1, 1, 1]
quad_nrm = [0, 1, 0] * 4
quad_uv = [0, 0, 1, 0, 1, 1, 0, 1]
ground_pos = [-4, 0, -4, 4, 0, -4, 4, 0, 4, -4, 0, 4]
ground_nrm = [0, 1, 0] * 4
ground_col = [0.55, 0.7, 0.9, 1.0] * 4
indices = struct.pack("<6H", 0, 2, 1, 0, 3, 2) + b"\x00\x00"  # counter-clockwise seen from above, padded

blobs = [f32(quad_pos), f32(quad_nrm), f32(quad_uv), f32(ground_pos), f32(ground_nrm), f32(ground_col), indices]
views, accessors, data = [], [], b""
kinds = [("VEC3", 4), ("VEC3", 4), ("VEC2", 4), ("VEC3", 4), ("VEC3", 4), ("VEC4", 4), ("SCALAR", 6)]
for blob, (kind, count) in zip(blobs, kinds):
    views.append({"buffer": 0, "byteOffset": len(data), "byteLength": len(blob) - (2 if kind == "SCALAR" else 0)})
    acc = {"bufferView": len(views) - 1, "componentType": 5123 if kind == "SCALAR" else 5126, "count": count, "type": kind}
    if kind == "VEC3" and len(accessors) in (0, 3):
        pts = [blob[i:i + 12] for i in range(0, len(blob), 12)]
        xyz = [struct.unpack("<3f", p) for p in pts]
        acc["min"] = [min(p[i] for p in xyz) for i in range(3)]
        acc["max"] = [max(p[i] for p in xyz) for i in range(3)]
    accessors.append(acc)
    data += blob
(here / "alpha_mask.bin").write_bytes(data)

doc = {
    "asset": {"version": "2.0", "generator": "shadowlab tests/data/alpha_mask/make.py"},
    "scene": 0,
    "scenes": [{"nodes": [0, 1]}],
    "nodes": [{"mesh": 0, "name": "cut-out quad"}, {"mesh": 1, "name": "ground"}],
    "meshes": [
        {"name": "cut-out quad", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 6, "material": 0}]},
        {"name": "ground", "primitives": [{"attributes": {"POSITION": 3, "NORMAL": 4, "COLOR_0": 5}, "indices": 6, "material": 1}]},
    ],
    "materials": [
        {"name": "checker cut-out", "doubleSided": True, "alphaMode": "MASK", "alphaCutoff": 0.5,
         "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.5, 0.2, 1.0], "baseColorTexture": {"index": 0}}},
        {"name": "vertex colour"},
    ],
    "textures": [{"source": 0, "sampler": 0}],
    "samplers": [{"magFilter": 9728, "minFilter": 9728, "wrapS": 33071, "wrapT": 33071}],
    "images": [{"uri": "mask.png"}],
    "buffers": [{"uri": "alpha_mask.bin", "byteLength": len(data)}],
    "bufferViews": views,
    "accessors": accessors,
}
(here / "alpha_mask.gltf").write_text(json.dumps(doc, indent=1) + "\n")
