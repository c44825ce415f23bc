"""glint, the ray tracer of the textbooks, from Python.

    import glint
    scene = glint.load("scenes/showcase.yaml")
    image = glint.render(scene, width=320, spp=16)   # float32 numpy array, H x W x 3, linear
    glint.write_image("showcase.png", image)
    tree = glint.explain(scene, pixel=(160, 120))    # the ray tree of one sample, as dicts

docs/python.md tells the whole of it.
"""

import json
import os
from typing import Any, Callable, Dict, Iterable, Optional, Sequence, Tuple, Union

from . import _glint
from ._dict_scene import to_yaml
from ._image import Image, as_image

__version__ = _glint.__version__
SceneError = _glint.SceneError
SettingsError = _glint.SettingsError
ImageError = _glint.ImageError

PathLike = Union[str, "os.PathLike[str]"]

__all__ = ["Scene", "load", "render", "explain", "write_image", "read_image", "Image",
           "SceneError", "SettingsError", "ImageError", "__version__"]


def _limits(allow_read: Iterable[PathLike], max_file_size: Optional[int],
            max_pixels: Optional[int], max_samples: Optional[int],
            max_ray_depth: Optional[int]) -> Dict[str, Any]:
    return dict(allow_read=[os.fspath(p) for p in allow_read], max_file_size=max_file_size,
                max_pixels=max_pixels, max_samples=max_samples, max_ray_depth=max_ray_depth)


class Scene:
    """A scene: from a dict with the keys of glint's YAML format, or from a file by load().

    Files the scene names (meshes, textures) are looked for in `base` (default: the current
    folder) and may be read only there and under `allow_read`, as on the command line. An error
    raises SceneError whose message starts with the key's path in the dict:
    "materials.red.kd: material "red" kd must be >= 0, got -1".
    """

    def __init__(self, description: Dict[str, Any], *, base: Optional[PathLike] = None,
                 allow_read: Iterable[PathLike] = (), max_file_size: Optional[int] = None,
                 max_pixels: Optional[int] = None, max_samples: Optional[int] = None,
                 max_ray_depth: Optional[int] = None) -> None:
        text, paths = to_yaml(description)
        folder = os.path.abspath(os.fspath(base) if base is not None else os.getcwd())
        as_file = os.path.join(folder, "<dict>")
        try:
            self._data = _glint.parse(text, as_file, **_limits(
                allow_read, max_file_size, max_pixels, max_samples, max_ray_depth))
        except SceneError as error:
            # An error in a file the dict names keeps that file's place.
            if error.file != as_file:
                raise
            raise _located_in_dict(error, paths) from None

    @classmethod
    def _of(cls, data: Any) -> "Scene":
        scene = cls.__new__(cls)
        scene._data = data
        return scene

    # What the scene asks for, before any override.
    width = property(lambda self: self._data.width, doc="image width in pixels")
    height = property(lambda self: self._data.height, doc="image height in pixels")
    spp = property(lambda self: self._data.spp, doc="samples per pixel")
    max_depth = property(lambda self: self._data.max_depth, doc="deepest level of the ray tree")
    integrator = property(lambda self: self._data.integrator, doc="the integrator's name")
    objects = property(lambda self: self._data.objects, doc="number of objects")
    lights = property(lambda self: self._data.lights, doc="number of lights")
    materials = property(lambda self: self._data.materials, doc="number of materials")
    warnings = property(lambda self: list(self._data.warnings),
                        doc="what the loader accepted but you should know")
    files_read = property(lambda self: [str(p) for p in self._data.files_read],
                          doc="the files the scene read besides its own")

    def __repr__(self) -> str:
        return (f"<glint.Scene {self.width}x{self.height}, {self.spp} spp, {self.integrator}: "
                f"{self.objects} objects, {self.lights} lights>")


def _located_in_dict(error: Exception, paths: Sequence[str]) -> Exception:
    line = getattr(error, "line", 0)
    path = paths[line - 1] if 0 < line <= len(paths) else ""
    message = getattr(error, "message", str(error))
    text = f"{path}: {message}" if path else message
    for note in getattr(error, "notes", []):
        text += f"\nnote: {note}"
    located = SceneError(text)
    located.file, located.line, located.column = "<dict>", 0, 0
    located.message, located.notes, located.key = message, list(getattr(error, "notes", [])), path
    return located


