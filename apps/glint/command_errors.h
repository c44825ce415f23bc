// How every verb reports what stops it: the message on standard error, and the exit status
// (docs/cli.md#exit-status): 2 for bad input (a scene error at its file, line and column, bad
// usage, a resume file of another render), 1 for any other failure.
#pragma once

#include <functional>

namespace glint::cli {

inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

// run()'s exit status, or the status of what it threw, reported.
int reporting_errors(const std::function<int()>& run);

}  // namespace glint::cli
