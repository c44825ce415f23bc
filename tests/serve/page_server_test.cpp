// glint-serve's server on a free port: each endpoint, the page's files and nothing beside them,
// the Host check and the token, oversized requests, the event stream's frames to the image of a
// render, live editing, a page that leaves mid-render, and twenty pages at once.
#include "page_server.h"

#include <gtest/gtest.h>
#include <httplib.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "glint/image/exr_io.h"
#include "glint/image/png_io.h"
#include "glint/render/explain/explain.h"
#include "glint/render/explain/ray_tree_formats.h"
#include "glint/render/film/aov_picture.h"
#include "glint/render/render.h"
#include "glint/render/world.h"
#include "glint/scene/load_scene.h"

namespace glint::serve {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// Small enough to render in a blink, with a shadow and a mirror.
std::string scene_text(const std::string& color = "[0.8, 0.3, 0.2]", int spp = 4) {
    return "image: {width: 64, height: 48, samples: " + std::to_string(spp) +
           ", max_depth: 4}\n"
           "camera: {from: [0, 1, -5], at: [0, 0.5, 0], up: [0, 1, 0], fov: 45}\n"
           "lights:\n  - {type: point, position: [3, 5, -3], color: [1, 1, 1]}\n"
           "materials:\n  red: {color: " +
           color +
           ", kd: 0.7, ks: 0.3, shininess: 40, reflect: 0.2}\n"
           "objects:\n"
           "  - {type: sphere, center: [0, 0.5, 0], radius: 0.5, material: red}\n"
           "  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: red}\n";
}

void write_file(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// A scene file of its own, and a server for it on a free port, answering on a thread.
class Served {
public:
    explicit Served(const std::string& name, ServeOptions options = {},
                    const std::string& text = scene_text())
        : folder_(fs::path(GLINT_TEST_OUTPUT_DIR) / ("serve_" + name)) {
        fs::remove_all(folder_);
        fs::create_directories(folder_);
        write_file(scene_file(), text);
        scene_ = std::make_unique<WatchedScene>(scene_file(), LoadOptions{});
        options.port = 0;
        server_ = std::make_unique<PageServer>(*scene_, options);
        port_ = server_->bind();
        thread_ = std::thread([this] { server_->listen(); });
    }
    ~Served() {
        server_->stop();
        thread_.join();
    }
    fs::path scene_file() const { return folder_ / "scene.yaml"; }
    WatchedScene& scene() { return *scene_; }
    PageServer& server() { return *server_; }
    httplib::Client client() const {
        httplib::Client c("127.0.0.1", port_);
        c.set_read_timeout(30, 0);
        return c;
    }
    int port() const { return port_; }

private:
    fs::path folder_;
    std::unique_ptr<WatchedScene> scene_;
    std::unique_ptr<PageServer> server_;
    int port_ = 0;
    std::thread thread_;
};

struct Event {
    std::string name, data;
};

// The value of a JSON number or string field, found by its key (enough for these tests).
std::string field(const std::string& json, const std::string& key) {
    const std::string quoted = "\"" + key + "\": ";
    const std::size_t at = json.find(quoted);
    if (at == std::string::npos) return "";
    std::size_t begin = at + quoted.size(), end = begin;
    if (json[begin] == '"') return json.substr(begin + 1, json.find('"', begin + 1) - begin - 1);
    while (end < json.size() && json[end] != ',' && json[end] != '}') ++end;
    return json.substr(begin, end - begin);
}

// Reads a page's event stream on a thread, until `enough` says so or the stream ends.
class EventStream {
public:
    EventStream(const Served& served, std::function<bool(const std::vector<Event>&)> enough,
                const std::string& path = "/events")
        : enough_(std::move(enough)) {
        thread_ = std::thread([this, &served, path] {
            httplib::Client client = served.client();
            std::string buffer;
            const auto result = client.Get(
                path,
                [&](const httplib::Response& r) {
                    status_ = r.status;
                    return true;
                },
                [&](const char* data, std::size_t size) {
                    buffer.append(data, size);
                    for (std::size_t end; (end = buffer.find("\n\n")) != std::string::npos;) {
                        const std::string block = buffer.substr(0, end);
                        buffer.erase(0, end + 2);
                        if (block.starts_with(":")) continue;
                        Event event;
                        event.name = block.substr(7, block.find('\n') - 7);
                        event.data = block.substr(block.find("data: ") + 6);
                        const std::lock_guard lock(mutex_);
                        events_.push_back(event);
                        if (enough_(events_) || leave_) return false;
                    }
                    return !leave_;
                });
            if (result && status_ == 0) status_ = result->status;
            done_ = true;
        });
    }
    ~EventStream() { join(); }
    // Waits for the stream to end; one that has not ended in two minutes fails the test, with
    // the last event seen, and is left (its next keep-alive ends it).
    void join() {
        if (!thread_.joinable()) return;
        const auto end = std::chrono::steady_clock::now() + 120s;
        while (!done_ && !leave_ && std::chrono::steady_clock::now() < end)
            std::this_thread::sleep_for(5ms);
        if (!done_ && !leave_) {
            const std::vector<Event> seen = events();
            ADD_FAILURE() << "the event stream did not end; " << seen.size() << " events, the last "
                          << (seen.empty() ? "none" : seen.back().name + " " + seen.back().data);
            leave_ = true;
        }
        thread_.join();
    }
    void leave() { leave_ = true; }
    std::vector<Event> events() {
        const std::lock_guard lock(mutex_);
        return events_;
    }
    // The session, once the hello came.
    std::string session() {
        for (int i = 0; i < 3000; ++i) {
            for (const Event& e : events())
                if (e.name == "hello") return field(e.data, "session");
            if (done_) break;
            std::this_thread::sleep_for(1ms);
        }
        return "";
    }
    int status() const { return status_; }
    bool done() const { return done_; }

private:
    std::function<bool(const std::vector<Event>&)> enough_;
    std::mutex mutex_;
    std::vector<Event> events_;
    std::atomic<int> status_{0};
    std::atomic<bool> done_{false}, leave_{false};
    std::thread thread_;
};

// A frame event of the full view, all its passes done, of at least `version`.
bool finished_frame(const Event& e, int version = 0) {
    return e.name == "frame" && field(e.data, "preview") == "false" &&
           field(e.data, "error") == "null" &&
           field(e.data, "passes_done") == field(e.data, "passes_total") &&
           std::stoi(field(e.data, "version")) >= version;
}

auto until_finished(int version = 0) {
    return [version](const std::vector<Event>& events) {
        return !events.empty() && finished_frame(events.back(), version);
    };
}

Image rendered(const fs::path& file, const SettingOverrides& overrides = {}) {
    Scene scene = load_scene(file);
    apply_setting_overrides(overrides, scene.settings);
    const World world(std::move(scene));
    return render(world, RenderOptions{}).image;
}

bool wait_until(const std::function<bool()>& condition, std::chrono::milliseconds timeout = 20s) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (!condition()) {
        if (std::chrono::steady_clock::now() > end) return false;
        std::this_thread::sleep_for(5ms);
    }
    return true;
}

TEST(PageServer, ServesThePagesFilesAndNothingElse) {
    Served served("files");
    httplib::Client c = served.client();
    const auto page = c.Get("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(page->status, 200);
    EXPECT_NE(page->get_header_value("Content-Type").find("text/html"), std::string::npos);
    EXPECT_NE(page->body.find("app.js"), std::string::npos);
    for (const char* file : {"/index.html", "/app.js", "/style.css"}) {
        const auto res = c.Get(file);
        ASSERT_TRUE(res) << file;
        EXPECT_EQ(res->status, 200) << file;
        EXPECT_FALSE(res->body.empty()) << file;
    }
    EXPECT_NE(c.Get("/app.js")->get_header_value("Content-Type").find("javascript"),
              std::string::npos);
    // Nothing from the file system, by any spelling of "..".
    for (const char* path : {"/nothing.js", "/../../../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd",
                             "/page/../CMakeLists.txt", "/..%2f..%2fetc%2fpasswd", "/scene.yaml",
                             "/page_server.cpp"}) {
        const auto res = c.Get(path);
        ASSERT_TRUE(res) << path;
        EXPECT_EQ(res->status, 404) << path;
        EXPECT_EQ(res->body.find("root:"), std::string::npos) << path;
        EXPECT_EQ(res->body.find("image:"), std::string::npos) << path;
    }
}

TEST(PageServer, AnswersOnlyRequestsForThisMachine) {
    Served served("host");
    httplib::Client c = served.client();
    // A page of another site reaching 127.0.0.1 through a name rebound to it.
    const auto rebound =
        c.Get("/", {{"Host", "attacker.example:" + std::to_string(served.port())}});
    ASSERT_TRUE(rebound);
    EXPECT_EQ(rebound->status, 403);
    const auto local = c.Get("/", {{"Host", "localhost:" + std::to_string(served.port())}});
    ASSERT_TRUE(local);
    EXPECT_EQ(local->status, 200);
}

TEST(PageServer, WithATokenEveryRequestMustCarryIt) {
    ServeOptions options;
    options.token = random_token();
    EXPECT_EQ(options.token.size(), 32u);
    EXPECT_NE(options.token, random_token());
    Served served("token", options);
    httplib::Client c = served.client();
    EXPECT_EQ(c.Get("/")->status, 403);
    EXPECT_EQ(c.Get("/?token=0123")->status, 403);
    EXPECT_EQ(c.Get("/app.js")->status, 403);
    EXPECT_EQ(c.Post("/camera?session=x", "{}", "text/plain")->status, 403);
    EXPECT_EQ(c.Get("/?token=" + options.token)->status, 200);
    // Any Host then: the token is what keeps others out.
    EXPECT_EQ(c.Get("/?token=" + options.token, {{"Host", "render.example:1"}})->status, 200);
}

TEST(PageServer, StreamsAPreviewThenEveryPassToTheRendersImage) {
    Served served("stream", {}, scene_text("[0.8, 0.3, 0.2]", 16));
    EventStream stream(served, until_finished());
    const std::string session = stream.session();
    ASSERT_FALSE(session.empty());
    stream.join();
    const std::vector<Event> events = stream.events();
    ASSERT_GE(events.size(), 3u);
    EXPECT_EQ(events[0].name, "hello");
    EXPECT_EQ(field(events[0].data, "scene"), "scene.yaml");
    EXPECT_EQ(field(events[0].data, "width"), "64");
    EXPECT_EQ(field(events[0].data, "integrator"), "whitted");
    // A quarter-size preview of one sample, then the passes in turn, 16 of a sample each. The
    // stream sends the newest frame when it writes: one that came while the previous one was
    // being sent is overtaken (a busy machine may even render the first pass before the preview
    // is sent).
    std::size_t first_pass = 1;
    if (field(events[1].data, "preview") == "true") {
        EXPECT_EQ(field(events[1].data, "width"), "16");
        EXPECT_EQ(field(events[1].data, "samples_done"), "1");
        first_pass = 2;
    }
    int passes = 0;
    for (std::size_t i = first_pass; i < events.size(); ++i) {
        EXPECT_EQ(field(events[i].data, "preview"), "false");
        const int done = std::stoi(field(events[i].data, "passes_done"));
        EXPECT_GT(done, passes);
        passes = done;
        EXPECT_EQ(field(events[i].data, "samples_done"), std::to_string(passes));
        EXPECT_EQ(field(events[i].data, "passes_total"), "16");
        EXPECT_EQ(field(events[i].data, "width"), "64");
    }
    EXPECT_EQ(passes, 16);
    // The last image is glint render's, PNG byte for byte.
    httplib::Client c = served.client();
    const auto png = c.Get("/image.png?session=" + session);
    ASSERT_TRUE(png);
    EXPECT_EQ(png->status, 200);
    EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
    EXPECT_TRUE(png->body == png_bytes(rendered(served.scene_file())));
    // Saved as PNG or, linear, as EXR, named after the scene.
    const auto saved = c.Get("/save?format=png&session=" + session);
    ASSERT_TRUE(saved);
    EXPECT_TRUE(saved->body == png->body);
    EXPECT_EQ(saved->get_header_value("Content-Disposition"), "attachment; filename=\"scene.png\"");
    const auto exr = c.Get("/save?format=exr&session=" + session);
    ASSERT_TRUE(exr);
    EXPECT_TRUE(exr->body == exr_bytes(rendered(served.scene_file())));
    EXPECT_EQ(c.Get("/save?format=tiff&session=" + session)->body,
              "{\"error\": \"format: expected png or exr, got \\\"tiff\\\"\"}\n");
    // The stream ended with the page: its render is gone.
    EXPECT_TRUE(wait_until([&] { return served.server().pages() == 0; }));
}

TEST(PageServer, ACameraMoveRendersTheNewViewAndABadOneIsRefusedWhereItIsWrong) {
    Served served("camera");
    EventStream stream(served, until_finished(1));
    const std::string session = stream.session();
    ASSERT_FALSE(session.empty());
    httplib::Client c = served.client();
    const std::string moved =
        R"({"from": [2, 1.5, -4], "at": [0, 0.5, 0], "up": [0, 1, 0], "fov": 40})";
    const auto res = c.Post("/camera?session=" + session, moved, "application/json");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200);
    EXPECT_NE(res->body.find("camera: {from: [2, 1.5, -4], at: [0, 0.5, 0]"), std::string::npos);
    stream.join();
    const auto png = c.Get("/image.png?session=" + session);
    ASSERT_TRUE(png);
    Scene scene = load_scene(served.scene_file());
    scene.camera.from = {2, 1.5f, -4};
    scene.camera.fov = 40;
    EXPECT_TRUE(png->body == png_bytes(render(World(scene), RenderOptions{}).image));
    // The camera as a line of the scene file.
    EXPECT_EQ(c.Get("/camera.yaml?session=" + session)->body,
              "camera: {from: [2, 1.5, -4], at: [0, 0.5, 0], up: [0, 1, 0], fov: 40}\n");
    // Refused as a scene file's camera is, at its place in the text.
    const auto bad = c.Post("/camera?session=" + session, R"({"from": [1, 1, 1], "at": [1, 1, 1]})",
                            "application/json");
    ASSERT_TRUE(bad);
    EXPECT_EQ(bad->status, 400);
    EXPECT_NE(bad->body.find("camera:1:27: error: camera from and at must differ"),
              std::string::npos)
        << bad->body;
    const auto reset = c.Post("/camera/reset?session=" + session, "", "text/plain");
    ASSERT_TRUE(reset);
    EXPECT_NE(reset->body.find("\"from\": [0, 1, -5]"), std::string::npos);
}

TEST(PageServer, SettingsAreCheckedAsGlintRendersOptionsAre) {
    Served served("settings");
    EventStream stream(served, [](const std::vector<Event>& events) {
        for (const Event& e : events)
            if (finished_frame(e) && field(e.data, "samples_total") == "9") return true;
        return false;
    });
    const std::string session = stream.session();
    httplib::Client c = served.client();
    const auto post = [&](const std::string& query) {
        return c.Post("/settings?session=" + session + "&" + query, "", "text/plain");
    };
    EXPECT_EQ(post("spp=0")->body,
              "{\"error\": \"spp: expected a whole number from 1 to 16777216, got 0\"}\n");
    EXPECT_EQ(post("spp=two")->status, 400);
    EXPECT_NE(post("integrator=raycast")->body.find("integrator"), std::string::npos);
    EXPECT_NE(post("accel=octree")->body.find("accel names are: bvh"), std::string::npos);
    EXPECT_EQ(post("max_depth=-1")->status, 400);
    const auto good = post("spp=9&accel=kdtree");
    ASSERT_TRUE(good);
    EXPECT_EQ(good->status, 200) << good->body;
    EXPECT_NE(good->body.find("\"spp\": 9"), std::string::npos);
    EXPECT_NE(good->body.find("\"accel\": \"kdtree\""), std::string::npos);
    stream.join();
    SettingOverrides nine;
    nine.spp = 9;  // the regular grid's square count
    EXPECT_TRUE(c.Get("/image.png?session=" + session)->body ==
                png_bytes(rendered(served.scene_file(), nine)));
}

TEST(PageServer, AClickedPixelsTreeIsGlintExplainsWithItsSegments) {
    Served served("explain");
    EventStream stream(served, until_finished());
    const std::string session = stream.session();
    stream.join();
    httplib::Client c = served.client();
    const auto res =
        c.Post("/explain?session=" + session + "&x=32&y=20&sample=3", "", "text/plain");
    ASSERT_TRUE(res);
    ASSERT_EQ(res->status, 200) << res->body;
    const World world(load_scene(served.scene_file()));
    const std::string tree = ray_tree_json(explain(world, {32, 20, 3, 0}));
    const std::size_t at = res->body.find("\"tree\": ");
    ASSERT_NE(at, std::string::npos);
    EXPECT_EQ(res->body.substr(at + 8, tree.size()), tree);
    EXPECT_NE(res->body.find("\"overlay\": [{\"node\": 0, \"kind\": \"primary\""),
              std::string::npos);
    EXPECT_NE(res->body.find("\"kind\": \"shadow\""), std::string::npos);
    // Outside the image or its samples: glint explain's own errors.
    EXPECT_NE(c.Post("/explain?session=" + session + "&x=64&y=0", "", "text/plain")
                  ->body.find("outside the image of 64x48 pixels"),
              std::string::npos);
    EXPECT_EQ(c.Post("/explain?session=" + session + "&x=1&y=1&sample=4", "", "text/plain")->status,
              400);
    EXPECT_EQ(c.Post("/explain?session=" + session + "&x=1", "", "text/plain")->status, 400);
    // Traced by another integrator than the render's: that integrator's tree of the sample.
    const auto path =
        c.Post("/explain?session=" + session + "&x=32&y=20&integrator=path", "", "text/plain");
    ASSERT_TRUE(path);
    ASSERT_EQ(path->status, 200) << path->body;
    Scene scene = load_scene(served.scene_file());
    scene.settings.integrator = IntegratorKind::path;
    const std::string path_tree = ray_tree_json(explain(World(scene), {32, 20, 0, 0}));
    EXPECT_EQ(path->body.substr(path->body.find("\"tree\": ") + 8, path_tree.size()), path_tree);
    EXPECT_NE(path_tree, ray_tree_json(explain(world, {32, 20, 0, 0})));
    const auto unknown =
        c.Post("/explain?session=" + session + "&x=1&y=1&integrator=raycast", "", "text/plain");
    EXPECT_EQ(unknown->status, 400);
    EXPECT_NE(unknown->body.find("integrator"), std::string::npos) << unknown->body;
    EXPECT_EQ(c.Post("/explain?session=" + session + "&x=1&y=1&integrator=cone", "", "text/plain")
                  ->status,
              400);
}

TEST(PageServer, AViewOfAnOutputVariableShowsItsPictureAndIsSavedWithTheImage) {
    Served served("views");
    EventStream stream(served, [](const std::vector<Event>& events) {
        return !events.empty() && finished_frame(events.back()) &&
               events.back().data.find("\"views\": [\"depth\"") != std::string::npos;
    });
    const std::string session = stream.session();
    ASSERT_FALSE(session.empty());
    EXPECT_NE(stream.events()[0].data.find("\"views\": [\"depth\", \"position\""),
              std::string::npos);
    httplib::Client c = served.client();
    const auto post = [&](const std::string& query) {
        return c.Post("/settings?session=" + session + "&" + query, "", "text/plain");
    };
    EXPECT_EQ(post("aovs=depth,colour")->body.rfind("{\"error\": \"aovs: unknown", 0), 0u);
    const auto all = post("aovs=all");
    ASSERT_EQ(all->status, 200) << all->body;
    EXPECT_NE(all->body.find("\"aovs\": [\"depth\", \"position\""), std::string::npos);
    // The cone integrator traces no rays for the variables to follow: glint render's words.
    EXPECT_EQ(post("integrator=cone")->body,
              "{\"error\": \"aovs: the output variables follow rays, and the cone integrator "
              "traces cones\"}\n");
    stream.join();
    RenderOptions options;
    options.aovs = parse_aov_list("all");
    const RenderResult expected = render(World(load_scene(served.scene_file())), options);
    const auto layer = [&](Aov aov) {
        for (const AovImage& l : expected.aovs)
            if (l.aov == aov) return l;
        return AovImage{};
    };
    // Each view its picture with its colour map and legend; the image stays the render's.
    const std::string image_url = "/image.png?session=" + session;
    EXPECT_TRUE(c.Get(image_url + "&view=depth")->body ==
                png_bytes(aov_picture(layer(Aov::depth))));
    EXPECT_TRUE(c.Get(image_url + "&view=image")->body == png_bytes(expected.image));
    EXPECT_TRUE(c.Get(image_url)->body == png_bytes(expected.image));
    const auto unknown = c.Get(image_url + "&view=colour");
    EXPECT_EQ(unknown->status, 400);
    EXPECT_NE(unknown->body.find("view: expected image or an output variable"), std::string::npos);
    // Saved: the view as PNG, named after it; the image with every variable as EXR layers.
    const auto normal = c.Get("/save?format=png&view=normal&session=" + session);
    EXPECT_TRUE(normal->body == png_bytes(aov_picture(layer(Aov::normal))));
    EXPECT_EQ(normal->get_header_value("Content-Disposition"),
              "attachment; filename=\"scene.normal.png\"");
    const auto exr = c.Get("/save?format=exr&session=" + session);
    std::vector<AovImage> shown;  // all but the samples taken, which frames cannot read
    for (const AovImage& l : expected.aovs)
        if (l.aov != Aov::samples) shown.push_back(l);
    EXPECT_TRUE(exr->body == exr_bytes(expected.image, aov_exr_layers(shown)));
    // Back to none recorded: the views are gone with them.
    ASSERT_EQ(post("aovs=")->status, 200);
    ASSERT_TRUE(wait_until([&] { return c.Get(image_url + "&view=depth")->status == 404; }));
}

TEST(PageServer, AnUnknownPageIsNotFound) {
    Served served("unknown");
    httplib::Client c = served.client();
    EXPECT_EQ(c.Get("/image.png?session=nobody")->status, 404);
    EXPECT_EQ(c.Get("/camera.yaml")->status, 404);
    EXPECT_EQ(c.Get("/save?session=nobody")->status, 404);
    EXPECT_EQ(c.Post("/camera?session=nobody", "{}", "text/plain")->status, 404);
    EXPECT_EQ(c.Post("/settings?session=nobody&spp=1", "", "text/plain")->status, 404);
    EXPECT_EQ(c.Post("/explain?session=nobody&x=1&y=1", "", "text/plain")->status, 404);
}

TEST(PageServer, OversizedRequestsAreRefused) {
    ServeOptions options;
    options.max_request_bytes = 16 * 1024;
    Served served("sizes", options);
    EventStream stream(served, [](const auto&) { return false; });
    const std::string session = stream.session();
    httplib::Client c = served.client();
    const auto camera = c.Post("/camera?session=" + session, std::string(5000, ' '), "text/plain");
    ASSERT_TRUE(camera);
    EXPECT_EQ(camera->status, 413);
    const auto huge = c.Post("/camera?session=" + session, std::string(100000, 'x'), "text/plain");
    EXPECT_TRUE(!huge || huge->status == 413);
    const auto long_uri = c.Get("/" + std::string(10000, 'a'));
    EXPECT_TRUE(!long_uri || long_uri->status == 414);
    EXPECT_EQ(served.client().Get("/")->status, 200);  // and it still answers
    stream.leave();
}

TEST(PageServer, APageThatLeavesMidRenderCancelsItsRender) {
    // Slow enough (a few seconds) that the render is still in flight when the page leaves.
    Served served("leave", {}, scene_text("[0.8, 0.3, 0.2]", 4096));
    EventStream stream(served, [](const std::vector<Event>& events) {
        return events.size() >= 3;  // the hello, the preview and the first pass
    });
    ASSERT_FALSE(stream.session().empty());
    stream.join();
    // Its first pass takes long enough for the preview to be seen first.
    const std::vector<Event> events = stream.events();
    ASSERT_EQ(events.size(), 3u);
    EXPECT_EQ(field(events[1].data, "preview"), "true");
    EXPECT_EQ(field(events[1].data, "width"), "16");
    EXPECT_EQ(field(events[1].data, "height"), "12");
    EXPECT_EQ(field(events[1].data, "samples_done"), "1");
    EXPECT_EQ(field(events[2].data, "preview"), "false");
    EXPECT_EQ(field(events[2].data, "samples_done"), "256");
    const auto left = std::chrono::steady_clock::now();
    EXPECT_TRUE(wait_until([&] { return served.server().pages() == 0; }));
    // Gone within a second or so: the pass in flight was cancelled, not finished.
    EXPECT_LT(std::chrono::steady_clock::now() - left, 10s);
}

TEST(PageServer, EditingTheSceneRendersItAgainAndABrokenOneShowsItsError) {
    Served served("edit");
    std::atomic<bool> watching{true};
    std::thread watcher([&] {
        while (watching) {
            served.scene().reload_if_changed();
            std::this_thread::sleep_for(20ms);
        }
    });
    EventStream stream(served, [](const std::vector<Event>& events) {
        int fixed = 0;
        for (const Event& e : events)
            fixed += field(e.data, "error") != "null" && e.name == "frame";
        return fixed > 0 && finished_frame(events.back(), 2);
    });
    const std::string session = stream.session();
    httplib::Client c = served.client();
    ASSERT_TRUE(wait_until([&] { return c.Get("/image.png?session=" + session)->status == 200; }));
    std::this_thread::sleep_for(50ms);
    write_file(served.scene_file(), scene_text("[0.2, 0.3, 0.9]"));  // blue, and a byte longer
    ASSERT_TRUE(wait_until([&] {
        return c.Get("/image.png?session=" + session)->body ==
               png_bytes(rendered(served.scene_file()));
    }));
    std::this_thread::sleep_for(50ms);
    write_file(served.scene_file(),
               "image: {width: 64, height: 48}\ncamera: {from: [0, 1, -5], at: [0, 1, -5]}\n");
    // The frame that shows the camera's error (a look that caught the file emptied twice, when
    // the writer was held up between truncating and writing, would show an empty scene's first).
    const auto camera_error = [&] {
        for (const Event& e : stream.events())
            if (e.name == "frame" && e.data.find("camera from and at must differ") != e.data.npos)
                return e.data;
        return std::string();
    };
    ASSERT_TRUE(wait_until([&] { return !camera_error().empty(); }));
    const std::string error = camera_error();
    EXPECT_NE(error.find("scene.yaml:2:"), std::string::npos) << error;
    EXPECT_NE(error.find("\\u000a    2 | camera:"), std::string::npos) << error;  // the line
    EXPECT_NE(field(error, "image"), "false");  // the last good image stays
    // While it stays broken, a camera move renders the last good scene, its error still shown.
    const auto moved =
        c.Post("/camera?session=" + session,
               R"({"from": [1, 1, -5], "at": [0, 0.5, 0], "up": [0, 1, 0]})", "application/json");
    ASSERT_EQ(moved->status, 200) << moved->body;
    const int version = std::stoi(field(moved->body, "version"));
    ASSERT_TRUE(wait_until([&] {
        for (const Event& e : stream.events())
            if (e.name == "frame" && std::stoi(field(e.data, "version")) >= version &&
                field(e.data, "passes_total") != "0" &&
                field(e.data, "passes_done") == field(e.data, "passes_total"))
                return field(e.data, "error").find("camera from and at must differ") !=
                       std::string::npos;
        return false;
    }));
    ASSERT_EQ(c.Post("/camera/reset?session=" + session, "", "text/plain")->status, 200);
    std::this_thread::sleep_for(50ms);
    write_file(served.scene_file(), scene_text("[0.9, 0.9, 0.2]"));
    stream.join();
    EXPECT_TRUE(c.Get("/image.png?session=" + session)->body ==
                png_bytes(rendered(served.scene_file())));
    watching = false;
    watcher.join();
}

TEST(PageServer, TwentyPagesAtOnceEachGetARenderOrABusyAnswer) {
    ServeOptions options;
    options.max_pages = 8;
    Served served("twenty", options);
    std::vector<std::unique_ptr<EventStream>> streams;
    for (int i = 0; i < 20; ++i)
        streams.push_back(std::make_unique<EventStream>(served, until_finished()));
    int rendered_pages = 0, busy = 0;
    for (auto& stream : streams) {
        stream->join();
        const int status = stream->status();
        EXPECT_TRUE(status == 200 || status == 503) << status;
        rendered_pages += status == 200;
        busy += status == 503;
        if (status == 200) {
            EXPECT_TRUE(finished_frame(stream->events().back()));
        }
    }
    EXPECT_GE(rendered_pages, 8);
    EXPECT_EQ(rendered_pages + busy, 20);
    EXPECT_TRUE(wait_until([&] { return served.server().pages() == 0; }));
    EXPECT_EQ(served.client().Get("/")->status, 200);
}

}  // namespace
}  // namespace glint::serve
