// The progress watcher: a thread that wakes every 100 ms to redraw the bar (or print a plain line
// per tenth of the work) and to pass Ctrl-C and SIGTERM, counted by a signal handler, on as a
// stop after the pass in flight (the first) and a stop now (the second).
#include "progress.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>

namespace glint::cli {

namespace {

// Counted by the handler on the main thread and read by the watcher's: a lock-free atomic, which
// a signal handler may change (a volatile sig_atomic_t is safe only within one thread).
std::atomic<int> g_interrupts = 0;
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_interrupt(int) { g_interrupts.fetch_add(1); }

std::string format_duration(double seconds) {
    const long s = static_cast<long>(seconds + 0.5);
    char buffer[32];
    if (s >= 3600)
        std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else
        std::snprintf(buffer, sizeof buffer, "%ld:%02ld", s / 60, s % 60);
    return buffer;
}

}  // namespace

ProgressWatcher::ProgressWatcher(RenderProgress& progress, bool show)
    : progress_(progress), show_(show), terminal_(isatty(STDERR_FILENO) != 0) {
    g_interrupts = 0;
    previous_sigint_ = std::signal(SIGINT, on_interrupt);
    previous_sigterm_ = std::signal(SIGTERM, on_interrupt);
    thread_ = std::thread([this] { run(); });
}

ProgressWatcher::~ProgressWatcher() {
    {
        const std::lock_guard lock(mutex_);
        done_ = true;
    }
    wake_.notify_one();
    thread_.join();
    std::signal(SIGINT, previous_sigint_);
    std::signal(SIGTERM, previous_sigterm_);
}

void ProgressWatcher::run() {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    int last_reported_tenth = 0;
    bool drew_bar = false;
    double start_fraction = -1;  // a continued render starts part done: the ETA counts from there
    for (;;) {
        {
            std::unique_lock lock(mutex_);
            if (wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return done_; }))
                break;
        }
        // A render of one pass would finish whole after the first: it stops at once instead.
        const int interrupts = g_interrupts;
        const bool one_pass = progress_.passes_total <= 1;
        if (interrupts >= 1 && !progress_.stop_after_pass) {
            progress_.stop_after_pass = true;
            if (show_ && !one_pass)
                std::fprintf(stderr,
                             "%sglint: stopping after the pass in flight (%d of %d); interrupt "
                             "again to stop after the tiles in flight\n",
                             drew_bar ? "\n" : "", progress_.passes_done + 1,
                             progress_.passes_total.load());
        }
        if (interrupts >= 2 || (interrupts >= 1 && one_pass)) progress_.cancel = true;
        const int total = progress_.tiles_total;
        if (!show_ || total == 0) continue;
        const double fraction = double(progress_.tiles_done) / total;
        if (start_fraction < 0) start_fraction = fraction;
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        const std::string eta =
            fraction > start_fraction
                ? format_duration(elapsed * (1 - fraction) / (fraction - start_fraction))
                : "?";
        if (terminal_) {
            constexpr int kWidth = 30;
            const int filled = static_cast<int>(fraction * kWidth);
            std::fprintf(
                stderr, "\r[%s%s] %3d%%  elapsed %s  ETA %s ", std::string(filled, '#').c_str(),
                std::string(kWidth - filled, ' ').c_str(), static_cast<int>(fraction * 100),
                format_duration(elapsed).c_str(), eta.c_str());
            drew_bar = true;
        } else if (const int tenth = static_cast<int>(fraction * 10);
                   tenth > last_reported_tenth && tenth < 10) {
            // Plain lines for logs: one per tenth of the work, and only after a second.
            if (elapsed >= 1) {
                std::fprintf(stderr, "glint: %d%% done, elapsed %s, ETA %s\n", tenth * 10,
                             format_duration(elapsed).c_str(), eta.c_str());
                last_reported_tenth = tenth;
            }
        }
        std::fflush(stderr);
    }
    if (drew_bar) std::fprintf(stderr, "\r%*s\r", 70, "");
}

}  // namespace glint::cli
