// Shows a render's progress while it runs: a bar with an ETA on a terminal, plain periodic
// lines otherwise. Also turns Ctrl-C into a request to stop.
#pragma once

#include <atomic>
#include <thread>

#include "glint/render/render.h"

namespace glint::cli {

class ProgressWatcher {
public:
    // Starts watching at once. With show == false it only relays Ctrl-C.
    ProgressWatcher(RenderProgress& progress, bool show);
    ~ProgressWatcher();  // stops watching and ends the bar's line

    ProgressWatcher(const ProgressWatcher&) = delete;
    ProgressWatcher& operator=(const ProgressWatcher&) = delete;

private:
    void run();

    RenderProgress& progress_;
    bool show_;
    bool terminal_;
    std::atomic<bool> done_{false};
    std::thread thread_;
};

}  // namespace glint::cli
