// Whether the tests run under AddressSanitizer or ThreadSanitizer, which make code 5 to 50 times
// slower: the slowest property tests then check fewer random cases of the same kinds, so that
// the whole suite runs under the sanitizers on every CI run.
#pragma once

namespace glint::testing {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)  // GCC
inline constexpr bool kUnderSanitizer = true;
#elif defined(__has_feature)  // Clang
inline constexpr bool kUnderSanitizer =
    __has_feature(address_sanitizer) || __has_feature(thread_sanitizer);
#else
inline constexpr bool kUnderSanitizer = false;
#endif

}  // namespace glint::testing
