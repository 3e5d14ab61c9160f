"""Bad input raises a Python exception with the command line's message; nothing aborts the
interpreter."""
import numpy as np
import pytest

import convray
from conftest import run_cli

TRI_V = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])
TRI_F = np.array([[0, 1, 2]])


def test_wrong_shapes():
    with pytest.raises(ValueError, match=r"points must have shape \(n, 3\).*got \(4, 2\)"):
        convray.field(TRI_V, TRI_F, np.zeros((4, 2)), 1.0)
    with pytest.raises(ValueError, match=r"got \(3,\)"):
        convray.field(TRI_V, TRI_F, np.zeros(3), 1.0)
    with pytest.raises(ValueError, match=r"F must have shape"):
        convray.field(TRI_V, np.array([[0, 1]]), np.zeros((1, 3)), 1.0)
    obj = convray.ConvolutionObject().add_point([0, 0, 0], 1.0)
    with pytest.raises(ValueError, match="same number of rows"):
        obj.intersect(np.zeros((2, 3)), np.ones((3, 3)))
    with pytest.raises(ValueError, match="center must be three numbers"):
        obj.add_point([0, 0], 1.0)


def test_dtypes():
    # Integer and float32 arrays are converted; bool, complex and strings are not numbers here.
    ints, _ = convray.field(TRI_V.astype(np.int32), TRI_F, np.array([[0, 0, 0]]), 1.0)
    floats, _ = convray.field(TRI_V, TRI_F, np.array([[0.0, 0.0, 0.0]]), 1.0)
    assert ints.tolist() == floats.tolist()
    for bad in (np.zeros((1, 3), dtype=complex), np.zeros((1, 3), dtype=bool),
                np.array([["a", "b", "c"]])):
        with pytest.raises(TypeError, match="points must be an array of real numbers"):
            convray.field(TRI_V, TRI_F, bad, 1.0)
    with pytest.raises(TypeError, match="F must be an integer array"):
        convray.field(TRI_V, TRI_F.astype(float), np.zeros((1, 3)), 1.0)


def test_non_finite_values_and_bad_numbers():
    points = np.zeros((5, 3))
    points[3, 1] = np.nan
    with pytest.raises(ValueError, match=r"points\[3\] is not finite"):
        convray.field(TRI_V, TRI_F, points, 1.0)
    with pytest.raises(ValueError, match=r"V\[1\] is not finite"):
        convray.field(np.array([[0, 0, 0], [np.inf, 0, 0], [0, 1, 0]]), TRI_F, points[:1], 1.0)
    with pytest.raises(ValueError, match="refers to vertex 7, but there are 3 vertices"):
        convray.field(TRI_V, [[0, 1, 7]], points[:1], 1.0)
    with pytest.raises(ValueError, match="refers to vertex -1"):
        convray.self_intersections(TRI_V, [[0, 1, -1]])
    with pytest.raises(ValueError, match="radius must be > 0"):
        convray.field(TRI_V, TRI_F, points[:1], 0.0)
    with pytest.raises(ValueError, match="strength must be finite"):
        convray.field(TRI_V, TRI_F, points[:1], 1.0, strength=np.nan)
    with pytest.raises(ValueError, match="kernel must be"):
        convray.field(TRI_V, TRI_F, points[:1], 1.0, kernel="gauss")
    with pytest.raises(ValueError, match="no components"):
        convray.ConvolutionObject().field(points[:1])
    with pytest.raises(ValueError, match="threshold must be positive"):
        convray.ConvolutionObject(threshold=-1.0)


def test_missing_mesh_file_has_the_command_lines_message(tmp_path):
    missing = tmp_path / "missing.obj"
    code, _, err = run_cli("info", missing)
    assert code == 2
    with pytest.raises(FileNotFoundError) as caught:
        convray.load_mesh(missing)
    assert str(caught.value) == err.strip()
    with pytest.raises(FileNotFoundError):
        convray.ConvolutionObject().add_file(missing, 1.0)


def test_malformed_mesh_file_has_the_command_lines_message(tmp_path):
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    code, _, err = run_cli("info", bad)
    assert code == 2
    with pytest.raises(convray.InputError) as caught:
        convray.load_mesh(bad)
    assert str(caught.value) == err.strip()
    assert str(caught.value).startswith(str(bad) + ":4: ")
    assert isinstance(caught.value, ValueError)


def test_scene_errors_carry_file_line_and_column(tmp_path):
    scene = tmp_path / "broken.pov"
    scene.write_text("camera { location <0, 0, -3> look_at 0 }\nsphere { 0, 1 pigment { colr rgb 1 } }\n")
    code, _, err = run_cli(scene, "-o", tmp_path / "x.png")
    assert code == 2
    with pytest.raises(convray.InputError) as caught:
        convray.render(scene, 16, 16)
    assert str(caught.value) == err.rstrip("\n")
    assert str(caught.value).startswith(str(scene) + ":2:")
    with pytest.raises(convray.InputError, match=r"^<string>:2:\d+: "):
        convray.render(scene.read_text(), 16, 16)


def test_missing_scene_and_bad_options(tmp_path):
    missing = tmp_path / "nothing.pov"
    code, _, err = run_cli(missing, "-o", tmp_path / "x.png")
    with pytest.raises(FileNotFoundError) as caught:
        convray.render(missing, 16, 16)
    assert str(caught.value) == err.strip()
    scene = "camera { location <0, 0, -3> look_at 0 }\n"
    with pytest.raises(TypeError, match="unexpected keyword argument 'antialiasing'"):
        convray.render(scene, 16, 16, antialiasing=0.3)
    with pytest.raises(ValueError, match="--width"):
        convray.render(scene, 0, 16)
    with pytest.raises(ValueError, match="not an INI file"):
        convray.render("walk.ini", 16, 16)
    with pytest.raises(ValueError, match="--aa-depth"):
        convray.render(scene, 16, 16, aa_depth=20)
