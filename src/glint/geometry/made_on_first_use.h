// Per-ray state that only some rays need (a block tester, say), made the first time it is asked
// for: no heap, and, unlike std::optional, no zero-filling of its storage on every ray.
#pragma once

#include <new>
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

}  // namespace glint
