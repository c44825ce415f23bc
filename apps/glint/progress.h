// Shows a render's progress while it runs: a bar with an ETA on a terminal, plain periodic
// lines otherwise. Also turns Ctrl-C and SIGTERM into requests to stop: the first after the pass
// in flight, the second after the tiles in flight.
#pragma once

#include <atomic>
#include <condition_variable>
#include <csignal>
#include <mutex>
#include <thread>

#include "glint/render/render.h"

namespace glint::cli {

class ProgressWatcher {
public:
    // Starts watching at once. With show == false it only relays Ctrl-C and SIGTERM.
    ProgressWatcher(RenderProgress& progress, bool show);
    ~ProgressWatcher();  // stops watching and ends the bar's line

    ProgressWatcher(const ProgressWatcher&) = delete;
    ProgressWatcher& operator=(const ProgressWatcher&) = delete;

private:
    void run();

    RenderProgress& progress_;
    bool show_;
    bool terminal_;
    // The watcher waits on this between updates, so that the end of the render wakes it at once
    // (a plain sleep kept every render waiting for the rest of the interval: up to 0.1 s).
    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false;  // guarded by mutex_
    std::thread thread_;
    // Put back when the watcher goes.
    void (*previous_sigint_)(int) = SIG_DFL;
    void (*previous_sigterm_)(int) = SIG_DFL;
};

}  // namespace glint::cli
