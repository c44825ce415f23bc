// The dict's values, cast: a missing key is the scene's setting.
#include "overrides_arg.h"

#include <pybind11/stl.h>

#include <optional>
#include <string>

namespace py = pybind11;

namespace glint::python {

namespace {

// The value as T, or a TypeError that names the key and what it was given.
template <typename T>
T as(const py::handle& value, const char* key, const char* expected) {
    try {
        return value.cast<T>();
    } catch (const py::cast_error&) {
        throw py::type_error(std::string(key) + ": expected " + expected + ", got " +
                             py::repr(value).cast<std::string>());
    }
}

std::optional<int> number(const py::dict& given, const char* key) {
    if (!given.contains(key) || given[key].is_none()) return std::nullopt;
    return as<int>(given[key], key, "a whole number");
}

std::string name(const py::dict& given, const char* key) {
    if (!given.contains(key) || given[key].is_none()) return {};
    return as<std::string>(given[key], key, "a name");
}

}  // namespace

SettingOverrides overrides_from(const py::dict& given) {
    return {.width = number(given, "width"),
            .height = number(given, "height"),
            .spp = number(given, "spp"),
            .max_depth = number(given, "max_depth"),
            .integrator = name(given, "integrator"),
            .sampler = name(given, "sampler"),
            .filter = name(given, "filter"),
            .shadows = name(given, "shadows")};
}

}  // namespace glint::python
