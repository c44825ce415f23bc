// Whether the tests run under AddressSanitizer or ThreadSanitizer, which make code 5 to 50 times
// slower: the slowest property tests then check fewer random cases of the same kinds, so that
// the whole suite runs under the sanitizers on every CI run.
#pragma once

#include "glint/math/sanitizer_build.h"

namespace glint::testing {

#ifdef GLINT_UNDER_SANITIZER
inline constexpr bool kUnderSanitizer = true;
#else
inline constexpr bool kUnderSanitizer = false;
#endif

}  // namespace glint::testing
