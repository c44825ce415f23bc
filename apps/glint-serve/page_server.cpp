// Routes, checks and the event stream. Every request passes the pre-routing check first: the
// token when one is set, else a Host header naming this machine (so that a web page elsewhere
// cannot reach the server through a DNS name rebound to 127.0.0.1).
#include "page_server.h"

#include <httplib.h>

#include <cctype>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <random>
#include <span>
#include <stdexcept>
#include <string_view>

#include "glint/image/exr_io.h"
#include "glint/image/png_io.h"
#include "glint/render/film/aov_picture.h"
#include "glint/render/json_string.h"
#include "glint/render/ray_stats.h"
#include "glint/render/render_choices.h"
#include "glint/scene/camera_text.h"
#include "glint/scene/integrators.h"
#include "glint/scene/scene_error.h"
#include "page_files.h"

namespace glint::serve {

namespace {

// The longest camera the page may send: a camera map is a few hundred bytes.
constexpr std::size_t kMaxCameraBytes = 4096;

void answer_json(httplib::Response& res, int status, const std::string& json) {
    res.status = status;
    res.set_content(json, "application/json");
}

void answer_error(httplib::Response& res, int status, const std::string& message) {
    answer_json(res, status, "{\"error\": " + json_string(message) + "}\n");
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

std::string point_json(Point3 p) {
    return "[" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + "]";
}

std::string camera_json(const CameraSpec& c) {
    return std::string("{\"type\": ") + json_string(projection_name(c.projection)) +
           ", \"from\": " + point_json(c.from) + ", \"at\": " + point_json(c.at) +
           ", \"up\": " + point_json(Point3(c.up.x, c.up.y, c.up.z)) +
           ", \"fov\": " + number(c.fov) + ", \"vertical_fov\": " + number(c.vertical_fov) +
           ", \"height\": " + number(c.height) +
           ", \"axis\": " + (c.cylinder_axis_across ? "\"horizontal\"" : "\"vertical\"") +
           ", \"parallel\": " + (c.cylinder_parallel ? "true" : "false") +
           ", \"yaml\": " + json_string("camera: " + camera_yaml(c)) + "}";
}

std::string overlay_json(const std::vector<OverlaySegment>& segments) {
    std::string out = "[";
    for (const OverlaySegment& s : segments) {
        if (out.size() > 1) out += ", ";
        out += "{\"node\": " + std::to_string(s.node) +
               ", \"kind\": " + json_string(kRayKindNames[std::size_t(s.kind)]) +
               ", \"light\": " + std::to_string(s.light) +
               ", \"blocked\": " + (s.blocked ? "true" : "false") +
               ", \"missed\": " + (s.missed ? "true" : "false") + ", \"from\": [" +
               number(s.from.x) + ", " + number(s.from.y) + "], \"to\": [" + number(s.to.x) + ", " +
               number(s.to.y) + "]}";
    }
    return out + "]";
}

std::string names_json(std::span<const std::string_view> names) {
    std::string out = "[";
    for (const std::string_view name : names)
        out += (out.size() > 1 ? ", " : "") + json_string(name);
    return out + "]";
}

std::vector<std::string_view> aov_names(const AovSet& set) {
    std::vector<std::string_view> names;
    for (const Aov aov : set.list()) names.push_back(aov_info(aov).name);
    return names;
}

// The output variables the page can show: all but the samples each pixel took, which the
// render's threads count as they go, and a frame cannot read (glint render --aov writes them).
std::vector<std::string_view> view_names() {
    std::vector<std::string_view> names;
    for (const Aov aov : parse_aov_list("all").list())
        if (aov != Aov::samples) names.push_back(aov_info(aov).name);
    return names;
}

// The output variables of a frame, each a view the page may show beside the image.
std::vector<std::string_view> recorded_names(const Frame& f) {
    std::vector<std::string_view> names;
    if (f.aovs)
        for (const AovImage& layer : *f.aovs) names.push_back(aov_info(layer.aov).name);
    return names;
}

std::string frame_json(const Frame& f) {
    return "{\"sequence\": " + std::to_string(f.sequence) +
           ", \"version\": " + std::to_string(f.version) +
           ", \"preview\": " + (f.preview ? "true" : "false") +
           ", \"width\": " + std::to_string(f.width) + ", \"height\": " + std::to_string(f.height) +
           ", \"passes_done\": " + std::to_string(f.passes_done) +
           ", \"passes_total\": " + std::to_string(f.passes_total) +
           ", \"samples_done\": " + std::to_string(f.samples_done) +
           ", \"samples_total\": " + std::to_string(f.samples_total) +
           ", \"seconds\": " + number(f.seconds) + ", \"seconds_left\": " + number(f.seconds_left) +
           ", \"image\": " + (f.png ? "true" : "false") +
           ", \"views\": " + names_json(recorded_names(f)) +
           ", \"error\": " + (f.error.empty() ? "null" : json_string(f.error)) + "}";
}

// The page's settings as applied to the scene's (check_page_settings).
std::string settings_json(const RenderSettings& s, const PageSettings& page) {
    return std::string("{\"integrator\": ") + json_string(integrator_name(s.integrator)) +
           ", \"spp\": " + std::to_string(s.samples_per_pixel) +
           ", \"max_depth\": " + std::to_string(s.max_depth) +
           ", \"accel\": " + json_string(accel_name(page.accel)) +
           ", \"aovs\": " + names_json(aov_names(page.aovs)) + "}";
}

std::string camera_answer(int version, const LiveRender& page) {
    return "{\"version\": " + std::to_string(version) +
           ", \"camera\": " + camera_json(page.camera()) + "}\n";
}

// As glint prints it: the message, then its notes.
std::string settings_error_text(const SettingsError& e) {
    std::string text = e.what();
    for (const std::string& note : e.notes()) text += " (" + note + ")";
    return text;
}

// The output variable a view shows by its name, nothing for the image itself; throws
// SettingsError for a name that is neither.
std::optional<Aov> view_of(const httplib::Request& req) {
    const std::string name = req.has_param("view") ? req.get_param_value("view") : "image";
    if (name == "image") return std::nullopt;
    for (std::size_t a = 0; a < kAovCount; ++a)
        if (aov_info(Aov(a)).name == name) return Aov(a);
    throw SettingsError("view",
                        "view: expected image or an output variable's name, got \"" + name + "\"");
}

// The picture of a frame's view as a PNG (the image's own for the image), or nothing when the
// frame's render does not record that variable.
std::optional<std::string> view_png(const Frame& frame, std::optional<Aov> view) {
    if (!view) return frame.png ? std::optional(*frame.png) : std::nullopt;
    if (frame.aovs)
        for (const AovImage& layer : *frame.aovs)
            if (layer.aov == *view) return png_bytes(aov_picture(layer));
    return std::nullopt;
}

// A whole number parameter, or SettingsError naming it.
std::optional<int> whole_parameter(const httplib::Request& req, const char* key) {
    if (!req.has_param(key)) return std::nullopt;
    const std::string text = req.get_param_value(key);
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        throw SettingsError(key,
                            std::string(key) + ": expected a whole number, got \"" + text + "\"");
    return value;
}

int required_whole(const httplib::Request& req, const char* key) {
    const auto value = whole_parameter(req, key);
    if (!value) throw SettingsError(key, std::string(key) + ": missing");
    return *value;
}

// The scene's name with the format's extension, in letters a header may carry unquoted.
std::string download_name(const std::filesystem::path& scene, const std::string& extension) {
    std::string name = scene.stem().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.')
            c = '_';
    return (name.empty() ? "render" : name) + "." + extension;
}

bool is_local_host(std::string_view host, int port) {
    const std::string suffix = ":" + std::to_string(port);
    for (const std::string_view name : {"127.0.0.1", "localhost", "[::1]"})
        if (host == name || host == std::string(name) + suffix) return true;
    return false;
}

}  // namespace

std::string random_token() {
    std::random_device device;
    char text[33];
    std::snprintf(text, sizeof text, "%08x%08x%08x%08x", device(), device(), device(), device());
    return text;
}

PageServer::PageServer(const WatchedScene& scene, ServeOptions options)
    : scene_(scene),
      options_(std::move(options)),
      slots_(options_.max_renders),
      server_(std::make_unique<httplib::Server>()) {
    // An event stream holds a thread while its page is open: room for every page, and more.
    const int threads = options_.max_pages + 8;
    server_->new_task_queue = [threads] { return new httplib::ThreadPool(std::size_t(threads)); };
    server_->set_payload_max_length(options_.max_request_bytes);
    add_routes();
}

PageServer::~PageServer() {
    stop();
    const std::lock_guard lock(mutex_);
    pages_.clear();
}

int PageServer::bind() {
    if (options_.port == 0) {
        port_ = server_->bind_to_any_port(options_.host);
        if (port_ < 0) throw std::runtime_error("cannot listen on " + options_.host);
    } else {
        if (!server_->bind_to_port(options_.host, options_.port))
            throw std::runtime_error("cannot listen on " + options_.host + " port " +
                                     std::to_string(options_.port) +
                                     " (in use? choose another with --port)");
        port_ = options_.port;
    }
    return port_;
}

void PageServer::listen() { server_->listen_after_bind(); }

void PageServer::stop() { server_->stop(); }

int PageServer::pages() const {
    const std::lock_guard lock(mutex_);
    return int(pages_.size());
}

std::shared_ptr<LiveRender> PageServer::page_of(const std::string& session) const {
    const std::lock_guard lock(mutex_);
    const auto found = pages_.find(session);
    return found == pages_.end() ? nullptr : found->second;
}

void PageServer::add_routes() {
    using httplib::Request;
    using httplib::Response;
    httplib::Server& s = *server_;

    s.set_pre_routing_handler([this](const Request& req, Response& res) {
        if (!options_.token.empty()) {
            if (req.get_param_value("token") != options_.token) {
                answer_error(res, 403, "this server asks for its token: open the URL it printed");
                return httplib::Server::HandlerResponse::Handled;
            }
        } else if (!is_local_host(req.get_header_value("Host"), port_)) {
            answer_error(res, 403, "this server answers requests for 127.0.0.1 only");
            return httplib::Server::HandlerResponse::Handled;
        }
        return httplib::Server::HandlerResponse::Unhandled;
    });
    s.set_exception_handler([](const Request&, Response& res, std::exception_ptr error) {
        try {
            std::rethrow_exception(error);
        } catch (const std::bad_alloc&) {
            answer_error(res, 503, "out of memory");
        } catch (const std::exception& e) {
            answer_error(res, 500, e.what());
        } catch (...) {
            answer_error(res, 500, "unknown error");
        }
    });

    s.Get("/events", [this](const Request&, Response& res) {
        std::string id = random_token();
        std::shared_ptr<LiveRender> page;
        {
            const std::lock_guard lock(mutex_);
            if (int(pages_.size()) >= options_.max_pages) {
                answer_error(res, 503,
                             "too many pages are open (" + std::to_string(options_.max_pages) +
                                 ", glint-serve --max-pages): close one");
                return;
            }
            page = std::make_shared<LiveRender>(scene_, slots_, options_.threads);
            pages_[id] = page;
        }
        const WatchedScene::Loaded loaded = scene_.current();
        const std::string hello =
            "event: hello\ndata: {\"session\": " + json_string(id) +
            ", \"scene\": " + json_string(scene_.file().filename().string()) +
            ", \"width\": " + std::to_string(loaded.scene->settings.width) +
            ", \"height\": " + std::to_string(loaded.scene->settings.height) +
            ", \"camera\": " + camera_json(page->camera()) + ", \"settings\": " +
            settings_json(check_page_settings(*loaded.scene, page->settings()), page->settings()) +
            ", \"integrators\": " + names_json(integrator_names()) +
            ", \"accels\": " + names_json(accel_names()) +
            ", \"views\": " + names_json(view_names()) + "}\n\n";
        auto seen = std::make_shared<int>(0);
        auto greeted = std::make_shared<bool>(false);
        res.set_header("Cache-Control", "no-cache");
        res.set_chunked_content_provider(
            "text/event-stream",
            [page, hello, seen, greeted](std::size_t, httplib::DataSink& sink) {
                if (!*greeted) {
                    *greeted = true;
                    return sink.write(hello.data(), hello.size());
                }
                const Frame frame = page->frame_after(*seen, std::chrono::seconds(1));
                std::string event;
                if (frame.sequence > *seen) {
                    *seen = frame.sequence;
                    event = "event: frame\ndata: " + frame_json(frame) + "\n\n";
                } else {
                    event = ": still here\n\n";  // a page gone away fails this write
                }
                return sink.write(event.data(), event.size());
            },
            [this, id](bool) {
                // The page went away, or the server stops: its render is cancelled and joined.
                std::shared_ptr<LiveRender> gone;
                {
                    const std::lock_guard lock(mutex_);
                    const auto found = pages_.find(id);
                    if (found == pages_.end()) return;
                    gone = std::move(found->second);
                    pages_.erase(found);
                }
            });
    });

    s.Get("/image.png", [this](const Request& req, Response& res) {
        const auto page = page_of(req.get_param_value("session"));
        if (!page) return answer_error(res, 404, "no such page");
        const Frame frame = page->latest();
        std::optional<std::string> png;
        try {
            png = view_png(frame, view_of(req));
        } catch (const SettingsError& e) {
            return answer_error(res, 400, e.what());
        }
        if (!png) return answer_error(res, 404, "no image of this view yet");
        res.set_header("X-Glint-Sequence", std::to_string(frame.sequence));
        res.set_header("Cache-Control", "no-store");
        res.set_content(std::move(*png), "image/png");
    });

    s.Get("/save", [this](const Request& req, Response& res) {
        const auto page = page_of(req.get_param_value("session"));
        if (!page) return answer_error(res, 404, "no such page");
        const std::string format = req.has_param("format") ? req.get_param_value("format") : "png";
        if (format != "png" && format != "exr")
            return answer_error(res, 400, "format: expected png or exr, got \"" + format + "\"");
        const Frame frame = page->latest();
        if (!frame.image) return answer_error(res, 404, "no image yet");
        std::string bytes;
        if (format == "png") {
            // The view shown, its legend included.
            std::optional<Aov> view;
            try {
                view = view_of(req);
            } catch (const SettingsError& e) {
                return answer_error(res, 400, e.what());
            }
            auto png = view_png(frame, view);
            if (!png) return answer_error(res, 404, "no image of this view yet");
            bytes = std::move(*png);
            const std::string name = view ? std::string(aov_info(*view).name) : "";
            res.set_header("Content-Disposition",
                           "attachment; filename=\"" +
                               download_name(scene_.file(), name.empty() ? "png" : name + ".png") +
                               "\"");
        } else {
            // The image with every output variable recorded, as glint render --aov writes it.
            const std::vector<ExrLayer> layers =
                frame.aovs ? aov_exr_layers(*frame.aovs) : std::vector<ExrLayer>{};
            bytes = exr_bytes(*frame.image, layers);
            res.set_header("Content-Disposition",
                           "attachment; filename=\"" + download_name(scene_.file(), "exr") + "\"");
        }
        res.set_content(std::move(bytes), format == "png" ? "image/png" : "image/x-exr");
    });

    s.Get("/camera.yaml", [this](const Request& req, Response& res) {
        const auto page = page_of(req.get_param_value("session"));
        if (!page) return answer_error(res, 404, "no such page");
        res.set_content("camera: " + camera_yaml(page->camera()) + "\n", "text/yaml");
    });

    s.Post("/camera", [this](const Request& req, Response& res) {
        const auto page = page_of(req.get_param_value("session"));
        if (!page) return answer_error(res, 404, "no such page");
        if (req.body.size() > kMaxCameraBytes)
            return answer_error(res, 413, "a camera is at most 4096 bytes");
        int version = 0;
        try {
            version = page->set_camera(parse_camera_text(req.body, "camera"));
        } catch (const SceneError& e) {
            return answer_error(res, 400, format_scene_error(e));
        }
        answer_json(res, 200, camera_answer(version, *page));
    });

    s.Post("/camera/reset", [this](const Request& req, Response& res) {
        const auto page = page_of(req.get_param_value("session"));
        if (!page) return answer_error(res, 404, "no such page");
        answer_json(res, 200, camera_answer(page->reset_camera(), *page));
    });

    s.Post("/settings", [this](const Request& req, Response& res) {
        const auto page = page_of(req.get_param_value("session"));
        if (!page) return answer_error(res, 404, "no such page");
        const WatchedScene::Loaded loaded = scene_.current();
        PageSettings settings = page->settings();
        RenderSettings applied;
        try {
            if (req.has_param("integrator"))
                settings.overrides.integrator = req.get_param_value("integrator");
            if (const auto spp = whole_parameter(req, "spp")) settings.overrides.spp = spp;
            if (const auto depth = whole_parameter(req, "max_depth"))
                settings.overrides.max_depth = depth;
            if (req.has_param("accel")) settings.accel = accel_named(req.get_param_value("accel"));
            if (req.has_param("aovs")) {
                // Checked against the integrator chosen, which the request may change too.
                const std::string list = req.get_param_value("aovs");
                settings.aovs = {};
                if (!list.empty())
                    settings.aovs =
                        aovs_named(list, check_page_settings(*loaded.scene, settings).integrator);
            }
            applied = check_page_settings(*loaded.scene, settings);
        } catch (const SettingsError& e) {
            return answer_error(res, 400, settings_error_text(e));
        }
        const int version = page->set_settings(settings);
        answer_json(res, 200,
                    "{\"version\": " + std::to_string(version) +
                        ", \"settings\": " + settings_json(applied, settings) + "}\n");
    });

    s.Post("/explain", [this](const Request& req, Response& res) {
        const auto page = page_of(req.get_param_value("session"));
        if (!page) return answer_error(res, 404, "no such page");
        try {
            const LiveRender::Explained explained = page->explain(
                required_whole(req, "x"), required_whole(req, "y"),
                whole_parameter(req, "sample").value_or(0), req.get_param_value("integrator"));
            answer_json(res, 200,
                        "{\"version\": " + std::to_string(explained.version) +
                            ", \"overlay\": " + overlay_json(explained.overlay) +
                            ", \"tree\": " + explained.tree_json + "}\n");
        } catch (const SettingsError& e) {
            answer_error(res, 400, settings_error_text(e));
        } catch (const SceneError& e) {
            answer_error(res, 400, format_scene_error(e));  // an integrator the scene cannot take
        }
    });

    // The page's files, from the table compiled in: no path reaches the file system. Last, so
    // that the routes above come first.
    s.Get(R"(/([a-z_]*(\.[a-z]+)?))", [](const Request& req, Response& res) {
        const std::string name = req.matches[1].str();
        if (const auto file = page_file(name.empty() ? "index.html" : name)) {
            res.set_content(std::string(file->content), std::string(file->type));
            res.set_header("Cache-Control", "no-cache");
            return;
        }
        answer_error(res, 404, "no such file");
    });
}

}  // namespace glint::serve
