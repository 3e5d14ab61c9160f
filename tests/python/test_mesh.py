"""convray.load_mesh, self_intersections and distance, against the command line's `info`
and `distance` and against answers known by construction."""
import gzip
import re

import numpy as np
import pytest

import convray
from conftest import SOUP, run_cli


def info_number(text, key):
    return int(re.search(r"^%s: (\d+)" % re.escape(key), text, re.M).group(1))


def test_load_mesh_matches_info(soup):
    V, F = soup
    code, out, _ = run_cli("info", SOUP)
    assert code == 0
    assert V.dtype == np.float64 and V.shape[1] == 3
    assert F.dtype == np.int64 and F.shape == (info_number(out, "triangles"), 3)
    assert F.min() >= 0 and F.max() < len(V)
    box_min = [float(x) for x in re.search(r"^bounding box min: (.*)$", out, re.M).group(1).split()]
    np.testing.assert_allclose(V[np.unique(F)].min(axis=0), box_min, rtol=1e-5)


def test_every_format_and_gzip(tmp_path, soup):
    V = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    off = "OFF\n4 4 0\n" + "".join("%g %g %g\n" % tuple(v) for v in V) + \
          "".join("3 %d %d %d\n" % tuple(f) for f in F)
    ply = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
           "end_header\n" + "".join("%g %g %g\n" % tuple(v) for v in V) +
           "".join("3 %d %d %d\n" % tuple(f) for f in F))
    obj = "".join("v %g %g %g\n" % tuple(v) for v in V) + \
          "".join("f %d %d %d\n" % tuple(f + 1) for f in F)
    stl = "solid t\n" + "".join(
        "facet normal 0 0 0\nouter loop\n" + "".join("vertex %g %g %g\n" % tuple(V[i]) for i in f)
        + "endloop\nendfacet\n" for f in F) + "endsolid t\n"
    for name, text in [("t.off", off), ("t.ply", ply), ("t.obj", obj), ("t.stl", stl)]:
        (tmp_path / name).write_text(text)
        with gzip.open(tmp_path / (name + ".gz"), "wt") as f:
            f.write(text)
        for path in (tmp_path / name, str(tmp_path / (name + ".gz"))):
            LV, LF = convray.load_mesh(path)
            assert LF.shape == (4, 3)
            # STL repeats corners; every format gives the same triangles' corners.
            np.testing.assert_array_equal(LV[LF], V[F])
    # The example soup, compressed, reads the same as plain.
    packed = tmp_path / "soup.obj.gz"
    packed.write_bytes(gzip.compress(SOUP.read_bytes()))
    for a, b in zip(convray.load_mesh(packed), soup):
        np.testing.assert_array_equal(a, b)


def crossing_triangles():
    V = np.array([[0.0, 0, 0], [2, 0, 0], [0, 2, 0],           # in z = 0
                  [0.5, 0.5, -1], [0.5, 0.5, 1], [1.5, 1.5, 0.5],  # pierces the first
                  [5, 5, 5], [6, 5, 5], [5, 6, 5]])              # far from both
    F = np.array([[0, 1, 2], [3, 4, 5], [6, 7, 8]])
    return V, F


def test_self_intersections_of_crossing_triangles(tmp_path):
    V, F = crossing_triangles()
    pairs = convray.self_intersections(V, F)
    assert pairs.dtype == np.int64 and pairs.tolist() == [[0, 1]]
    assert convray.self_intersections(V, F[[0, 2]]).shape == (0, 2)
    # The command line numbers faces from 1.
    path = tmp_path / "crossing.obj"
    path.write_text("".join("v %r %r %r\n" % tuple(v) for v in V.tolist()) +
                    "".join("f %d %d %d\n" % tuple(f + 1) for f in F))
    code, out, _ = run_cli("info", "--self-intersections", path)
    assert code == 0 and "self-intersecting face pairs: 1 " in out
    assert "faces 1 and 2 intersect" in out


def test_self_intersections_of_the_soup_match_info(soup):
    code, out, _ = run_cli("info", "--self-intersections", SOUP)
    assert len(convray.self_intersections(*soup)) == info_number(out, "self-intersecting face pairs")


def square(z, shift=0.0):
    V = np.array([[0.0, 0, z], [1, 0, z], [1, 1, z], [0, 1, z]]) + [shift, 0, 0]
    return V, np.array([[0, 1, 2], [0, 2, 3]])


def test_distance_between_parallel_squares():
    d = convray.distance(square(0.0), square(0.5))
    assert d["a_to_b"] == pytest.approx(0.5, abs=1e-15)
    assert d["b_to_a"] == pytest.approx(0.5, abs=1e-15)
    assert d["hausdorff"] == pytest.approx(0.5) and d["mean"] == pytest.approx(0.5)
    # Shifted sideways by 0.25 as well: the corners that overhang are sqrt(0.25^2 + 0.5^2) away.
    d = convray.distance(square(0.0), square(0.5, shift=0.25), samples=1000)
    assert d["hausdorff"] == pytest.approx(np.hypot(0.25, 0.5), rel=1e-12)


def test_distance_matches_the_command_line(tmp_path, soup):
    V, F = soup
    moved = tmp_path / "moved.obj"
    W = V + [0.01, -0.02, 0.005]
    moved.write_text("".join("v %r %r %r\n" % tuple(v) for v in W.tolist()) +
                     "".join("f %d %d %d\n" % tuple(f + 1) for f in F))
    code, out, err = run_cli("distance", SOUP, moved, "--samples", "5000")
    assert code == 0, err
    d = convray.distance(SOUP, (W, F), samples=5000)
    printed = lambda key: float(re.search(r"^%s: (\S+)" % re.escape(key), out, re.M).group(1))
    assert d["a_to_b"] == pytest.approx(printed("A -> B max"), rel=1e-5)
    assert d["b_to_a"] == pytest.approx(printed("B -> A max"), rel=1e-5)
    assert d["mean"] == pytest.approx(printed("mean"), rel=1e-5)
    assert d["diagonal"] == pytest.approx(printed("diagonal"), rel=1e-5)
