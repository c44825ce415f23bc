// The ray tree of one sample from Python: as `glint explain --format json` gives it, which the
// package turns into nested dicts.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <memory>
#include <string>

#include "bindings.h"
#include "glint/render/explain/explain.h"
#include "glint/render/explain/ray_tree_formats.h"
#include "glint/render/world.h"
#include "glint/scene/integrator_fit.h"
#include "glint/scene/setting_overrides.h"
#include "overrides_arg.h"

namespace py = pybind11;

namespace glint::python {

void bind_explain(py::module_& m) {
    m.def(
        "explain_json",
        [](const std::shared_ptr<const Scene>& scene_data, int x, int y, int sample,
           std::uint64_t seed, const py::dict& overrides) {
            Scene scene = *scene_data;
            apply_setting_overrides(overrides_from(overrides), scene.settings);
            check_integrator_fits(scene);
            const PixelSample which{x, y, sample, seed};
            check_explainable(scene.settings, which);
            const py::gil_scoped_release unlocked;
            const World world(std::move(scene));
            return ray_tree_json(explain(world, which));
        },
        py::arg("scene"), py::arg("x"), py::arg("y"), py::arg("sample"), py::arg("seed"),
        py::arg("overrides"));
}

}  // namespace glint::python
