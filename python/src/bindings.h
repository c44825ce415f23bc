// The parts of the module, each binding one part of the library (module.cpp calls them in turn).
#pragma once

#include <pybind11/pybind11.h>

namespace glint::python {

void bind_scene(pybind11::module_& m);
void bind_render(pybind11::module_& m);
void bind_explain(pybind11::module_& m);
void bind_image(pybind11::module_& m);

}  // namespace glint::python
