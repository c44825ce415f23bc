"""The arrays glint returns: numpy arrays that show themselves in Jupyter."""

import os
import tempfile

import numpy as np

from . import _glint


class Image(np.ndarray):
    """A float32 numpy array of linear colour, H x W x 3 (or H x W for one channel), rows from
    the top. It is an ordinary array in every way; Jupyter shows it as the sRGB PNG glint would
    write."""

    def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
        # Arithmetic on images gives plain arrays, and reductions (np.mean, max) plain numbers:
        # an Image is what glint returned, not what was computed from it.
        def plain(values):
            return tuple(np.asarray(v) if isinstance(v, Image) else v for v in values)

        outs = kwargs.get("out")
        if outs:
            kwargs["out"] = plain(outs)
        result = getattr(ufunc, method)(*plain(inputs), **kwargs)
        if outs:  # in place (image += 1): the arrays written into, as they were
            return outs[0] if len(outs) == 1 else outs
        return result

    def _repr_png_(self) -> bytes:
        pixels = np.asarray(self, dtype=np.float32)
        if pixels.ndim == 3 and pixels.shape[2] == 2:  # uv: red and green
            pixels = np.concatenate([pixels, np.zeros(pixels.shape[:2] + (1,), np.float32)], 2)
        pixels = np.nan_to_num(pixels, nan=0.0, posinf=0.0, neginf=0.0)
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "image.png")
            _glint.write_image(path, pixels)
            with open(path, "rb") as file:
                return file.read()


def as_image(array: np.ndarray) -> Image:
    return array.view(Image)
