"""convray.ConvolutionObject: field, thresholds, polygonize and ray intersections, checked
against convray.field, closed forms, bisection on the field and mesh topology."""
import math
from collections import Counter

import numpy as np
import pytest

import convray
from conftest import SOUP


def test_mesh_object_field_equals_field_function(soup):
    V, F = soup
    obj = convray.ConvolutionObject().add_mesh(V, F, radius=0.25)
    rng = np.random.default_rng(3)
    points = rng.uniform(-1.3, 1.3, size=(200, 3))
    values, gradients = obj.field(points)
    ref_values, ref_gradients = convray.field(V, F, points, 0.25)
    np.testing.assert_allclose(values, ref_values, rtol=1e-10, atol=1e-13)
    np.testing.assert_allclose(gradients, ref_gradients, rtol=1e-9, atol=1e-12)


def test_add_file_equals_add_mesh(soup):
    V, F = soup
    a = convray.ConvolutionObject().add_file(SOUP, 0.25)
    b = convray.ConvolutionObject().add_mesh(V, F, 0.25)
    points = np.array([[1.0, 0.0, 0.0], [0.0, 0.95, 0.2], [0.0, 0.0, 1.15]])
    np.testing.assert_array_equal(a.field(points)[0], b.field(points)[0])


def test_point_and_segment_fields_are_the_closed_forms():
    R = 1.2
    obj = convray.ConvolutionObject().add_point([0, 0, 0], R, strength=2.0)
    p = np.array([[0.3, 0.4, 0.5]])
    r2 = float(np.sum(p**2))
    assert obj.field(p)[0][0] == pytest.approx(2.0 * (1 - r2 / R**2) ** 2, rel=1e-14)
    # A long segment, far from its ends: the infinite line's field (16/15)(R^2-d^2)^(5/2)/R^4.
    line = convray.ConvolutionObject().add_segment([-10, 0, 0], [10, 0, 0], R)
    d = 0.5
    expected = (16 / 15) * (R * R - d * d) ** 2.5 / R**4
    assert line.field([[0.0, d, 0.0]])[0][0] == pytest.approx(expected, rel=1e-13)


def test_threshold_for_offset_follows_the_command_lines_rule():
    R, d = 0.4, 0.1
    mesh = convray.ConvolutionObject().add_mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]], R)
    assert mesh.threshold_for_offset(d) == pytest.approx(
        (math.pi / 3) * (R * R - d * d) ** 3 / R**4, rel=1e-15)
    point = convray.ConvolutionObject().add_point([0, 0, 0], R, strength=3.0)
    assert point.threshold_for_offset(d) == pytest.approx(3.0 * (1 - d * d / R**2) ** 2)
    with pytest.raises(ValueError, match="offset"):
        point.threshold_for_offset(R)
    mixed = convray.ConvolutionObject().add_point([0, 0, 0], 1.0).add_point([1, 0, 0], 2.0)
    with pytest.raises(ValueError, match="one radius"):
        mixed.threshold_for_offset(0.1)


def closed_and_oriented(F):
    """Every directed edge once, and its reverse once: closed, 2-manifold, consistent."""
    directed = Counter()
    for a, b, c in F.tolist():
        for e in ((a, b), (b, c), (c, a)):
            directed[e] += 1
    return all(n == 1 and directed[(e[1], e[0])] == 1 for e, n in directed.items())


def test_polygonize_a_point_gives_a_closed_sphere_on_the_surface():
    R = 1.0
    obj = convray.ConvolutionObject().add_point([0.5, 0, 0], R)
    obj.threshold = obj.threshold_for_offset(0.5)
    V, F = obj.polygonize()
    assert V.dtype == np.float64 and F.dtype == np.int64 and F.shape[1] == 3 and len(F) > 100
    assert closed_and_oriented(F)
    values, _ = obj.field(V)
    assert np.max(np.abs(values - obj.threshold)) <= 1e-6 * obj.threshold
    np.testing.assert_allclose(np.linalg.norm(V - [0.5, 0, 0], axis=1), 0.5, rtol=1e-6)


