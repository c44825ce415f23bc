// Image files from Python: write an array as any format glint writes, read one back.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "bindings.h"
#include "glint/image/image_io.h"
#include "glint/image/image_limits.h"
#include "glint/scene/scene_limits.h"
#include "image_arrays.h"

namespace py = pybind11;

namespace glint::python {

py::array_t<float> image_array(const Image& image, int channels) {
    std::vector<py::ssize_t> shape{image.height, image.width};
    if (channels > 1) shape.push_back(channels);
    py::array_t<float> array(shape);
    float* out = array.mutable_data();
    for (const Color& c : image.pixels) {
        const float parts[3] = {c.r, c.g, c.b};
        for (int k = 0; k < channels; ++k) *out++ = parts[k];
    }
    return array;
}

Image image_from_array(const py::array& given) {
    const auto array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(given);
    if (!array) throw py::value_error("image: expected an array of numbers");
    const bool gray = array.ndim() == 2;
    if (!gray && !(array.ndim() == 3 && array.shape(2) == 3))
        throw py::value_error("image: expected an array of H x W x 3 or H x W numbers");
    const py::ssize_t height = array.shape(0), width = array.shape(1);
    if (height < 1 || width < 1) throw py::value_error("image: the array is empty");
    if (height * width > kMaxWrittenImagePixels || width > kMaxImageSide || height > kMaxImageSide)
        throw py::value_error("image: larger than the limit of " +
                              std::to_string(kMaxWrittenImagePixels) + " pixels");
    Image image(static_cast<int>(width), static_cast<int>(height));
    const float* in = array.data();
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        Color& c = image.pixels[i];
        if (gray) {
            c = Color::gray(*in++);
        } else {
            c = {in[0], in[1], in[2]};
            in += 3;
        }
        // A written image never holds a NaN or an infinity, whoever made it.
        if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b))
            throw py::value_error("image: pixel (" + std::to_string(i % std::size_t(width)) + ", " +
                                  std::to_string(i / std::size_t(width)) + ") is not finite");
    }
    return image;
}

void bind_image(py::module_& m) {
    m.def(
        "write_image",
        [](const std::filesystem::path& path, const py::array& array) {
            const Image image = image_from_array(array);
            const py::gil_scoped_release unlocked;
            write_image(path, image);
        },
        py::arg("path"), py::arg("image"));
    m.def(
        "read_image",
        [](const std::filesystem::path& path) {
            Image image;
            {
                const py::gil_scoped_release unlocked;
                image = read_image(path);
            }
            return image_array(image, 3);
        },
        py::arg("path"));
}

}  // namespace glint::python
