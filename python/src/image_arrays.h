// Images as numpy arrays: float32, rows from the top, H x W x 3 (or H x W for one channel, H x W
// x 2 for two), linear, as the film holds them.
#pragma once

#include <pybind11/numpy.h>

#include "glint/image/image.h"

namespace glint::python {

// The first `channels` (1, 2 or 3) of each pixel's colour.
pybind11::array_t<float> image_array(const Image& image, int channels);

// An H x W x 3 or H x W array of numbers (converted to float32); throws ValueError for any
// other shape, an empty one, or one larger than the image limits.
Image image_from_array(const pybind11::array& array);

}  // namespace glint::python
