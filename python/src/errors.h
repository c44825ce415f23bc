// glint's exceptions as Python's: a scene error (glint.SceneError, a ValueError with the file,
// line, column, message and notes), a setting that cannot be rendered (glint.SettingsError, a
// ValueError naming the setting) and an image file's failure (glint.ImageError, an OSError).
#pragma once

#include <pybind11/pybind11.h>

namespace glint::python {

void bind_errors(pybind11::module_& m);

}  // namespace glint::python
