// Large blocks mapped on 2 MiB boundaries with MADV_HUGEPAGE (Linux); operator new elsewhere.
#include "glint/math/huge_page_allocator.h"

#include <cstdint>

#include "glint/math/sanitizer_build.h"

#if defined(__linux__) && !defined(GLINT_UNDER_SANITIZER)
#include <sys/mman.h>
#define GLINT_HUGE_PAGES 1
#endif

namespace glint {

namespace {

#ifdef GLINT_HUGE_PAGES
constexpr std::size_t kHugePage = std::size_t(2) << 20;

std::size_t round_up(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

// Which blocks are mapped by hand; the others come from operator new.
bool on_huge_pages(std::size_t bytes, std::size_t alignment) {
    return bytes >= kHugePage && alignment <= kHugePage;
}
#endif

}  // namespace

void* allocate_large(std::size_t bytes, std::size_t alignment) {
    // No object is larger than PTRDIFF_MAX bytes: refused here, in every build (a sanitizer's
    // operator new aborts on such a size instead of throwing).
    if (bytes > std::size_t(PTRDIFF_MAX)) throw std::bad_alloc();
#ifdef GLINT_HUGE_PAGES
    if (on_huge_pages(bytes, alignment)) {
        const std::size_t size = round_up(bytes);
        // One huge page more than needed, so that a 2 MiB boundary lies in the first; the slack
        // on both sides goes back at once.
        void* mapped = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE,
                            MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (mapped == MAP_FAILED) throw std::bad_alloc();
        const auto begin = reinterpret_cast<std::uintptr_t>(mapped);
        const std::uintptr_t start = round_up(begin);
        if (start > begin) munmap(mapped, start - begin);
        if (const std::size_t after = begin + kHugePage - start; after > 0)
            munmap(reinterpret_cast<void*>(start + size), after);
        // Advice only: where transparent huge pages are off, the block keeps small pages.
        madvise(reinterpret_cast<void*>(start), size, MADV_HUGEPAGE);
        return reinterpret_cast<void*>(start);
    }
#endif
    return ::operator new(bytes, std::align_val_t(alignment));
}

void deallocate_large(void* p, [[maybe_unused]] std::size_t bytes, std::size_t alignment) noexcept {
#ifdef GLINT_HUGE_PAGES
    if (on_huge_pages(bytes, alignment)) {
        munmap(p, round_up(bytes));
        return;
    }
#endif
    ::operator delete(p, std::align_val_t(alignment));
}

}  // namespace glint
