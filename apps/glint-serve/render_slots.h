// How many renders may run at once across all pages: each takes every core, so more than a
// few only share them more thinly, and each holds a world in memory.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>

namespace glint::serve {

class RenderSlots {
public:
    explicit RenderSlots(int slots) : free_(slots) {}

    // Waits for a free slot; gives up (returning false) as soon as `give_up` says so, which is
    // asked whenever nudge() is called and every few hundredths of a second.
    bool acquire(const std::function<bool()>& give_up);
    void release();
    // Wakes the waiters to ask their give_up again.
    void nudge() { freed_.notify_all(); }

private:
    std::mutex mutex_;
    std::condition_variable freed_;
    int free_;
};

// A slot held for a scope.
class SlotHold {
public:
    explicit SlotHold(RenderSlots& slots) : slots_(slots) {}
    ~SlotHold() { slots_.release(); }
    SlotHold(const SlotHold&) = delete;
    SlotHold& operator=(const SlotHold&) = delete;

private:
    RenderSlots& slots_;
};

}  // namespace glint::serve
