// Whether the tests run under AddressSanitizer or ThreadSanitizer, which make code 5 to 50 times
// slower: the slowest property tests then check fewer random cases of the same kinds, so that
// the whole suite runs under the sanitizers on every CI run.
#pragma once

namespace glint::testing {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kUnderSanitizer = true;
#else
inline constexpr bool kUnderSanitizer = false;
#endif

}  // namespace glint::testing
