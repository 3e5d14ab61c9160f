#!/usr/bin/env python3
"""Writes the point cloud of bench/point_cloud_blob.sh and POV-Ray's blob of the same spheres.

    python3 bench/point_cloud_blob.py dragon_vrip.ply.gz POINTS RADIUS THRESHOLD OUT_DIR

POV-Ray refuses a blob of 1,000,000 components or more ("more than the maximum supported
components in a blob"), so bench/point_cloud_blob.sh asks for 999,999 points.

Samples POINTS points uniformly over the surface of the full Stanford dragon (ASCII PLY, as the
npm package ships it; triangles chosen by area, then a uniform point of the triangle, seeded so
every run makes the same cloud), fitted into the box (-200,-200,-200)-(200,200,200) as
`convray quick --fit-box 400` fits a mesh. Writes OUT_DIR/cloud.ply (binary little-endian,
float32 x y z, vertices only: a point cloud) and OUT_DIR/cloud.pov: a POV-Ray 3.7 blob with
one `sphere { <x, y, z>, RADIUS, 1 }` per point, threshold THRESHOLD, the coordinates printed
with 9 significant digits (exactly the float32 values of the PLY), and the camera, light and
finish of bench/vertex_blob.cpp, with which `convray quick` renders the PLY.
"""
import bisect
import gzip
import os
import random
import struct
import sys


def read_dragon(path):
    with gzip.open(path, "rt") as f:
        counts = {}
        while True:
            words = f.readline().split()
            if words[:1] == ["element"]:
                counts[words[1]] = int(words[2])
            if words == ["end_header"]:
                break
        vertices = [tuple(map(float, f.readline().split()[:3])) for _ in range(counts["vertex"])]
        faces = [tuple(int(w) for w in f.readline().split()[1:4]) for _ in range(counts["face"])]
    return vertices, faces


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def area(a, b, c):
    u, v = sub(b, a), sub(c, a)
    x, y, z = u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]
    return 0.5 * (x * x + y * y + z * z) ** 0.5


def main():
    source, count, radius, threshold, out = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
    vertices, faces = read_dragon(source)
    lo = [min(v[k] for v in vertices) for k in range(3)]
    hi = [max(v[k] for v in vertices) for k in range(3)]
    scale = 400.0 / max(hi[k] - lo[k] for k in range(3))
    centre = [(lo[k] + hi[k]) / 2 for k in range(3)]
    cumulative, total = [], 0.0
    for f in faces:
        total += area(*(vertices[i] for i in f))
        cumulative.append(total)
    rng = random.Random(23)
    points = []
    for _ in range(count):
        a, b, c = (vertices[i] for i in faces[min(bisect.bisect(cumulative, rng.random() * total), len(faces) - 1)])
        r1, r2 = rng.random(), rng.random()
        if r1 + r2 > 1.0:
            r1, r2 = 1.0 - r1, 1.0 - r2
        p = [a[k] + r1 * (b[k] - a[k]) + r2 * (c[k] - a[k]) for k in range(3)]
        points.append(struct.unpack("<3f", struct.pack("<3f", *((p[k] - centre[k]) * scale for k in range(3)))))
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "cloud.ply"), "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\ncomment %d points on the dragon's surface\n"
                 "element vertex %d\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
                 % (count, count)).encode())
        f.write(b"".join(struct.pack("<3f", *p) for p in points))
    with open(os.path.join(out, "cloud.pov"), "w") as f:
        f.write("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
                "background { color rgb <0.015, 0.018, 0.025> }\n"
                "camera {\n  perspective\n  right x*800/600\n  up y\n  sky y\n  angle 42\n"
                "  location <-300, 200, -600>\n  look_at <0, 0, 0>\n}\n"
                "light_source { <-300, 500, -500> color rgb 1 }\n"
                "blob {\n  threshold %s\n" % threshold)
        f.write("".join("  sphere { <%.9g, %.9g, %.9g>, %s, 1 }\n" % (p[0], p[1], p[2], radius) for p in points))
        f.write("  pigment { color rgb <0.80, 0.60, 0.42> }\n"
                "  finish { ambient 0.08 diffuse 0.85 phong 0.30 phong_size 40 }\n}\n")


if __name__ == "__main__":
    main()
