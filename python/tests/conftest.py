"""What the tests share: the source tree, the command-line tool of the same build, and small
scenes as dicts."""

import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("GLINT_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
BINARY = os.environ.get("GLINT_BINARY", str(SOURCE / "build/release/apps/glint/glint"))


def run_glint(*arguments: str) -> subprocess.CompletedProcess:
    return subprocess.run([BINARY, *arguments], capture_output=True, text=True, timeout=300)


def sphere_scene(**image) -> dict:
    """The notes' worked example: an eye at the origin looking down -z at a unit sphere 5 away,
    lit by one point light."""
    return {
        "image": {"width": 16, "height": 12, "samples": 1, **image},
        "camera": {"from": [0, 0, 0], "at": [0, 0, -1], "up": [0, 1, 0], "fov": 40},
        "materials": {"red": {"color": [0.9, 0.1, 0.1], "kd": 0.7, "ks": 0.3}},
        "lights": [{"type": "point", "position": [5, 5, 0]}],
        "objects": [{"type": "sphere", "center": [0, 0, -5], "radius": 1, "material": "red"}],
    }


@pytest.fixture
def source() -> pathlib.Path:
    return SOURCE
