// glint._glint: the library's bindings, which the package glint (python/glint) wraps in Python.
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "errors.h"

#ifndef GLINT_VERSION
#define GLINT_VERSION "unknown"
#endif

PYBIND11_MODULE(_glint, m) {
    m.doc() = "glint's library: load, render, explain, write images (use the package glint)";
    m.attr("__version__") = GLINT_VERSION;
    glint::python::bind_errors(m);
    glint::python::bind_scene(m);
    glint::python::bind_render(m);
    glint::python::bind_explain(m);
    glint::python::bind_image(m);
}
