// A collector for TBB's threading-tools notifications that hands them to ThreadSanitizer.
// Debian's libtbb is not built with ThreadSanitizer, so the atomics by which it passes tasks
// between threads are invisible to it; but libtbb tells threading tools (through the ITT API)
// where it releases and acquires, and loads the library named by INTEL_LIBITTNOTIFY64 to hear
// it. The tsan preset builds this library and points its tests at it.
#include <sanitizer/tsan_interface.h>

extern "C" {

// Its presence tells libtbb's ITT loader to look up the functions below by name.
__attribute__((visibility("default"))) int __itt_api_version = 1;

__attribute__((visibility("default"))) void __itt_sync_releasing(void* address) {
    __tsan_release(address);
}

__attribute__((visibility("default"))) void __itt_sync_acquired(void* address) {
    __tsan_acquire(address);
}

}  // extern "C"
