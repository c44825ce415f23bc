// Per-ray state that only some rays need (a block tester, say), made the first time it is asked
// for: no heap, and, unlike std::optional, no zero-filling of its storage on every ray.
#pragma once

#include <cstddef>
#include <new>
#include <span>
#include <type_traits>

namespace glint {

template <typename T, typename Arg>
class MadeOnFirstUse {
    static_assert(std::is_trivially_destructible_v<T>, "never destroyed");

public:
    explicit MadeOnFirstUse(const Arg& arg) : arg_(arg) {}
    MadeOnFirstUse(const MadeOnFirstUse&) = delete;
    MadeOnFirstUse& operator=(const MadeOnFirstUse&) = delete;

    const T& get() {
        if (!made_) {
            new (bytes_) T(arg_);
            made_ = true;
        }
        return *std::launder(reinterpret_cast<const T*>(bytes_));
    }

private:
    const Arg& arg_;
    bool made_ = false;
    alignas(T) unsigned char bytes_[sizeof(T)];
};

// The same for each of up to N rays traced together (a packet's), each made when its own ray
// first asks: a ray that reaches no leaf needs none.
template <typename T, typename Arg, std::size_t N>
class EachMadeOnFirstUse {
    static_assert(std::is_trivially_destructible_v<T>, "never destroyed");
    static_assert(N <= 32, "one bit of made_ each");

public:
    explicit EachMadeOnFirstUse(std::span<const Arg> args) : args_(args) {}
    EachMadeOnFirstUse(const EachMadeOnFirstUse&) = delete;
    EachMadeOnFirstUse& operator=(const EachMadeOnFirstUse&) = delete;

    const T& get(std::size_t i) {
        if ((made_ >> i & 1) == 0) {
            new (bytes_[i]) T(args_[i]);
            made_ |= 1u << i;
        }
        return *std::launder(reinterpret_cast<const T*>(bytes_[i]));
    }

private:
    std::span<const Arg> args_;
    unsigned made_ = 0;  // bit i: element i is made
    alignas(T) unsigned char bytes_[N][sizeof(T)];
};

}  // namespace glint
