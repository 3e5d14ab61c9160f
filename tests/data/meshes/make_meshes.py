#!/usr/bin/env python3
"""Writes the mesh test corpus of this folder: one small file per variant of the formats that
users' files come in (issue 23), each made by hand here, none taken from another project.
tests/mesh/mesh_corpus_test.cpp reads every file and checks its triangle, segment and point
counts against the counts written in README.md, worked out by hand from what this script
writes (not from what convray reads).

    python3 tests/data/meshes/make_meshes.py      # rewrites the files in place

The files are committed; run this only to change them (and README.md with them).
"""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, data):
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)


# A cube: 8 corners, 6 quads (12 triangles), counted from 0.
CUBE_V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_Q = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
# A unit square grid of 2 rows by 4 columns of vertices: 0-3 at y = 0, 4-7 at y = 1.
GRID_V = [(x, y, 0) for y in (0, 1) for x in range(4)]


def ply_header(fmt, elements):
    lines = ["ply", "format %s 1.0" % fmt]
    for name, count, props in elements:
        lines.append("element %s %d" % (name, count))
        lines += ["property " + p for p in props]
    lines.append("end_header")
    return "\n".join(lines) + "\n"


XYZ = ["float x", "float y", "float z"]
FACE = ["list uchar int vertex_indices"]


