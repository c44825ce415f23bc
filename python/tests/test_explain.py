"""The ray tree of a sample through Python: the command line's JSON, with the notes' numbers."""

import json

import pytest

import glint
from conftest import run_glint, sphere_scene


def test_the_tree_is_the_command_lines(source):
    scene_file = source / "scenes/whitted-basics.yaml"
    result = run_glint("explain", str(scene_file), "--pixel", "100,100", "--width", "200",
                       "--format", "json")
    assert result.returncode == 0, result.stderr
    tree = glint.explain(glint.load(scene_file), pixel=(100, 100), width=200)
    assert tree == json.loads(result.stdout)


def test_the_notes_worked_ray_sphere_example():
    # One pixel: its eye ray goes straight down -z from the origin, meets the unit sphere round
    # (0, 0, -5) at t = 5 - 1 = 4, at (0, 0, -4), where the normal is (0, 0, 1).
    tree = glint.explain(glint.Scene(sphere_scene(width=1, height=1)), pixel=(0, 0))
    eye = tree["rays"][0]
    assert eye["kind"] == "eye"
    assert eye["direction"] == pytest.approx([0, 0, -1], abs=1e-6)
    assert eye["hit"]["t"] == pytest.approx(4, abs=1e-5)
    assert eye["hit"]["point"] == pytest.approx([0, 0, -4], abs=1e-5)
    assert eye["hit"]["shading_normal"] == pytest.approx([0, 0, 1], abs=1e-5)
    # The light at (5, 5, 0): L = (5, 5, 4) / sqrt(66), N.L = 4 / sqrt(66).
    light = eye["lights"][0]["samples"][0]
    assert light["n_dot_l"] == pytest.approx(4 / 66 ** 0.5, abs=1e-6)


def test_a_pixel_outside_the_image_names_it():
    with pytest.raises(glint.SettingsError, match=r"pixel \(16, 0\) is outside") as caught:
        glint.explain(glint.Scene(sphere_scene()), pixel=(16, 0))
    assert caught.value.key == "pixel"


def test_a_sample_beyond_the_pixels_count_names_it():
    with pytest.raises(glint.SettingsError) as caught:
        glint.explain(glint.Scene(sphere_scene()), pixel=(0, 0), sample=1)
    assert caught.value.key == "sample"


def test_cones_are_not_explained():
    with pytest.raises(glint.SettingsError, match="follows rays") as caught:
        glint.explain(glint.Scene(sphere_scene()), pixel=(0, 0), integrator="cone")
    assert caught.value.key == "integrator"


def test_a_pixel_that_is_not_two_whole_numbers_is_a_type_error():
    for pixel in [(1,), (1.5, 2), "1,2", (1, 2, 3)]:
        with pytest.raises(TypeError, match="pixel: expected \\(x, y\\)"):
            glint.explain(glint.Scene(sphere_scene()), pixel=pixel)
