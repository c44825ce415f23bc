#include "phase_times.h"

namespace glint::cli {

namespace {
const Stopwatch process_clock;  // made before main() runs
}  // namespace

double process_seconds() { return process_clock.seconds(); }

}  // namespace glint::cli