def load(file: PathLike, *, allow_read: Iterable[PathLike] = (),
         max_file_size: Optional[int] = None, max_pixels: Optional[int] = None,
         max_samples: Optional[int] = None, max_ray_depth: Optional[int] = None) -> Scene:
    """Reads a scene file of any format glint reads (.yaml, .nff, .nff.gz, .obj, .ply, .gltf,
    .glb, .stl), under the sandbox and limits of the command line's options of the same names."""
    return Scene._of(_glint.load(os.fspath(file), **_limits(
        allow_read, max_file_size, max_pixels, max_samples, max_ray_depth)))


def _overrides(width: Optional[int], height: Optional[int], spp: Optional[int],
               integrator: Optional[str], sampler: Optional[str], filter: Optional[str],
               shadows: Optional[str], max_depth: Optional[int]) -> Dict[str, Any]:
    return dict(width=width, height=height, spp=spp, integrator=integrator, sampler=sampler,
                filter=filter, shadows=shadows, max_depth=max_depth)


def render(scene: Scene, *, width: Optional[int] = None, height: Optional[int] = None,
           spp: Optional[int] = None, integrator: Optional[str] = None,
           sampler: Optional[str] = None, filter: Optional[str] = None,
           shadows: Optional[str] = None, max_depth: Optional[int] = None, seed: int = 0,
           threads: int = 0, aovs: Sequence[str] = (), accel: str = "bvh",
           progress: Optional[Callable[[int, int], Any]] = None
           ) -> Union[Image, Tuple[Image, Dict[str, Image]]]:
    """Renders the scene, with the settings given overriding its own, as `glint render` does
    with the options of the same names; the same seed gives the command line's image, bit for
    bit. Returns the image, a float32 array H x W x 3 of linear colour; with `aovs`, the image
    and a dict of the output variables by name. `progress(done, total)` is called as the pieces
    of work (tiles x passes) are done. The GIL is released while it renders; Ctrl-C
    (KeyboardInterrupt) stops it, as does an exception raised by `progress`."""
    if not isinstance(scene, Scene):
        raise TypeError(f"scene: expected a glint.Scene, got {type(scene).__name__}")
    if isinstance(aovs, str):
        aovs = [aovs]
    result = _glint.render(
        scene._data, _overrides(width, height, spp, integrator, sampler, filter, shadows,
                                max_depth),
        seed=seed, threads=threads, aovs=list(aovs), accel=accel, progress=progress)
    if isinstance(result, tuple):
        image, layers = result
        return as_image(image), {name: as_image(layer) for name, layer in layers.items()}
    return as_image(result)


def explain(scene: Scene, *, pixel: Tuple[int, int], sample: int = 0, seed: int = 0,
            width: Optional[int] = None, height: Optional[int] = None,
            spp: Optional[int] = None, integrator: Optional[str] = None,
            sampler: Optional[str] = None, filter: Optional[str] = None,
            shadows: Optional[str] = None, max_depth: Optional[int] = None) -> Dict[str, Any]:
    """The ray tree of one sample of one pixel ((0, 0) is the top left), as nested dicts: the
    JSON of `glint explain`, with every term of the formula. Pass the settings the render was
    given, as to `glint explain`, to see the sample that render computed."""
    if not isinstance(scene, Scene):
        raise TypeError(f"scene: expected a glint.Scene, got {type(scene).__name__}")
    if (not isinstance(pixel, (tuple, list)) or len(pixel) != 2
            or not all(isinstance(v, int) and not isinstance(v, bool) for v in pixel)):
        raise TypeError(f"pixel: expected (x, y), two whole numbers, got {pixel!r}")
    x, y = pixel
    text = _glint.explain_json(
        scene._data, x=x, y=y, sample=sample, seed=seed,
        overrides=_overrides(width, height, spp, integrator, sampler, filter, shadows, max_depth))
    return json.loads(text)


def write_image(path: PathLike, image: Any) -> None:
    """Writes an array (H x W x 3 or H x W, linear) as the file's extension says: .png (sRGB,
    8-bit), .ppm, .pfm or .exr (float); written whole or not at all. Raises ImageError."""
    _glint.write_image(os.fspath(path), image)


def read_image(path: PathLike) -> Image:
    """Reads an image file (.png, .ppm, .pfm, .exr, .hdr) as a float32 array H x W x 3, linear."""
    return as_image(_glint.read_image(os.fspath(path)))
