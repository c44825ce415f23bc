// Where a render's wall time goes outside the render itself, for --stats: loading the scene,
// building its world (the acceleration structures, the lights' lists), writing the files, and
// the whole process so far. The parts outside the render are what a small scene's time is made
// of (bench/README.md).
#pragma once

#include <chrono>
#include <optional>

namespace glint::cli {

struct PhaseTimes {
    std::optional<double> load, build, write;  // seconds; none where this process did not do it
};

// Seconds since glint started (since its static objects were made, before main()).
double process_seconds();

// Seconds since it was made.
class Stopwatch {
public:
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace glint::cli
