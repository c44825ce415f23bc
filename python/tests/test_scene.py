"""Scenes from files and from dicts, their errors located in the dict, the sandbox and limits."""

import numpy as np
import pytest

import glint
from conftest import sphere_scene


def test_load_reads_a_scene_file(source):
    scene = glint.load(source / "scenes/whitted-basics.yaml")
    assert (scene.width, scene.height, scene.spp) == (320, 240, 1)
    assert scene.integrator == "whitted"
    assert (scene.objects, scene.lights, scene.materials) == (5, 1, 3)
    assert "320x240" in repr(scene)


def test_load_reads_every_format(source):
    assert glint.load(source / "scenes/features/jacks.nff").objects > 0


def test_a_missing_file_is_a_scene_error(tmp_path):
    with pytest.raises(glint.SceneError) as caught:
        glint.load(tmp_path / "none.yaml")
    assert "none.yaml" in str(caught.value)


def test_a_dict_scene_has_the_yaml_formats_keys():
    scene = glint.Scene(sphere_scene())
    assert (scene.width, scene.height) == (16, 12)
    assert scene.objects == 1


def test_tuples_and_numpy_values_are_taken():
    description = sphere_scene()
    description["camera"]["from"] = (0, 0, 0)
    description["objects"][0]["center"] = np.array([0.0, 0.0, -5.0])
    description["objects"][0]["radius"] = np.float32(1)
    assert glint.Scene(description).objects == 1


def error_of(description: dict) -> glint.SceneError:
    with pytest.raises(glint.SceneError) as caught:
        glint.Scene(description)
    return caught.value


def test_a_bad_value_names_its_path_in_the_dict():
    description = sphere_scene()
    description["materials"]["red"]["kd"] = -1
    error = error_of(description)
    assert str(error).startswith("materials.red.kd: material \"red\" kd must be >= 0, got -1")
    assert error.key == "materials.red.kd"


def test_an_unknown_key_in_a_list_names_its_index():
    description = sphere_scene()
    description["objects"].append({"type": "sphere", "center": [1, 0, -5], "radius": 1,
                                   "colour": [1, 0, 0]})
    error = error_of(description)
    assert str(error).startswith("objects[1].colour: ")
    assert "note:" in str(error)


def test_a_misspelt_type_is_suggested():
    description = sphere_scene()
    description["objects"][0]["type"] = "spere"
    error = error_of(description)
    assert error.key == "objects[0].type"
    assert "did you mean \"sphere\"" in str(error)


def test_values_yaml_cannot_hold_are_type_errors():
    with pytest.raises(TypeError, match="objects\\[0\\].radius"):
        glint.Scene({**sphere_scene(), "objects": [{"type": "sphere", "radius": object()}]})
    with pytest.raises(TypeError, match="keys must be strings"):
        glint.Scene({1: 2})
    with pytest.raises(TypeError):
        glint.Scene([1, 2])


def test_limits_apply_as_on_the_command_line():
    with pytest.raises(glint.SceneError, match="image.samples"):
        glint.Scene(sphere_scene(samples=64), max_samples=16)
    with pytest.raises(glint.SettingsError, match="max_samples"):
        glint.Scene(sphere_scene(), max_samples=0)


def test_a_dict_scene_reads_files_only_in_its_folder(tmp_path, source):
    mesh = source / "tests/data/meshes/cube_ascii.ply"
    assert mesh.exists()
    description = sphere_scene()
    description["objects"].append({"type": "mesh", "file": str(mesh), "material": "red"})
    with pytest.raises(glint.SceneError, match="outside"):
        glint.Scene(description, base=tmp_path)
    scene = glint.Scene(description, base=tmp_path, allow_read=[mesh.parent])
    assert scene.files_read == [str(mesh)]
