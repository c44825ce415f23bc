// A hold for the tests of Ctrl-C and resume: with GLINT_TEST_HOLD_AFTER_TILES=N in the
// environment, the render stops taking tiles after N of them until it is told to stop (Ctrl-C,
// SIGTERM) or killed, so that a signal always finds it running however fast the machine is.
#pragma once

#include <functional>

#include "glint/render/render.h"

namespace glint::cli {

// The after_tile hook that holds, or an empty function when the variable is not set. Throws
// UsageError for a value that is not a whole number from 1 up.
std::function<void(int)> test_hold_from_environment(const RenderProgress& progress);

}  // namespace glint::cli
