"""Renders through Python: the command line's image bit for bit, output variables, progress,
stopping, threads, and the settings checked as the command line checks them."""

import _thread
import os
import threading
import time

import numpy as np
import pytest

import glint
from conftest import run_glint, sphere_scene


@pytest.mark.parametrize("integrator", ["whitted", "distributed", "path"])
def test_the_image_is_the_command_lines_bit_for_bit(tmp_path, source, integrator):
    scene_file = source / "scenes/whitted-basics.yaml"
    out = tmp_path / "cli.pfm"
    result = run_glint("render", str(scene_file), "-o", str(out), "--width", "48", "--spp", "4",
                       "--integrator", integrator, "--seed", "7", "--quiet")
    assert result.returncode == 0, result.stderr
    image = glint.render(glint.load(scene_file), width=48, spp=4, integrator=integrator, seed=7)
    assert image.dtype == np.float32 and image.shape == (36, 48, 3)
    assert np.array_equal(image, glint.read_image(out))


def test_another_seed_gives_another_image():
    scene = glint.Scene(sphere_scene(samples=4))
    a = glint.render(scene, integrator="distributed", seed=1)
    b = glint.render(scene, integrator="distributed", seed=2)
    assert not np.array_equal(a, b)
    assert np.array_equal(a, glint.render(scene, integrator="distributed", seed=1, threads=1))


def test_the_sphere_is_lit_in_the_middle_and_the_background_around():
    image = glint.render(glint.Scene(sphere_scene()))
    assert image[6, 8, 0] > 0.1 and image[6, 8, 0] > image[6, 8, 2]
    assert np.all(image[0, 0] == image[0, 0, 0])  # a grey background corner


def test_output_variables_come_as_arrays_by_name():
    image, aovs = glint.render(glint.Scene(sphere_scene()), aovs=["depth", "normal", "uv"])
    assert set(aovs) == {"depth", "normal", "uv"}
    assert aovs["depth"].shape == (12, 16) and aovs["uv"].shape == (12, 16, 2)
    assert aovs["normal"].shape == image.shape
    # The eye is 5 from the centre of a unit sphere: the nearest point is 4 away.
    assert aovs["depth"][6, 8] == pytest.approx(4, abs=0.05)
    assert aovs["depth"][0, 0] == 0  # missed
    assert glint.render(glint.Scene(sphere_scene()), aovs="depth")[1].keys() == {"depth"}


def test_progress_counts_every_piece_up_to_the_total():
    calls = []
    glint.render(glint.Scene(sphere_scene(width=64, height=64)), spp=4,
                 progress=lambda done, total: calls.append((done, total)))
    assert calls and calls[-1][0] == calls[-1][1]
    assert [d for d, _ in calls] == sorted(d for d, _ in calls)


def test_an_exception_in_progress_stops_the_render():
    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop()

    with pytest.raises(Stop):
        glint.render(glint.Scene(sphere_scene(width=64, height=64)), progress=stop)


def test_ctrl_c_stops_a_long_render_with_keyboard_interrupt():
    scene = glint.Scene(sphere_scene(width=1024, height=1024))
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        glint.render(scene, spp=4096, integrator="path")
    # It stops within the tiles in flight, not at the end of a render of minutes.
    assert time.monotonic() - started < 20
    timer.join()


def test_renders_run_on_several_python_threads_at_once():
    scene = glint.Scene(sphere_scene(width=32, height=32))
    results = [None] * 3

    def work(i):
        results[i] = glint.render(scene, spp=4, integrator="distributed", threads=1)

    workers = [threading.Thread(target=work, args=(i,)) for i in range(3)]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    assert all(np.array_equal(results[0], r) for r in results)


@pytest.mark.parametrize("settings, key", [
    ({"spp": 0}, "spp"),
    ({"width": 100000}, "width"),
    ({"integrator": "pth"}, "integrator"),
    ({"sampler": "x"}, "sampler"),
    ({"threads": -1}, "threads"),
    ({"aovs": ["bogus"]}, "aovs"),
    ({"accel": "octree"}, "accel"),
    ({"spp": 8, "sampler": "regular"}, ""),
])
def test_bad_settings_raise_settings_error_naming_them(settings, key):
    with pytest.raises(glint.SettingsError) as caught:
        glint.render(glint.Scene(sphere_scene()), **settings)
    assert caught.value.key == key


def test_an_unknown_integrator_is_suggested():
    with pytest.raises(glint.SettingsError, match="did you mean \"path\""):
        glint.render(glint.Scene(sphere_scene()), integrator="pth")


def test_output_variables_are_refused_for_cones():
    with pytest.raises(glint.SettingsError, match="traces cones"):
        glint.render(glint.Scene(sphere_scene()), integrator="cone", aovs=["depth"])


def test_a_scene_the_integrator_cannot_render_is_a_scene_error():
    with pytest.raises(glint.SceneError, match="sphere"):
        glint.render(glint.Scene(sphere_scene()), integrator="beam")


def test_render_takes_only_scenes():
    with pytest.raises(TypeError):
        glint.render("scene.yaml")


def test_settings_of_the_wrong_type_are_type_errors():
    with pytest.raises(TypeError, match="spp: expected a whole number, got '4'"):
        glint.render(glint.Scene(sphere_scene()), spp="4")
    with pytest.raises(TypeError, match="integrator: expected a name, got 3"):
        glint.render(glint.Scene(sphere_scene()), integrator=3)


def resident_bytes() -> int:
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def test_a_hundred_renders_in_a_loop_leak_nothing():
    # Each render returns 192 KiB of image and as much of output variables: a leak of either, or
    # of the scene's copy or the world, would grow the process by tens of megabytes.
    scene = glint.Scene(sphere_scene(width=128, height=128))

    def renders(count):
        for _ in range(count):
            image, aovs = glint.render(scene, aovs=["normal"], threads=1)
            del image, aovs

    renders(20)  # allocators and caches settle
    before = resident_bytes()
    renders(100)
    assert resident_bytes() - before < 8 << 20
