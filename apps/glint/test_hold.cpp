// The test hold: the threads that finish a tile past the N-th wait, polling the stop flags, and
// the first of them says so on stderr, which is what a test waits for before its signal.
#include "test_hold.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>

#include "usage_error.h"

namespace glint::cli {

namespace {

constexpr const char* kVariable = "GLINT_TEST_HOLD_AFTER_TILES";
// A hold whose signal never comes (a test that died) ends after this, and the render goes on.
constexpr std::chrono::minutes kLongestHold{2};

}  // namespace

std::function<void(int)> test_hold_from_environment(const RenderProgress& progress) {
    const char* value = std::getenv(kVariable);
    if (!value) return {};
    char* end = nullptr;
    const long tiles = std::strtol(value, &end, 10);
    if (end == value || *end != '\0' || tiles < 1 || tiles > 1'000'000'000)
        throw UsageError{std::string(kVariable) +
                         " must be a whole number of tiles from 1, got \"" + value + "\""};
    auto announced = std::make_shared<std::atomic<bool>>(false);
    return [&progress, tiles, announced](int finished) {
        if (finished < tiles) return;
        if (!announced->exchange(true)) {
            std::fprintf(stderr, "glint: holding after %ld tiles (%s)\n", tiles, kVariable);
            std::fflush(stderr);
        }
        const auto give_up = std::chrono::steady_clock::now() + kLongestHold;
        while (!progress.stop_after_pass && !progress.cancel &&
               std::chrono::steady_clock::now() < give_up)
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
    };
}

}  // namespace glint::cli
