#!/usr/bin/env python3
"""Draws the README's labelled-frame figure from `swell render --labels` output.

  swell render scenes/under-way.toml -o /tmp/frame.png --size 480x270 --time 20 --labels
  python3 docs/images/labelled-frame.py /tmp/frame.png docs/images/labelled-frame.png

Four panels: the colour image with each object's box and the horizon line;
the semantic and instance labels; the range along each ray (log scale); the
surface normals. Needs NumPy only (the PNGs are read and written here).
"""
import json
import struct
import sys
import zlib

import numpy as np


def read_png(path):
    """8-bit RGB or RGBA, not interlaced: what Swell writes."""
    data = open(path, "rb").read()
    pos, chunks = 8, {}
    idat = b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    channels = {2: 3, 6: 4}[colour]
    raw = zlib.decompress(idat)
    stride = width * channels
    out = np.zeros((height, stride), np.int32)
    prev = np.zeros(stride, np.int32)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        row = np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int32)
        cur = np.zeros(stride, np.int32)
        for x in range(stride):
            a = cur[x - channels] if x >= channels else 0
            b = prev[x]
            c = prev[x - channels] if x >= channels else 0
            if kind == 0:
                p = 0
            elif kind == 1:
                p = a
            elif kind == 2:
                p = b
            elif kind == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[x] = (row[x] + p) & 255
        out[y] = cur
        prev = cur
    return out.reshape(height, width, channels)[:, :, :3].astype(np.uint8)


def write_png(path, rgb):
    height, width, _ = rgb.shape
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(height))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def draw_box(img, box, colour):
    x0, y0, x1, y1 = box
    img[y0, x0:x1] = img[y1 - 1, x0:x1] = colour
    img[y0:y1, x0] = img[y0:y1, x1 - 1] = colour


def draw_line(img, line, colour):
    a, b, c = line
    h, w, _ = img.shape
    for x in range(w):
        if abs(b) > 1e-9:
            y = int(round(-(a * (x + 0.5) + c) / b - 0.5))
            if 0 <= y < h:
                img[y, x] = colour


colour_png, out_png = sys.argv[1], sys.argv[2]
stem = colour_png[:-4]
meta = json.load(open(stem + ".json"))
colour = read_png(colour_png).copy()
labels = read_png(stem + ".labels.png").copy()
for o in meta["objects"]:
    if o["visible_pixels"]:
        draw_box(colour, o["box_px"], (255, 230, 0))
        draw_box(labels, o["box_px"], (255, 255, 255))
if meta["horizon"]["visible"]:
    draw_line(colour, meta["horizon"]["line"], (255, 60, 60))
    draw_line(labels, meta["horizon"]["line"], (255, 60, 60))
rng = np.load(stem + ".range.npy")
finite = np.isfinite(rng)
t = np.zeros_like(rng)
t[finite] = np.clip((np.log10(rng[finite]) - 0.5) / 3.5, 0.0, 1.0)  # 3 m .. 10 km
ramp = np.stack([0.1 + 0.9 * t, 0.2 + 0.6 * np.sin(np.pi * t), 0.9 - 0.8 * t], -1)
depth = np.where(finite[..., None], ramp * 255, 255).astype(np.uint8)
normal = np.load(stem + ".normal.npy")
normals = ((normal * 0.5 + 0.5) * 255 * (np.linalg.norm(normal, axis=-1, keepdims=True) > 0)).astype(np.uint8)
figure = np.concatenate([np.concatenate([colour, labels], 1), np.concatenate([depth, normals], 1)], 0)
write_png(out_png, figure)
