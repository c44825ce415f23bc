#include "render_slots.h"

#include <chrono>

namespace glint::serve {

bool RenderSlots::acquire(const std::function<bool()>& give_up) {
    std::unique_lock lock(mutex_);
    while (free_ == 0) {
        if (give_up()) return false;
        freed_.wait_for(lock, std::chrono::milliseconds(50));
    }
    if (give_up()) return false;
    --free_;
    return true;
}

void RenderSlots::release() {
    {
        const std::lock_guard lock(mutex_);
        ++free_;
    }
    freed_.notify_all();
}

}  // namespace glint::serve
