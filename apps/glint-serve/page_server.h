// glint-serve's HTTP server (cpp-httplib): the page's files, compiled in, and the endpoints a
// page talks to (docs/serve.md). Each page that opens its event stream gets a live render of its
// own, which ends when the page goes away.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "live_render.h"
#include "render_slots.h"
#include "watched_scene.h"

namespace httplib {
class Server;
}

namespace glint::serve {

struct ServeOptions {
    std::string host = "127.0.0.1";
    int port = 8080;      // 0: any free port
    std::string token;    // asked of every request when not empty (?token=...)
    int max_pages = 16;   // pages open at once, each with its render
    int max_renders = 2;  // renders running at once; the others wait their turn
    std::size_t max_request_bytes = 64 * 1024;
    int threads = 0;  // each render's; 0: all cores
};

class PageServer {
public:
    PageServer(const WatchedScene& scene, ServeOptions options);
    ~PageServer();

    // Binds to the host and port (a free one for port 0) and returns the port; throws
    // std::runtime_error when it cannot.
    int bind();
    // Answers requests until stop(), from another thread or a signal's watcher.
    void listen();
    void stop();

    // Pages open now.
    int pages() const;

private:
    struct Page;
    void add_routes();
    std::shared_ptr<LiveRender> page_of(const std::string& session) const;

    const WatchedScene& scene_;
    ServeOptions options_;
    RenderSlots slots_;
    std::unique_ptr<httplib::Server> server_;
    int port_ = 0;
    mutable std::mutex mutex_;  // over pages_
    std::map<std::string, std::shared_ptr<LiveRender>> pages_;
};

// A random token of 128 bits in hex, for --host.
std::string random_token();

}  // namespace glint::serve
