"""convray.render against the PNG the command line writes for the same scene and options."""
import numpy as np
import pytest

import convray
from conftest import SOURCE_DIR, png_bytes_of, read_png, run_cli, write_png

SCENE = """#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 0, 0> angle 40 }
light_source { <-4, 6, -5> color rgb 1 }
background { color rgb <0.2, 0.3, 0.4> }
convolution {
  radius 0.6  offset 0.2
  segment { <-1 + clock, 0, 0>, <1, 0.3, 0> }
  point { <0, 0.8, 0> }
  pigment { color rgb <0.9, 0.5, 0.3> }  finish { phong 0.5 }
}
plane { y, -1 pigment { checker color rgb 1 color rgb 0.1 } }
"""


@pytest.fixture()
def scene_file(tmp_path):
    path = tmp_path / "small.pov"
    path.write_text(SCENE)
    return path


def cli_png(scene, tmp_path, *switches):
    out = tmp_path / "cli.png"
    code, _, err = run_cli(scene, "-o", out, *switches)
    assert code == 0, err
    return read_png(out)


def test_render_file_and_text_equal_the_command_lines_png(scene_file, tmp_path):
    image = convray.render(scene_file, 64, 48)
    assert image.shape == (48, 64, 4) and image.dtype == np.float32
    assert np.all(image[..., 3] == 1.0) and image.min() >= 0.0 and image.max() <= 1.0
    png = cli_png(scene_file, tmp_path, "+W64", "+H48")
    np.testing.assert_array_equal(png_bytes_of(image), png)
    np.testing.assert_array_equal(convray.render(SCENE, 64, 48), image)
    np.testing.assert_array_equal(convray.render(str(scene_file), 64, 48), image)


def test_clock_and_options_as_the_command_line(scene_file, tmp_path):
    image = convray.render(scene_file, 48, 36, clock=0.5, antialias=0.1, threads=2)
    png = cli_png(scene_file, tmp_path, "+W48", "+H36", "+K0.5", "+A0.1", "+WT2")
    np.testing.assert_array_equal(png_bytes_of(image), png)
    assert not np.array_equal(image, convray.render(scene_file, 48, 36))


def test_linear_pixels_encode_to_the_default_ones(scene_file):
    srgb = convray.render(scene_file, 32, 24)
    linear = convray.render(scene_file, 32, 24, linear=True)
    v = np.clip(linear[..., :3], 0.0, 1.0).astype(np.float64)
    encoded = np.where(v <= 0.0031308, 12.92 * v, 1.055 * v ** (1 / 2.4) - 0.055)
    np.testing.assert_allclose(srgb[..., :3], encoded, atol=2e-6)


def test_a_repository_scene_with_a_mesh(tmp_path):
    scene = SOURCE_DIR / "scenes" / "soup.pov"
    image = convray.render(scene, 40, 30)
    np.testing.assert_array_equal(png_bytes_of(image), cli_png(scene, tmp_path, "+W40", "+H30"))


def test_declare_and_library_options(tmp_path):
    (tmp_path / "inc").mkdir()
    (tmp_path / "inc" / "colour.inc").write_text("#declare Shade = rgb <0.1, 0.7, 0.2>;\n")
    text = ('#include "colour.inc"\ncamera { location <0,0,-3> look_at 0 }\n'
            'light_source { <0, 5, -5> color rgb 1 }\n'
            'sphere { 0, Size pigment { color Shade } }\n')
    scene = tmp_path / "declared.pov"
    scene.write_text(text)
    # A scene without assumed_gamma warns, as the program does on its standard error.
    with pytest.warns(UserWarning, match="assumed_gamma not specified"):
        image = convray.render(scene, 24, 24, declare={"Size": 0.8},
                               library=str(tmp_path / "inc"))
    png = cli_png(scene, tmp_path, "+W24", "+H24", "Declare=Size=0.8", "+L" + str(tmp_path / "inc"))
    np.testing.assert_array_equal(png_bytes_of(image), png)


def test_image_maps_read_through_the_plugin_beside_the_module(tmp_path):
    # Scenes read images through libconvray_oiio.so, which the module finds beside itself
    # (inside python3, not beside the program).
    texture = np.zeros((4, 4, 3), dtype=np.uint8)
    texture[::2, ::2] = [250, 40, 30]
    texture[1::2, 1::2] = [20, 60, 240]
    write_png(tmp_path / "tex.png", texture)
    scene = tmp_path / "mapped.pov"
    scene.write_text("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
                     "camera { location <0.5, 0.5, -2> look_at <0.5, 0.5, 0> }\n"
                     "light_source { <0, 0, -10> color rgb 1 }\n"
                     'plane { z, 0 pigment { image_map { png "tex.png" } } '
                     "finish { ambient 1 diffuse 0 } }\n")
    image = convray.render(scene, 32, 32)
    np.testing.assert_array_equal(png_bytes_of(image), cli_png(scene, tmp_path, "+W32", "+H32"))
    assert len(np.unique(png_bytes_of(image).reshape(-1, 3), axis=0)) >= 2
