"""Images written and read from Python, and shown in Jupyter."""

import numpy as np
import pytest

import glint
from conftest import sphere_scene


def test_exr_and_pfm_keep_the_floats(tmp_path):
    pixels = np.random.default_rng(1).random((5, 7, 3), dtype=np.float32) * 4
    for name in ["a.exr", "a.pfm"]:
        glint.write_image(tmp_path / name, pixels)
        assert np.array_equal(glint.read_image(tmp_path / name), pixels)


def test_png_is_srgb_8_bit(tmp_path):
    pixels = np.full((2, 3, 3), 0.5, np.float32)
    glint.write_image(tmp_path / "a.png", pixels)
    # 0.5 linear lies between the sRGB levels 187 and 188 (0.4969 and 0.5029 linear): dithered,
    # each pixel takes one of the two, and the mean stays near 0.5.
    image = glint.read_image(tmp_path / "a.png")
    assert np.all((np.abs(image - 0.4969) < 1e-3) | (np.abs(image - 0.5029) < 1e-3))
    assert np.mean(image) == pytest.approx(0.5, abs=0.005)


def test_a_grey_array_is_written_as_grey(tmp_path):
    glint.write_image(tmp_path / "g.pfm", np.arange(6, dtype=np.float64).reshape(2, 3))
    image = glint.read_image(tmp_path / "g.pfm")
    assert image.shape == (2, 3, 3) and image[1, 2, 1] == 5


def test_bad_arrays_are_refused(tmp_path):
    with pytest.raises(ValueError, match="H x W x 3"):
        glint.write_image(tmp_path / "a.png", np.zeros((2, 2, 4)))
    with pytest.raises(ValueError, match="empty"):
        glint.write_image(tmp_path / "a.png", np.zeros((0, 2, 3)))
    nan = np.zeros((2, 2, 3))
    nan[1, 0, 2] = np.nan
    with pytest.raises(ValueError, match=r"pixel \(0, 1\) is not finite"):
        glint.write_image(tmp_path / "a.exr", nan)
    assert not (tmp_path / "a.exr").exists()


def test_bad_files_raise_image_error(tmp_path):
    with pytest.raises(glint.ImageError, match="a.bmp"):
        glint.write_image(tmp_path / "a.bmp", np.zeros((2, 2, 3)))
    with pytest.raises(glint.ImageError):
        glint.read_image(tmp_path / "missing.png")
    with pytest.raises(OSError):
        glint.write_image(tmp_path / "no/such/folder/a.png", np.zeros((2, 2, 3)))


def test_images_show_themselves_as_png():
    image = glint.render(glint.Scene(sphere_scene(width=4, height=3)))
    assert isinstance(image, glint.Image) and isinstance(image, np.ndarray)
    assert image._repr_png_().startswith(b"\x89PNG\r\n\x1a\n")


def test_what_is_computed_from_an_image_is_a_plain_array_or_number():
    image = glint.render(glint.Scene(sphere_scene(width=4, height=3)))
    mean = np.mean(image)
    assert type(mean) is np.float32 and mean == pytest.approx(np.asarray(image).mean())
    assert type(image * 2) is np.ndarray
    image += 1  # in place, it stays the Image it was
    assert isinstance(image, glint.Image)
