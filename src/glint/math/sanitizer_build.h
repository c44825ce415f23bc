// Whether this build runs under AddressSanitizer or ThreadSanitizer: GCC says so with
// __SANITIZE_ADDRESS__ and __SANITIZE_THREAD__, clang 14 only through __has_feature.
#pragma once

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define GLINT_UNDER_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define GLINT_UNDER_SANITIZER 1
#endif
#endif