def ply_files():
    # Plain ASCII cube of quads.
    body = "".join("%g %g %g\n" % v for v in CUBE_V) + "".join("4 %d %d %d %d\n" % q for q in CUBE_Q)
    write("ply_ascii_cube.ply", ply_header("ascii", [("vertex", 8, XYZ), ("face", 6, FACE)]) + body)

    # CR LF line ends throughout.
    write("ply_ascii_crlf.ply", (ply_header("ascii", [("vertex", 8, XYZ), ("face", 6, FACE)]) + body)
          .replace("\n", "\r\n"))

    # The face element declared (and stored) before the vertex element.
    header = ply_header("ascii", [("face", 6, FACE), ("vertex", 8, XYZ)])
    write("ply_face_before_vertex.ply", header + "".join("4 %d %d %d %d\n" % q for q in CUBE_Q) +
          "".join("%g %g %g\n" % v for v in CUBE_V))

    # Header lines without a keyword the format defines: obj_info, a blank line, a writer's own.
    header = ("ply\nformat ascii 1.0\ncomment made by hand\nobj_info num_cols 4\nobj_info num_rows 2\n\n"
              "TextureFile grid.png\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 3\nproperty list uchar int vertex_indices\nend_header\n")
    write("ply_header_extra_lines.ply", header + "".join("%g %g %g\n" % v for v in GRID_V) +
          "4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n")

    # Triangle strips (MeshLab, Cyberware scans): one strip of 4 triangles, a -1 restart, a strip of
    # 2; then a strip whose two triangles repeat a vertex (stitching, not faces). 6 triangles.
    strips = [[4, 0, 5, 1, 6, 2, -1, 6, 2, 7, 3], [0, 1, 1, 5]]
    header = ply_header("ascii", [("vertex", 8, XYZ), ("tristrips", 2, ["list int int vertex_indices"])])
    write("ply_tristrips.ply", header + "".join("%g %g %g\n" % v for v in GRID_V) +
          "".join("%d %s\n" % (len(s), " ".join(map(str, s))) for s in strips))
    # The same strips, binary big-endian.
    header = ply_header("binary_big_endian", [("vertex", 8, XYZ), ("tristrips", 2, ["list int int vertex_indices"])])
    data = b"".join(struct.pack(">3f", *v) for v in GRID_V)
    data += b"".join(struct.pack(">i%di" % len(s), len(s), *s) for s in strips)
    write("ply_tristrips_binary.ply", header.encode() + data)

    # A range scanner's camera element before the vertices, binary little-endian; a confidence
    # per vertex. The cube.
    camera = ["float view_px", "float view_py", "float view_pz", "float x_axisx", "int viewport_w"]
    header = ply_header("binary_little_endian",
                        [("camera", 1, camera), ("vertex", 8, XYZ + ["float confidence"]), ("face", 6, FACE)])
    data = struct.pack("<4fi", 0.5, 0.5, 3.0, 1.0, 640)
    data += b"".join(struct.pack("<4f", x, y, z, 0.75) for x, y, z in CUBE_V)
    data += b"".join(struct.pack("<B4i", 4, *q) for q in CUBE_Q)
    write("ply_camera_first.ply", header.encode() + data)

    # A binary body whose first byte is 0x0a (a line feed): x of vertex 0 is the float with bits
    # 0x3f80000a, whose little-endian first byte is 0x0a. One triangle.
    tri = [(struct.unpack("<f", struct.pack("<I", 0x3F80000A))[0], 0, 0), (2, 0, 0), (0, 1, 0)]
    header = ply_header("binary_little_endian", [("vertex", 3, XYZ), ("face", 1, FACE)])
    data = b"".join(struct.pack("<3f", *v) for v in tri) + struct.pack("<B3i", 3, 0, 1, 2)
    assert data[0] == 0x0A
    write("ply_binary_starts_with_newline.ply", header.encode() + data)

    # Every scalar type, in both spellings, and lists of several types, in every encoding. The x,
    # y, z are of three different types; faces use `vertex_index` with a ushort count and uint
    # items. The cube.
    props = ["char a", "uchar b", "short c", "ushort d", "int e", "uint f", "int16 x", "float64 y", "uint8 z",
             "float32 g", "int8 h", "uint16 i", "int32 j", "uint32 k", "list uint8 float32 normal_list"]
    fprops = ["uchar flags", "list ushort uint vertex_index", "list int8 int16 extra"]
    fmt = "bBhHiIhdBfbHiI"
    values = lambda v: (-1, 200, -300, 60000, -70000, 4000000000, v[0], float(v[1]), v[2], 0.5, -2, 3, 4, 5)
    for enc, bo in (("binary_big_endian", ">"), ("binary_little_endian", "<")):
        header = ply_header(enc, [("vertex", 8, props), ("face", 6, fprops)])
        data = b"".join(struct.pack(bo + fmt + "B3f", *values(v), 3, 0.0, 0.0, 1.0) for v in CUBE_V)
        data += b"".join(struct.pack(bo + "BH4I b2h", 9, 4, *q, 2, -1, 1) for q in CUBE_Q)
        write("ply_all_types_%s.ply" % ("be" if bo == ">" else "le"), header.encode() + data)
    header = ply_header("ascii", [("vertex", 8, props), ("face", 6, fprops)])
    body = "".join(" ".join(str(x) for x in values(v)) + " 3 0 0 1\n" for v in CUBE_V)
    body += "".join("9 4 %d %d %d %d 2 -1 1\n" % q for q in CUBE_Q)
    write("ply_all_types_ascii.ply", header + body)

    # Vertices only: a point cloud of 5 points, with normals.
    header = ply_header("ascii", [("vertex", 5, XYZ + ["float nx", "float ny", "float nz"])])
    write("ply_points.ply", header + "".join("%d 0 %d 0 0 1\n" % (k, k * k) for k in range(5)))
    # A face element with no faces: a point cloud too.
    header = ply_header("binary_little_endian", [("vertex", 4, XYZ), ("face", 0, FACE)])
    write("ply_points_empty_face.ply", header.encode() + b"".join(struct.pack("<3f", k, 1, 2) for k in range(4)))

    # Edges: the 12 edges of the cube, a segment skeleton.
    edges = sorted({tuple(sorted((q[k], q[(k + 1) % 4]))) for q in CUBE_Q for k in range(4)})
    assert len(edges) == 12
    header = ply_header("ascii", [("vertex", 8, XYZ), ("edge", 12, ["int vertex1", "int vertex2", "uchar red"])])
    write("ply_edges.ply", header + "".join("%g %g %g\n" % v for v in CUBE_V) +
          "".join("%d %d 255\n" % e for e in edges))
    # Faces and edges together: the bottom quad (2 triangles) and the 4 vertical edges.
    header = ply_header("ascii", [("vertex", 8, XYZ), ("face", 1, FACE), ("edge", 4, ["int vertex1", "int vertex2"])])
    write("ply_faces_and_edges.ply", header + "".join("%g %g %g\n" % v for v in CUBE_V) + "4 0 3 2 1\n" +
          "".join("%d %d\n" % (k, k + 4) for k in range(4)))

    # Broken: the header declares normals the data does not have (vertex 0, line 13).
    header = ply_header("ascii", [("vertex", 3, XYZ + ["float nx", "float ny", "float nz"]), ("face", 1, FACE)])
    write("broken_ply_header_mismatch.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    # Broken: binary, cut in the middle of the faces.
    header = ply_header("binary_little_endian", [("vertex", 8, XYZ), ("face", 6, FACE)])
    data = b"".join(struct.pack("<3f", *v) for v in CUBE_V) + b"".join(struct.pack("<B4i", 4, *q) for q in CUBE_Q)
    write("broken_ply_truncated.ply", header.encode() + data[:-10])
    # Broken: a face refers to vertex 8 of 8 (line 13).
    write("broken_ply_index.ply", ply_header("ascii", [("vertex", 3, XYZ), ("face", 1, FACE)]) +
          "0 0 0\n1 0 0\n0 1 0\n3 0 1 8\n")
    # Broken: no end_header.
    write("broken_ply_no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n")


def obj_files():
    cube = "".join("v %g %g %g\n" % v for v in CUBE_V)
    # Backslash continuations, in a vertex and in faces.
    write("obj_continuation.obj", "# continued lines\n" + cube.replace("v 1 1 1\n", "v 1 \\\n1 \\\n 1\n") +
          "f 1 4 \\\n3 2\nf 5 6 7 8\nf 1 2 \\\n  6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n")
    # A convex polygon of 300 corners on a circle: 298 triangles.
    n = 300
    ring = "".join("v %.17g %.17g 0\n" % (math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)) for k in range(n))
    write("obj_polygon_300.obj", ring + "f " + " ".join(str(k + 1) for k in range(n)) + "\n")
    # Every corner form: v, v/vt, v//vn, v/vt/vn, and v/, v//, v/vt/ (empty attribute).
    write("obj_corner_forms.obj", cube + "vt 0 0\nvt 1 0\nvn 0 0 1\n"
          "f 1 4 3 2\nf 5/1 6/2 7/1 8/2\nf 1//1 2//1 6//1 5//1\nf 2/1/1 3/2/1 7/1/1 6/2/1\n"
          "f 3/ 4/ 8/ 7/\nf 4// 1// 5// 8//\nf 1/1/ 2/2/ 3/1/\n")
    # Two coordinates per vertex (z = 0): a square of 2 triangles.
    write("obj_2d.obj", "v 0 0\nv 1 0\nv 1 1\nv 0 1\nf 1 2 3 4\n")
    # Four coordinates (w, ignored) and colours after them: one triangle.
    write("obj_4d.obj", "v 0 0 0 2\nv 2 0 0 0.5 1 0 0\nv 0 2 0 1\nf 1 2 3\n")
    # Negative (relative) indices, and a face before the vertices it names.
    write("obj_negative_and_forward.obj", "f 4 5 6\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 0 0 1\nv 1 0 1\nv 0 1 1\n")
    # UTF-16 with a byte-order mark, both byte orders; a comment with a non-ASCII letter. The cube.
    text = "# W\u00fcrfel\n" + cube + "".join("f %d %d %d %d\n" % tuple(i + 1 for i in q) for q in CUBE_Q)
    write("obj_utf16le.obj", b"\xff\xfe" + text.encode("utf-16-le"))
    write("obj_utf16be.obj", b"\xfe\xff" + text.encode("utf-16-be"))
    write("obj_utf8_bom.obj", b"\xef\xbb\xbf" + text.encode("utf-8"))
    # Vertices only: 6 points.
    write("obj_points.obj", "".join("v %d %d 0\n" % (k, k % 2) for k in range(6)))
    # `p` statements: 3 of the 5 vertices are points (the others are unused).
    write("obj_p.obj", "".join("v %d 0 0\n" % k for k in range(5)) + "p 1 3\np -1\n")
    # Polylines: one of 4 corners (3 segments), one of 2 (1 segment) with v/vt corners. 4 segments.
    write("obj_lines.obj", "".join("v %d %d 0\n" % (k, k * k) for k in range(5)) + "vt 0 0\n"
          "l 1 2 3 4\nl 4/1 5/1\n")
    # Faces, lines and points in one file: the cube (12 triangles), 2 segments, 1 point.
    write("obj_mixed.obj", cube + "v 5 5 5\n" + "".join("f %d %d %d %d\n" % tuple(i + 1 for i in q) for q in CUBE_Q) +
          "l 1 7 2\np 9\n")
    # Broken: a face of two corners, written v//.
    write("broken_obj_two_corners.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1// 2//\n")
    # Broken: a face refers to vertex 4 of 3.
    write("broken_obj_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")
    # Broken: a vertex with a single coordinate.
    write("broken_obj_vertex.obj", "v 0 0 0\nv 1\nv 0 1 0\nf 1 2 3\n")


