// The overrides of a scene's settings as the package passes them: a dict of width, height, spp,
// max_depth (a number or None), integrator, sampler, filter and shadows (a name, "" for the
// scene's). apply_setting_overrides checks them.
#pragma once

#include <pybind11/pybind11.h>

#include "glint/scene/setting_overrides.h"

namespace glint::python {

SettingOverrides overrides_from(const pybind11::dict& given);

}  // namespace glint::python
