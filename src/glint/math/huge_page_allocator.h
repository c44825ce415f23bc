// An allocator for glint's large flat arrays (shapes, parsed objects, BVH nodes and blocks):
// blocks of 2 MiB or more are mapped on 2 MiB boundaries and marked for transparent huge pages,
// so that filling one takes a page fault per 2 MiB instead of one per 4 KiB (Embree does the same
// for its BVHs). The SPD lattice-s40, 270,000 shapes: 73,000 page faults down to 15,000, the whole
// run 15% faster (bench/README.md). Smaller blocks, and every block in sanitizer builds, come from
// operator new.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace glint {

// At least `bytes`, aligned to `alignment`; throws std::bad_alloc.
void* allocate_large(std::size_t bytes, std::size_t alignment);
// Frees what allocate_large(bytes, alignment) returned.
void deallocate_large(void* p, std::size_t bytes, std::size_t alignment) noexcept;

template <typename T>
struct HugePageAllocator {
    using value_type = T;

    HugePageAllocator() = default;
    template <typename U>
    HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
        return static_cast<T*>(allocate_large(n * sizeof(T), alignof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept {
        deallocate_large(p, n * sizeof(T), alignof(T));
    }

    template <typename U>
    bool operator==(const HugePageAllocator<U>&) const noexcept {
        return true;  // stateless: any one frees what another allocated
    }
};

// A std::vector whose storage, once large, sits on huge pages.
template <typename T>
using LargeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace glint
