"""convray.field: against the command line's `field`, against independent quadrature of the
kernel over a triangle, and its gradient against finite differences."""
import numpy as np
import pytest

import convray
from conftest import SOUP, cli_field

# Strang and Fix's 7-point rule on a triangle, exact for polynomials of degree 5 (the quartic
# kernel is a degree-4 polynomial in q wherever the whole triangle is inside the support).
_A, _B = 0.059715871789770, 0.470142064105115
_C, _D = 0.797426985353087, 0.101286507323456
RULE_POINTS = np.array([[1 / 3, 1 / 3, 1 / 3],
                        [_A, _B, _B], [_B, _A, _B], [_B, _B, _A],
                        [_C, _D, _D], [_D, _C, _D], [_D, _D, _C]])
RULE_WEIGHTS = np.array([0.225] + [0.132394152788506] * 3 + [0.125939180544827] * 3)


def subtriangles(a, b, c, n):
    """The triangle abc cut into n^2 equal triangles: (k, 3, 3) corners."""
    out = []
    node = lambda i, j: a + (b - a) * (i / n) + (c - a) * (j / n)
    for i in range(n):
        for j in range(n - i):
            out.append([node(i, j), node(i + 1, j), node(i, j + 1)])
            if i + j < n - 1:
                out.append([node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)])
    return np.array(out)


def quadrature(p, triangle, kernel, n):
    """The integral over `triangle` of kernel(|p - q|^2), by the 7-point rule on n^2 pieces."""
    pieces = subtriangles(*triangle, n)
    areas = 0.5 * np.linalg.norm(np.cross(pieces[:, 1] - pieces[:, 0],
                                          pieces[:, 2] - pieces[:, 0]), axis=1)
    q = np.einsum("rk,tkd->trd", RULE_POINTS, pieces)  # (pieces, rule points, 3)
    r2 = np.sum((q - p) ** 2, axis=2)
    return float(np.sum(areas[:, None] * RULE_WEIGHTS[None, :] * kernel(r2)))


def quartic(radius):
    return lambda r2: np.maximum(1.0 - r2 / radius**2, 0.0) ** 2


TRIANGLE = np.array([[0.0, 0.0, 0.0], [1.0, 0.1, 0.0], [0.2, 0.9, 0.3]])


def test_field_inside_support_matches_exact_quadrature():
    # Every point of the triangle within R of p: the kernel is a polynomial there, and the
    # degree-5 rule integrates it exactly, so only rounding separates the two.
    radius = 2.5
    points = np.array([[0.3, 0.3, 0.1], [0.4, 0.2, -0.5], [0.0, 0.5, 0.6]])
    values, _ = convray.field(TRIANGLE, [[0, 1, 2]], points, radius)
    for p, v in zip(points, values):
        assert np.max(np.linalg.norm(TRIANGLE - p, axis=1)) < radius
        assert v == pytest.approx(quadrature(p, TRIANGLE, quartic(radius), 4), rel=1e-12)


def test_field_where_the_support_cuts_the_triangle_matches_fine_quadrature():
    # The support's sphere crosses the triangle: the kernel has a kink there, so quadrature
    # converges only as h^2; 120^2 pieces bring it within 1e-5.
    radius = 0.6
    points = np.array([[0.2, 0.2, 0.1], [0.8, 0.3, 0.2], [0.5, 0.5, -0.3]])
    values, _ = convray.field(TRIANGLE, [[0, 1, 2]], points, radius, strength=1.5)
    for p, v in zip(points, values):
        reference = 1.5 * quadrature(p, TRIANGLE, quartic(radius), 120)
        assert v == pytest.approx(reference, rel=1e-5)


def test_cauchy_field_matches_quadrature():
    s = 2.0
    point = np.array([[0.3, 0.4, 0.2]])  # inside the triangle's box grown by R: not truncated
    values, _ = convray.field(TRIANGLE, [[0, 1, 2]], point, 1.0, kernel="cauchy", sharpness=s)
    reference = quadrature(point[0], TRIANGLE, lambda r2: 1.0 / (1.0 + s * s * r2) ** 2, 60)
    assert values[0] == pytest.approx(reference, rel=1e-6)


def test_gradient_matches_finite_differences():
    radius = 0.6
    points = np.array([[0.2, 0.2, 0.1], [0.8, 0.3, 0.2], [0.5, 0.5, -0.3], [0.1, 0.7, 0.25]])
    _, gradients = convray.field(TRIANGLE, [[0, 1, 2]], points, radius)
    h = 1e-6
    for k in range(3):
        step = np.zeros(3)
        step[k] = h
        plus, _ = convray.field(TRIANGLE, [[0, 1, 2]], points + step, radius)
        minus, _ = convray.field(TRIANGLE, [[0, 1, 2]], points - step, radius)
        np.testing.assert_allclose(gradients[:, k], (plus - minus) / (2 * h), rtol=1e-6,
                                   atol=1e-9)


def test_field_of_a_soup_equals_the_command_line(soup):
    V, F = soup
    rng = np.random.default_rng(7)
    points = rng.uniform(V.min(axis=0) - 0.3, V.max(axis=0) + 0.3, size=(300, 3))
    values, gradients = convray.field(V, F, points, 0.25, strength=1.3)
    cli_values, cli_gradients = cli_field(SOUP, 0.25, points, strength=1.3)
    # The same evaluator on the same triangles; the program prints 17 significant digits.
    np.testing.assert_array_equal(values, cli_values)
    np.testing.assert_array_equal(gradients, cli_gradients)
    assert values.shape == (300,) and gradients.shape == (300, 3)
    assert values.dtype == np.float64 and gradients.dtype == np.float64
    assert np.count_nonzero(values) > 50


def test_strength_scales_the_field(soup):
    V, F = soup
    points = np.array([[1.0, 0.0, 0.0], [0.0, 0.95, 0.2]])
    one, g1 = convray.field(V, F, points, 0.25)
    two, g2 = convray.field(V, F, points, 0.25, strength=2.0)
    np.testing.assert_allclose(two, 2 * one, rtol=1e-15)
    np.testing.assert_allclose(g2, 2 * g1, rtol=1e-15)


def test_no_points_and_no_triangles():
    values, gradients = convray.field(TRIANGLE, [[0, 1, 2]], np.zeros((0, 3)), 1.0)
    assert values.shape == (0,) and gradients.shape == (0, 3)
    values, gradients = convray.field(TRIANGLE, np.zeros((0, 3), dtype=np.int64),
                                      [[0.0, 0.0, 0.0]], 1.0)
    assert values.tolist() == [0.0] and gradients.tolist() == [[0.0, 0.0, 0.0]]
