// Scenes: read from a file of any format glint reads, or from YAML text (what the package makes
// of a dict), under the sandbox and limits the command line applies.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "glint/scene/integrators.h"
#include "glint/scene/load_scene.h"
#include "glint/scene/setting_overrides.h"

namespace py = pybind11;

namespace glint::python {

namespace {

template <typename T>
T within(const char* key, std::optional<T> value, T fallback, T most) {
    if (!value) return fallback;
    check_whole_number(key, *value, 1, most);
    return *value;
}

// The command line's --allow-read, --max-file-size, --max-pixels, --max-samples and
// --max-ray-depth, checked as it checks them.
LoadOptions load_options(const std::vector<std::filesystem::path>& allow_read,
                         std::optional<std::int64_t> max_file_size,
                         std::optional<std::int64_t> max_pixels, std::optional<int> max_samples,
                         std::optional<int> max_ray_depth) {
    LoadOptions options;
    options.allow_read = allow_read;
    if (max_file_size)
        options.max_file_bytes = std::uintmax_t(
            within<std::int64_t>("max_file_size", max_file_size, 0, std::int64_t(1) << 62));
    const SceneLimits defaults;
    options.limits.image_pixels =
        within<std::int64_t>("max_pixels", max_pixels, defaults.image_pixels, kMaxRenderPixels);
    options.limits.samples_per_pixel =
        within("max_samples", max_samples, defaults.samples_per_pixel, kMaxSamplesPerPixel);
    options.limits.max_depth =
        within("max_ray_depth", max_ray_depth, defaults.max_depth, kMaxDepth);
    return options;
}

}  // namespace

void bind_scene(py::module_& m) {
    py::class_<Scene, std::shared_ptr<Scene>>(m, "SceneData",
                                              "A loaded scene, as the library holds it")
        .def_property_readonly("file", [](const Scene& s) { return s.sources.file; })
        .def_property_readonly("width", [](const Scene& s) { return s.settings.width; })
        .def_property_readonly("height", [](const Scene& s) { return s.settings.height; })
        .def_property_readonly("spp", [](const Scene& s) { return s.settings.samples_per_pixel; })
        .def_property_readonly("max_depth", [](const Scene& s) { return s.settings.max_depth; })
        .def_property_readonly(
            "integrator",
            [](const Scene& s) { return std::string(integrator_name(s.settings.integrator)); })
        .def_property_readonly("objects", [](const Scene& s) { return s.objects.size(); })
        .def_property_readonly("lights", [](const Scene& s) { return s.lights.size(); })
        .def_property_readonly("materials", [](const Scene& s) { return s.materials.size(); })
        .def_property_readonly("warnings", [](const Scene& s) { return s.warnings; })
        .def_property_readonly("files_read", [](const Scene& s) { return s.sources.files_read; });

    m.def(
        "load",
        [](const std::filesystem::path& file, const std::vector<std::filesystem::path>& allow_read,
           std::optional<std::int64_t> max_file_size, std::optional<std::int64_t> max_pixels,
           std::optional<int> max_samples, std::optional<int> max_ray_depth) {
            const LoadOptions options =
                load_options(allow_read, max_file_size, max_pixels, max_samples, max_ray_depth);
            const py::gil_scoped_release unlocked;
            return std::make_shared<Scene>(load_scene(file, options));
        },
        py::arg("file"), py::arg("allow_read"), py::arg("max_file_size"), py::arg("max_pixels"),
        py::arg("max_samples"), py::arg("max_ray_depth"));
    m.def(
        "parse",
        [](const std::string& text, const std::filesystem::path& as_file,
           const std::vector<std::filesystem::path>& allow_read,
           std::optional<std::int64_t> max_file_size, std::optional<std::int64_t> max_pixels,
           std::optional<int> max_samples, std::optional<int> max_ray_depth) {
            const LoadOptions options =
                load_options(allow_read, max_file_size, max_pixels, max_samples, max_ray_depth);
            const py::gil_scoped_release unlocked;
            return std::make_shared<Scene>(parse_scene_text(text, as_file, options));
        },
        py::arg("text"), py::arg("as_file"), py::arg("allow_read"), py::arg("max_file_size"),
        py::arg("max_pixels"), py::arg("max_samples"), py::arg("max_ray_depth"));
}

}  // namespace glint::python