def stl_ascii_facet(a, b, c):
    return ("  facet normal 0 0 1\n    outer loop\n" + "".join("      vertex %g %g %g\n" % p for p in (a, b, c)) +
            "    endloop\n  endfacet\n")


def stl_files():
    tris = [(CUBE_V[q[0]], CUBE_V[q[k]], CUBE_V[q[k + 1]]) for q in CUBE_Q for k in (1, 2)]
    # Three solids: the cube's first 4 triangles, an empty one, the other 8.
    text = "solid first\n" + "".join(stl_ascii_facet(*t) for t in tris[:4]) + "endsolid first\n"
    text += "solid empty\nendsolid empty\n"
    text += "solid rest\n" + "".join(stl_ascii_facet(*t) for t in tris[4:]) + "endsolid rest\n"
    write("stl_ascii_solids.stl", text)
    # Binary, its 80-byte header starting with "solid" (as many exporters write).
    head = b"solid exported by a CAD program".ljust(80, b" ")
    data = head + struct.pack("<I", len(tris))
    data += b"".join(struct.pack("<12fH", 0, 0, 1, *a, *b, *c, 0) for a, b, c in tris)
    write("stl_binary_solid_header.stl", data)
    # Broken: the binary file cut short.
    write("broken_stl_truncated.stl", data[:-25])


