# Type stubs of the package glint (python/glint/__init__.py has the docstrings).
import os
from typing import Any, Callable, Dict, Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

PathLike = Union[str, os.PathLike[str]]

__version__: str

class SceneError(ValueError):
    file: str
    line: int
    column: int
    message: str
    notes: List[str]

class SettingsError(ValueError):
    key: str
    notes: List[str]

class ImageError(OSError):
    file: str

class Image(np.ndarray):
    def _repr_png_(self) -> bytes: ...

class Scene:
    def __init__(self, description: Dict[str, Any], *, base: Optional[PathLike] = ...,
                 allow_read: Iterable[PathLike] = ..., max_file_size: Optional[int] = ...,
                 max_pixels: Optional[int] = ..., max_samples: Optional[int] = ...,
                 max_ray_depth: Optional[int] = ...) -> None: ...
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def spp(self) -> int: ...
    @property
    def max_depth(self) -> int: ...
    @property
    def integrator(self) -> str: ...
    @property
    def objects(self) -> int: ...
    @property
    def lights(self) -> int: ...
    @property
    def materials(self) -> int: ...
    @property
    def warnings(self) -> List[str]: ...
    @property
    def files_read(self) -> List[str]: ...

def load(file: PathLike, *, allow_read: Iterable[PathLike] = ...,
         max_file_size: Optional[int] = ..., max_pixels: Optional[int] = ...,
         max_samples: Optional[int] = ..., max_ray_depth: Optional[int] = ...) -> Scene: ...

def render(scene: Scene, *, width: Optional[int] = ..., height: Optional[int] = ...,
           spp: Optional[int] = ..., integrator: Optional[str] = ...,
           sampler: Optional[str] = ..., filter: Optional[str] = ...,
           shadows: Optional[str] = ..., max_depth: Optional[int] = ..., seed: int = ...,
           threads: int = ..., aovs: Sequence[str] = ..., accel: str = ...,
           progress: Optional[Callable[[int, int], Any]] = ...
           ) -> Union[Image, Tuple[Image, Dict[str, Image]]]: ...

def explain(scene: Scene, *, pixel: Tuple[int, int], sample: int = ..., seed: int = ...,
            width: Optional[int] = ..., height: Optional[int] = ..., spp: Optional[int] = ...,
            integrator: Optional[str] = ..., sampler: Optional[str] = ...,
            filter: Optional[str] = ..., shadows: Optional[str] = ...,
            max_depth: Optional[int] = ...) -> Dict[str, Any]: ...

def write_image(path: PathLike, image: Any) -> None: ...

def read_image(path: PathLike) -> Image: ...
