// Mailboxing for structures that list one primitive in many cells or leaves: a tiny
// direct-mapped cache of recently tested primitive ids that lives on one query's stack.
#pragma once

#include <array>
#include <cstdint>

namespace glint {

// Amanatides and Woo (1987) keep a "mailbox" ray id in each primitive; that writes to shared
// data and so needs one mailbox per thread. Here the memory is on the other side: each query
// owns kSlots slots, slot (id mod kSlots) holding the last id tested there. A hit in the cache
// means "already tested with this ray"; a collision only evicts an id, which can then be tested
// twice but never skipped wrongly. No allocation, no shared writes, safe on many threads.
class Mailbox {
public:
    static constexpr std::uint32_t kSlots = 16;  // a power of two; 64 bytes, one cache line
    // No primitive has this id: aggregates hold fewer than 2^32 - 1 primitives.
    static constexpr std::uint32_t kEmpty = 0xffffffffu;

    Mailbox() { slots_.fill(kEmpty); }

    // True the first time `id` is seen (or since it was evicted); false when it was tested
    // already with this query and may be skipped.
    bool first_visit(std::uint32_t id) {
        std::uint32_t& slot = slots_[id & (kSlots - 1)];
        if (slot == id) return false;
        slot = id;
        return true;
    }

private:
    std::array<std::uint32_t, kSlots> slots_;
};

}  // namespace glint