def test_polygonize_the_soup(soup):
    V, F = soup
    obj = convray.ConvolutionObject().add_mesh(V, F, 0.25)
    obj.threshold = obj.threshold_for_offset(0.1)
    SV, SF = obj.polygonize(max_error=0.02, outer=True)
    assert closed_and_oriented(SF) and len(SF) > 500
    values, _ = obj.field(SV)
    assert np.max(np.abs(values - obj.threshold)) <= 1e-6 * obj.threshold
    assert len(convray.self_intersections(SV, SF)) == 0


def test_polygonize_an_empty_surface_gives_empty_arrays():
    obj = convray.ConvolutionObject(threshold=10.0).add_point([0, 0, 0], 1.0)
    V, F = obj.polygonize(cell=0.2)
    assert V.shape == (0, 3) and F.shape == (0, 3)


def bisect_first_crossing(obj, origin, direction, t_far, samples=2000):
    """The first t where F - T changes sign along the ray, by sampling then bisection."""
    ts = np.linspace(0.0, t_far, samples)
    f = obj.field(origin + ts[:, None] * direction)[0] - obj.threshold
    k = int(np.argmax(f >= 0))
    assert f[k] >= 0 and k > 0
    lo, hi = ts[k - 1], ts[k]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        value = obj.field((origin + mid * direction)[None, :])[0][0] - obj.threshold
        lo, hi = (lo, mid) if value >= 0 else (mid, hi)
    return 0.5 * (lo + hi)


def test_intersect_matches_bisection_and_gradients(soup):
    V, F = soup
    obj = convray.ConvolutionObject().add_mesh(V, F, 0.25)
    obj.threshold = obj.threshold_for_offset(0.1)
    rng = np.random.default_rng(11)
    targets = rng.uniform(-0.3, 0.3, size=(12, 3))
    origins = rng.normal(size=(12, 3))
    origins = 4.0 * origins / np.linalg.norm(origins, axis=1)[:, None]
    directions = 2.0 * (targets - origins)  # not unit: t is measured along them as given
    t, normals = obj.intersect(origins, directions)
    assert t.shape == (12,) and normals.shape == (12, 3)
    for i in range(12):
        assert np.isfinite(t[i])
        reference = bisect_first_crossing(obj, origins[i], directions[i], 0.5)
        assert t[i] == pytest.approx(reference, abs=1e-9)
        hit = origins[i] + t[i] * directions[i]
        _, g = obj.field(hit[None, :])
        np.testing.assert_allclose(normals[i], -g[0] / np.linalg.norm(g[0]), atol=1e-6)


def test_intersect_a_point_sphere_and_misses():
    R = 1.0
    obj = convray.ConvolutionObject().add_point([0, 0, 0], R)
    obj.threshold = obj.threshold_for_offset(0.5)
    origins = np.array([[-3.0, 0.0, 0.0], [-3.0, 0.3, 0.0], [-3.0, 2.0, 0.0]])
    t, normals = obj.intersect(origins, [[1.0, 0.0, 0.0]])  # one direction for every ray
    assert t[0] == pytest.approx(2.5, abs=1e-12)
    assert t[1] == pytest.approx(3.0 - math.sqrt(0.25 - 0.09), abs=1e-12)
    np.testing.assert_allclose(normals[0], [-1, 0, 0], atol=1e-12)
    assert t[2] == np.inf and normals[2].tolist() == [0.0, 0.0, 0.0]
    t, _ = obj.intersect(origins[:1], [[1.0, 0.0, 0.0]], tmax=2.0)
    assert t[0] == np.inf


def test_arcs_and_cauchy_objects():
    arc = convray.ConvolutionObject().add_arc([1, 0, 0], [0, 1, 0], [-1, 0, 0], 0.5)
    assert arc.field([[0.0, 1.0, 0.0]])[0][0] > 0
    cauchy = convray.ConvolutionObject(kernel="cauchy", sharpness=2.0).add_point([0, 0, 0], 1.0)
    assert cauchy.kernel == "cauchy"
    assert cauchy.field([[0.1, 0.0, 0.0]])[0][0] == pytest.approx(1 / (1 + 4 * 0.01) ** 2)
    with pytest.raises(ValueError, match="not arcs"):
        cauchy.add_arc([1, 0, 0], [0, 1, 0], [-1, 0, 0], 0.5)
    assert "points=1" in repr(cauchy)