def off_files():
    cube = "".join("%g %g %g\n" % v for v in CUBE_V)
    quads = "".join("4 %d %d %d %d\n" % q for q in CUBE_Q)
    # A face whose indices continue on the next line, and one spread over three lines.
    write("off_face_across_lines.off", "OFF\n8 6 12\n" + cube +
          quads.replace("4 0 3 2 1\n", "4 0 3\n2 1\n").replace("4 3 0 4 7\n", "4\n3 0\n4 7\n"))
    # Counts glued to the keyword (ModelNet).
    write("off_counts_glued.off", "OFF8 6 12\n" + cube + quads)
    # nOFF with dimension 3.
    write("off_noff3.off", "nOFF\n3\n8 6 0\n" + cube + quads)
    # 4OFF: w divides; vertex 1 written (2 0 0 2) is (1 0 0).
    write("off_homogeneous.off", "4OFF\n3 1 0\n0 0 0 1\n2 0 0 2\n0 3 0 3\n3 0 1 2\n")
    # Comments, blank lines, colours on vertices and faces (COFF), counts on the keyword line.
    write("off_colours_comments.off", "# a coloured cube\nCOFF 8 6 0 # counts\n\n" +
          "".join("%g %g %g 1 0 0 1 # corner\n" % v for v in CUBE_V) +
          "".join("4 %d %d %d %d 0.5 0.5 0.5\n" % q for q in CUBE_Q))
    # A face of 12 corners (a convex polygon): 10 triangles.
    ring = "".join("%.17g %.17g 0\n" % (math.cos(2 * math.pi * k / 12), math.sin(2 * math.pi * k / 12)) for k in range(12))
    write("off_polygon_12.off", "OFF\n12 1 0\n" + ring + "12 " + " ".join(map(str, range(12))) + "\n")
    # No faces: 4 points.
    write("off_points.off", "OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n")
    # Binary OFF as pmp-library writes it: little-endian, no colour counts. The cube.
    data = b"OFF BINARY\n" + struct.pack("<3i", 8, 6, 0) + b"".join(struct.pack("<3f", *v) for v in CUBE_V)
    data += b"".join(struct.pack("<5i", 4, *q) for q in CUBE_Q)
    write("off_binary_little_endian.off", data)
    # Binary OFF: big-endian counts, vertices, faces with a colour count (the second with 4 colours).
    data = b"OFF BINARY\n" + struct.pack(">3i", 8, 6, 12) + b"".join(struct.pack(">3f", *v) for v in CUBE_V)
    for k, q in enumerate(CUBE_Q):
        colours = [0.5, 0.5, 0.5, 1.0] if k == 1 else []
        data += struct.pack(">5ii%df" % len(colours), 4, *q, len(colours), *colours)
    write("off_binary.off", data)
    # Broken: nOFF of dimension 4.
    write("broken_off_dimension.off", "nOFF\n4\n1 0 0\n0 0 0 0\n")
    # Broken: a face refers to vertex 3 of 3 (line 6).
    write("broken_off_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n")


if __name__ == "__main__":
    ply_files()
    obj_files()
    stl_files()
    off_files()
