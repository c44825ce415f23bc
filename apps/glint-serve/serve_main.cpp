// glint-serve SCENE: a page in the browser on which the scene renders progressively, the camera
// moves with the mouse and a click shows a pixel's ray tree (docs/serve.md). It listens on
// 127.0.0.1 unless told otherwise, and then asks for a token in the URL.
#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>
#include <thread>

#include "command_errors.h"
#include "page_server.h"
#include "scene_read_options.h"
#include "usage_error.h"
#include "whole_number_option.h"

#ifndef GLINT_VERSION
#define GLINT_VERSION "unknown"
#endif

namespace {

// Set by SIGINT and SIGTERM; the watcher thread then stops the server.
volatile std::sig_atomic_t stop_asked = 0;

extern "C" void ask_to_stop(int) { stop_asked = 1; }

constexpr const char* kExamples = R"(
Examples:
  glint-serve scenes/showcase.yaml              then open http://127.0.0.1:8080/
  glint-serve scene.yaml --port 9000 --threads 2
  glint-serve scene.yaml --host 0.0.0.0         other machines too, with the printed token
)";

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"glint-serve: a page in the browser to look into a render"};
    app.footer(kExamples);
    app.set_version_flag("--version", std::string("glint-serve ") + GLINT_VERSION);
    std::string scene;
    glint::serve::ServeOptions options;
    glint::cli::SceneReadOptions reading;
    app.add_option("scene", scene, "Scene file, as for glint render")->required();
    app.add_option("--port", options.port, "Port to listen on (0: any free one)")
        ->check(glint::cli::whole_number(0, 65535))
        ->capture_default_str();
    app.add_option("--host", options.host,
                   "Address to listen on; anything but 127.0.0.1 lets other machines in, so a "
                   "random token is then asked for in the URL")
        ->capture_default_str();
    app.add_option("--threads", options.threads, "Threads of each render (0: all cores)")
        ->check(glint::cli::whole_number(0, 4096));
    app.add_option("--max-pages", options.max_pages, "Pages open at once, each with its render")
        ->check(glint::cli::whole_number(1, 256))
        ->capture_default_str();
    app.add_option("--max-renders", options.max_renders,
                   "Renders running at once; further pages wait their turn")
        ->check(glint::cli::whole_number(1, 64))
        ->capture_default_str();
    glint::cli::add_scene_read_options(app, reading);
    CLI11_PARSE(app, argc, argv);

    return glint::cli::reporting_errors([&] {
        if (options.host != "127.0.0.1") {
            options.token = glint::serve::random_token();
            std::fprintf(stderr,
                         "glint-serve: warning: listening on %s lets other machines in; each "
                         "request must carry the token of the URL below\n",
                         options.host.c_str());
        }
        glint::serve::WatchedScene watched(scene, reading.load_options());
        glint::serve::PageServer server(watched, options);
        int port = 0;
        try {
            port = server.bind();
        } catch (const std::runtime_error& e) {
            throw glint::cli::UsageError{e.what()};
        }
        const std::string host = options.host == "0.0.0.0" ? "127.0.0.1" : options.host;
        std::printf("glint-serve: http://%s:%d/%s%s\n", host.c_str(), port,
                    options.token.empty() ? "" : "?token=", options.token.c_str());
        std::fflush(stdout);
        std::signal(SIGINT, ask_to_stop);
        std::signal(SIGTERM, ask_to_stop);
        // The scene's files looked at four times a second, and a stop asked for.
        std::atomic<bool> serving{true};
        std::thread watcher([&] {
            for (int tick = 0; serving; ++tick) {
                if (stop_asked) server.stop();
                if (tick % 5 == 0) watched.reload_if_changed();
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
            }
        });
        server.listen();
        serving = false;
        watcher.join();
        std::fprintf(stderr, "glint-serve: stopped\n");
        return 0;
    });
}
