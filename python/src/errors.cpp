// The exception types and the translator that raises them from the library's exceptions.
#include "errors.h"

#include <pybind11/stl.h>

#include <exception>
#include <new>
#include <string>

#include "glint/image/image_error.h"
#include "glint/scene/scene_error.h"
#include "glint/scene/setting_overrides.h"

namespace py = pybind11;

namespace glint::python {

namespace {

// The types, made once when the module is imported and kept for the process's life.
PyObject* scene_error_type = nullptr;
PyObject* settings_error_type = nullptr;
PyObject* image_error_type = nullptr;

// Raises `type(text)` with the attributes set on the instance.
void raise(PyObject* type, const std::string& text, const py::dict& attributes) {
    py::object error = py::reinterpret_borrow<py::object>(type)(text);
    for (const auto& [name, value] : attributes)
        py::setattr(error, name, py::reinterpret_borrow<py::object>(value));
    PyErr_SetObject(type, error.ptr());
}

std::string with_notes(const std::string& message, const std::vector<std::string>& notes) {
    std::string text = message;
    for (const std::string& note : notes) text += " (" + note + ")";
    return text;
}

}  // namespace

void bind_errors(py::module_& m) {
    scene_error_type = PyErr_NewExceptionWithDoc(
        "glint.SceneError",
        "A scene that cannot be read: str() is the message as glint prints it (file:line:col, "
        "the line, a caret, notes); file, line, column, message and notes hold its parts.",
        PyExc_ValueError, nullptr);
    settings_error_type = PyErr_NewExceptionWithDoc(
        "glint.SettingsError",
        "A setting that cannot be rendered; key names it (\"spp\", \"pixel\"), or is empty when "
        "the settings as a whole cannot be.",
        PyExc_ValueError, nullptr);
    image_error_type = PyErr_NewExceptionWithDoc(
        "glint.ImageError", "An image file that cannot be read or written; file names it.",
        PyExc_OSError, nullptr);
    m.attr("SceneError") = py::handle(scene_error_type);
    m.attr("SettingsError") = py::handle(settings_error_type);
    m.attr("ImageError") = py::handle(image_error_type);

    py::register_exception_translator([](std::exception_ptr thrown) {
        try {
            if (thrown) std::rethrow_exception(thrown);
        } catch (const SceneError& e) {
            py::dict parts;
            parts["file"] = e.location().file;
            parts["line"] = e.location().line;
            parts["column"] = e.location().column;
            parts["message"] = e.message();
            parts["notes"] = py::cast(e.notes());
            std::string text = format_scene_error(e);
            while (!text.empty() && text.back() == '\n') text.pop_back();
            raise(scene_error_type, text, parts);
        } catch (const SettingsError& e) {
            py::dict parts;
            parts["key"] = e.key();
            parts["notes"] = py::cast(e.notes());
            raise(settings_error_type, with_notes(e.what(), e.notes()), parts);
        } catch (const ImageError& e) {
            py::dict parts;
            parts["file"] = e.file.string();
            raise(image_error_type, e.what(), parts);
        }
    });
}

}  // namespace glint::python
