// A render from Python: the settings checked as the command line checks them, the world built
// and rendered by the library's render job on a thread of its own while this one, without the
// GIL, wakes every few hundredths of a second to report progress and to look for Ctrl-C
// (KeyboardInterrupt cancels the job) or an exception from the progress callback.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "bindings.h"
#include "glint/accel/make_aggregate.h"
#include "glint/render/memory_estimate.h"
#include "glint/render/render_choices.h"
#include "glint/render/render_job.h"
#include "glint/render/world.h"
#include "glint/scene/integrator_fit.h"
#include "glint/scene/integrators.h"
#include "glint/scene/setting_overrides.h"
#include "image_arrays.h"
#include "overrides_arg.h"

namespace py = pybind11;

namespace glint::python {

namespace {

AovSet aov_set(const std::vector<std::string>& names, IntegratorKind integrator) {
    if (names.empty()) return {};
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ",") + name;
    return aovs_named(list, integrator);
}

// Runs the job on a thread of its own; the calling thread, holding the GIL only between waits,
// reports progress and stops the job for Ctrl-C or a failing callback.
RenderResult run_job(RenderJob& job, const py::object& progress) {
    std::mutex mutex;
    std::condition_variable finished_signal;
    bool finished = false;
    RenderResult result;
    std::exception_ptr failure;
    std::thread worker([&] {
        try {
            result = job.run();
        } catch (...) {
            failure = std::current_exception();
        }
        const std::lock_guard lock(mutex);
        finished = true;
        finished_signal.notify_one();
    });
    const auto stop = [&] {
        job.cancel();
        const py::gil_scoped_release unlocked;
        worker.join();
    };
    int reported = -1;
    while (true) {
        bool done = false;
        {
            const py::gil_scoped_release unlocked;
            std::unique_lock lock(mutex);
            done = finished_signal.wait_for(lock, std::chrono::milliseconds(40),
                                            [&] { return finished; });
        }
        if (PyErr_CheckSignals() != 0) {
            stop();
            throw py::error_already_set();
        }
        const int tiles_done = job.progress().tiles_done, tiles_total = job.progress().tiles_total;
        if (!progress.is_none() && tiles_done != reported && tiles_total > 0) {
            reported = tiles_done;
            try {
                progress(tiles_done, tiles_total);
            } catch (...) {
                stop();
                throw;
            }
        }
        if (done) break;
    }
    worker.join();
    if (failure) std::rethrow_exception(failure);
    return result;
}

py::object render(const std::shared_ptr<const Scene>& scene_data, const SettingOverrides& overrides,
                  std::uint64_t seed, int threads, const std::vector<std::string>& aov_names,
                  const std::string& accel_name, const py::object& progress) {
    check_whole_number("threads", threads, 0, 4096);
    Scene scene = *scene_data;
    apply_setting_overrides(overrides, scene.settings);
    check_integrator_fits(scene);
    const AovSet aovs = aov_set(aov_names, scene.settings.integrator);
    const AccelKind accel = accel_named(accel_name);
    const MemoryEstimate need = estimate_render_memory(scene, accel, RenderExtras{.aovs = aovs});
    if (auto refusal = memory_refusal(scene, accel, need, std::nullopt, "max_memory")) {
        PyErr_SetString(PyExc_MemoryError, refusal->c_str());
        throw py::error_already_set();
    }
    RenderOptions options;
    options.threads = threads;
    options.seed = seed;
    options.aovs = aovs;
    std::optional<World> world;
    {
        const py::gil_scoped_release unlocked;
        world.emplace(std::move(scene), accel);
    }
    RenderJob job(*world, options);
    const RenderResult result = run_job(job, progress);
    py::object image = image_array(result.image, 3);
    if (aov_names.empty()) return image;
    py::dict layers;
    for (const AovImage& layer : result.aovs) {
        const AovInfo& info = aov_info(layer.aov);
        layers[py::str(std::string(info.name))] = image_array(layer.image, info.channels);
    }
    return py::make_tuple(image, layers);
}

}  // namespace

void bind_render(py::module_& m) {
    m.def(
        "render",
        [](const std::shared_ptr<const Scene>& scene, const py::dict& overrides, std::uint64_t seed,
           int threads, const std::vector<std::string>& aovs, const std::string& accel,
           const py::object& progress) {
            return render(scene, overrides_from(overrides), seed, threads, aovs, accel, progress);
        },
        py::arg("scene"), py::arg("overrides"), py::arg("seed"), py::arg("threads"),
        py::arg("aovs"), py::arg("accel"), py::arg("progress"));
}

}  // namespace glint::python
