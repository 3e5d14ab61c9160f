"""Calls from several Python threads at once give what one thread gets alone."""
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import convray


def test_field_from_many_threads(soup):
    V, F = soup
    rng = np.random.default_rng(5)
    batches = [rng.uniform(-1.3, 1.3, size=(2000, 3)) for _ in range(8)]
    alone = [convray.field(V, F, b, 0.25) for b in batches]
    obj = convray.ConvolutionObject().add_mesh(V, F, 0.25)
    obj_alone = [obj.field(b) for b in batches]

    def work(i):
        return convray.field(V, F, batches[i], 0.25), obj.field(batches[i])

    with ThreadPoolExecutor(max_workers=8) as pool:
        together = list(pool.map(work, range(8)))
    for i, (direct, through_object) in enumerate(together):
        np.testing.assert_array_equal(direct[0], alone[i][0])
        np.testing.assert_array_equal(direct[1], alone[i][1])
        np.testing.assert_array_equal(through_object[0], obj_alone[i][0])
        np.testing.assert_array_equal(through_object[1], obj_alone[i][1])


def test_object_changed_while_queried(soup):
    V, F = soup
    obj = convray.ConvolutionObject().add_mesh(V, F, 0.25)
    points = np.zeros((500, 3))

    def query(_):
        return obj.field(points)[0].copy()

    def grow(i):
        obj.add_point([3.0 + i, 0, 0], 0.5)
        return None

    with ThreadPoolExecutor(max_workers=6) as pool:
        results = list(pool.map(lambda i: query(i) if i % 2 else grow(i), range(12)))
    # Points far from the origin do not change the field there.
    for r in results:
        if r is not None:
            np.testing.assert_array_equal(r, obj.field(points)[0])
