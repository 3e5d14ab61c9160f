"""The worked example of docs/python.md: load a polygon soup, sample its convolution field on
a grid, polygonize the surface, shoot rays at it, and render it.

    python3 docs/examples/python_example.py [PICTURE.png]

(after `bash scripts/setup.sh demo`, or with PYTHONPATH=build/python). The picture goes to
out/python_example.png unless named.
"""
import struct
import sys
import zlib
from pathlib import Path

import numpy as np

import convray

ROOT = Path(__file__).resolve().parents[2]


def write_png(path, image):
    """An (H, W, 4) render as an 8-bit RGB PNG, rounded as the command line rounds it."""
    rgb = np.floor(image[..., :3].astype(np.float32) * np.float32(255) + 0.5).astype(np.uint8)
    rows = b"".join(b"\x00" + row.tobytes() for row in rgb)
    chunk = lambda kind, body: (struct.pack(">I", len(body)) + kind + body +
                                struct.pack(">I", zlib.crc32(kind + body)))
    header = struct.pack(">IIBBBBB", rgb.shape[1], rgb.shape[0], 8, 2, 0, 0, 0)
    Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                           chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


# 1. The soup: a damaged icosphere (holes, flipped and degenerate faces).
V, F = convray.load_mesh(ROOT / "scenes" / "models" / "soup.obj")
print(f"soup: {len(V)} vertices, {len(F)} triangles, "
      f"{len(convray.self_intersections(V, F))} self-intersecting face pairs")

# 2. Its convolution object: radius 0.25, the surface 0.1 off its flat parts.
soup = convray.ConvolutionObject().add_mesh(V, F, radius=0.25)
soup.threshold = soup.threshold_for_offset(0.1)
print(f"threshold T for offset 0.1: {soup.threshold:.6f}")

# 3. The field on a 200 x 200 grid in the plane z = 0.
xs = np.linspace(-1.5, 1.5, 200)
X, Y = np.meshgrid(xs, xs)
grid = np.column_stack([X.ravel(), Y.ravel(), np.zeros(X.size)])
values, gradients = soup.field(grid)
print(f"grid: {np.count_nonzero(values >= soup.threshold)} of {len(grid)} points inside F >= T, "
      f"max F/T {values.max() / soup.threshold:.3f}, "
      f"max |grad F| {np.linalg.norm(gradients, axis=1).max():.3f}")

# 4. The surface F = T as a closed mesh, and how far it stands from the soup.
SV, SF = soup.polygonize(max_error=0.02, outer=True)
edges = np.sort(np.concatenate([SF[:, [0, 1]], SF[:, [1, 2]], SF[:, [2, 0]]]), axis=1)
_, uses = np.unique(edges, axis=0, return_counts=True)
residual = np.abs(soup.field(SV)[0] - soup.threshold).max() / soup.threshold
print(f"polygonized: {len(SV)} vertices, {len(SF)} triangles, every edge in two triangles: "
      f"{bool(np.all(uses == 2))}, max |F - T|/T at the vertices {residual:.1e}")
print(f"  self-intersecting face pairs: {len(convray.self_intersections(SV, SF))}")
d = convray.distance((V, F), (SV, SF), samples=20000)
print(f"  distance soup -> surface {d['a_to_b']:.4f}, surface -> soup {d['b_to_a']:.4f}")

# 5. Rays from the -z side at the centre and one off to the side that misses.
t, normals = soup.intersect([[0, 0, -5], [0, 3, -5]], [[0, 0, 1]])
print(f"rays: t = {t[0]:.6f} (hit at z = {-5 + t[0]:.6f}, normal {np.round(normals[0], 6)}), "
      f"t = {t[1]} (a miss)")

# 6. A picture, rendered by convray from scene text: the polygonized mesh as a mesh2 on the
#    left, the same surface ray traced directly from the soup on the right.
def mesh2(V, F):
    vertices = ",\n".join("<%.9g, %.9g, %.9g>" % tuple(v) for v in V)
    faces = ",\n".join("<%d, %d, %d>" % tuple(f) for f in F)
    return (f"mesh2 {{ vertex_vectors {{ {len(V)},\n{vertices} }}\n"
            f"face_indices {{ {len(F)},\n{faces} }}")


scene = """#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -6.5> look_at <0, 0.1, 0> right x * image_width / image_height angle 45 }
light_source { <-6, 9, -7> color rgb 1 }
light_source { <7, 4, -3> color rgb 0.35 shadowless }
background { color rgb <0.78, 0.84, 0.92> }
plane { y, -1.45 pigment { checker color rgb 0.85 color rgb 0.55 scale 0.5 } }
#declare Clay = texture { pigment { color rgb <0.85, 0.55, 0.35> }
                          finish { ambient 0.1 diffuse 0.75 phong 0.6 phong_size 60 } }
""" + mesh2(SV, SF) + """
  texture { Clay } translate -1.3 * x }
convolution {
  radius 0.25  offset 0.1
  mesh { "models/soup.obj" }
  texture { Clay } translate 1.3 * x
}
"""
image = convray.render(scene, 480, 360, antialias=0.3, library=ROOT / "scenes")
print(f"render: {image.shape} {image.dtype}, mean RGB {np.round(image[..., :3].mean(axis=(0, 1)), 3)}")
out = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "out" / "python_example.png"
out.parent.mkdir(parents=True, exist_ok=True)
write_png(out, image)
print(f"wrote {out.relative_to(ROOT) if out.is_relative_to(ROOT) else out}")
