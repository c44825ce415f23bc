// Bad usage found after parsing (an option that contradicts the scene, an unwritable output):
// the verbs report its message and exit with status 2.
#pragma once

#include <string>

namespace glint::cli {

struct UsageError {
    std::string message;
};

}  // namespace glint::cli
