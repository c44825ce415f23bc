// The allocator of the large arrays: small and large blocks, their alignment, and vectors that
// grow across the huge-page threshold.
#include "glint/math/huge_page_allocator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <numeric>

#include "glint/math/sanitizer_build.h"

namespace glint {
namespace {

constexpr std::size_t kMiB = std::size_t(1) << 20;

bool aligned(const void* p, std::size_t alignment) {
    return reinterpret_cast<std::uintptr_t>(p) % alignment == 0;
}

TEST(HugePageAllocator, SmallAndLargeBlocksAreAlignedAndWritable) {
    for (const std::size_t bytes : {std::size_t(1), std::size_t(4096), 2 * kMiB - 1, 2 * kMiB,
                                    2 * kMiB + 1, 5 * kMiB + 123}) {
        for (const std::size_t alignment : {std::size_t(1), std::size_t(16), std::size_t(64)}) {
            void* p = allocate_large(bytes, alignment);
            ASSERT_NE(p, nullptr);
            EXPECT_TRUE(aligned(p, alignment)) << bytes << " bytes";
            std::memset(p, 0xab, bytes);  // every byte is ours
            EXPECT_EQ(static_cast<unsigned char*>(p)[bytes - 1], 0xab);
            deallocate_large(p, bytes, alignment);
        }
    }
}

#if defined(__linux__) && !defined(GLINT_UNDER_SANITIZER)
TEST(HugePageAllocator, LargeBlocksStartOnTwoMebibyteBoundaries) {
    for (const std::size_t bytes : {2 * kMiB, 3 * kMiB, 9 * kMiB + 7}) {
        void* p = allocate_large(bytes, 8);
        EXPECT_TRUE(aligned(p, 2 * kMiB)) << bytes << " bytes";
        deallocate_large(p, bytes, 8);
    }
}
#endif

TEST(HugePageAllocator, VectorsGrowAcrossTheThresholdAndKeepTheirContents) {
    LargeVector<std::uint32_t> v;
    const std::uint32_t n = 3 * (1u << 20);  // 12 MiB, through several reallocations
    for (std::uint32_t i = 0; i < n; ++i) v.push_back(i);
    std::uint64_t sum = std::accumulate(v.begin(), v.end(), std::uint64_t(0));
    EXPECT_EQ(sum, std::uint64_t(n) * (n - 1) / 2);
    LargeVector<std::uint32_t> copy = v;  // allocators compare equal: copies and moves just work
    LargeVector<std::uint32_t> moved = std::move(v);
    EXPECT_EQ(copy, moved);
    moved.clear();
    moved.shrink_to_fit();  // frees the large block
    EXPECT_EQ(moved.capacity(), 0u);
}

TEST(HugePageAllocator, ImpossibleSizesThrowBadAlloc) {
    HugePageAllocator<double> allocator;
    EXPECT_THROW(static_cast<void>(allocator.allocate(std::size_t(-1) / 4)), std::bad_alloc);
    EXPECT_THROW(allocate_large(std::size_t(-1) - kMiB, 8), std::bad_alloc);
}

}  // namespace
}  // namespace glint
