// The render thread waits for a change (or a look at the scene's files every tenth of a second),
// then renders the newest view: a preview at a quarter of the size and one sample a pixel, then
// the view itself. Each stage first checks that no newer view has come.
#include "live_render.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "glint/image/png_io.h"
#include "glint/render/explain/explain.h"
#include "glint/render/explain/ray_tree_formats.h"
#include "glint/render/render_choices.h"
#include "glint/scene/integrator_fit.h"
#include "glint/scene/integrators.h"
#include "glint/scene/scene_error.h"

namespace glint::serve {

namespace {

using Clock = std::chrono::steady_clock;

// The preview's size: a quarter across, so a sixteenth of the pixels.
constexpr int kPreviewShrink = 4;

}  // namespace

RenderSettings check_page_settings(const Scene& scene, const PageSettings& settings) {
    RenderSettings checked = scene.settings;
    apply_setting_overrides(settings.overrides, checked);
    if (const auto problem = aovs_problem(settings.aovs, checked.integrator))
        throw SettingsError("aovs", "aovs: " + *problem);
    return checked;
}

LiveRender::LiveRender(const WatchedScene& scene, RenderSlots& slots, int threads)
    : scene_(scene), slots_(slots), threads_(threads), thread_([this] { run(); }) {}

LiveRender::~LiveRender() {
    {
        const std::lock_guard lock(mutex_);
        closing_ = true;
        if (running_) running_->cancel();
    }
    changed_.notify_all();
    slots_.nudge();
    thread_.join();
}

int LiveRender::changed() {
    ++version_;
    if (running_) running_->cancel();
    changed_.notify_all();
    slots_.nudge();
    return version_;
}

int LiveRender::set_camera(const CameraSpec& camera) {
    const std::lock_guard lock(mutex_);
    camera_ = camera;
    return changed();
}

int LiveRender::reset_camera() {
    const std::lock_guard lock(mutex_);
    camera_.reset();
    return changed();
}

int LiveRender::set_settings(const PageSettings& settings) {
    const std::lock_guard lock(mutex_);
    settings_ = settings;
    return changed();
}

CameraSpec LiveRender::camera() const {
    const std::lock_guard lock(mutex_);
    if (camera_) return *camera_;
    return scene_.current().scene->camera;
}

PageSettings LiveRender::settings() const {
    const std::lock_guard lock(mutex_);
    return settings_;
}

Frame LiveRender::latest() const {
    const std::lock_guard lock(mutex_);
    return latest_;
}

Frame LiveRender::frame_after(int sequence, std::chrono::milliseconds timeout) const {
    std::unique_lock lock(mutex_);
    published_.wait_for(lock, timeout, [&] { return latest_.sequence > sequence || closing_; });
    return latest_;
}

bool LiveRender::stale(int version) const { return closing_ || version != version_; }

void LiveRender::publish(Frame frame) {
    {
        const std::lock_guard lock(mutex_);
        frame.sequence = latest_.sequence + 1;
        if (!frame.png) {
            // An error keeps the last image, and what it showed.
            frame.image = latest_.image;
            frame.png = latest_.png;
            frame.aovs = latest_.aovs;
            frame.width = latest_.width;
            frame.height = latest_.height;
        }
        latest_ = std::move(frame);
    }
    published_.notify_all();
}

void LiveRender::run() {
    int rendered = -1;  // the version last rendered
    int generation = 0;
    for (;;) {
        View view;
        {
            std::unique_lock lock(mutex_);
            changed_.wait_for(lock, std::chrono::milliseconds(100),
                              [&] { return closing_ || version_ != rendered; });
            if (closing_) return;
            const WatchedScene::Loaded loaded = scene_.current();
            if (loaded.generation != generation) {
                generation = loaded.generation;
                if (!loaded.error.empty()) {
                    // The last good image stays, with the error over it.
                    lock.unlock();
                    Frame error;
                    error.version = rendered;
                    error.error = loaded.error;
                    publish(std::move(error));
                    continue;
                }
                ++version_;
            }
            if (version_ == rendered) continue;
            view = {version_, loaded.scene, camera_, settings_, loaded.error};
        }
        rendered = view.version;
        try {
            render_view(view);
        } catch (const std::exception& e) {
            Frame error;
            error.version = view.version;
            error.error = load_error_text(e);
            publish(std::move(error));
        }
    }
}

Scene LiveRender::scene_of(const View& view) const {
    Scene scene = *view.scene;
    if (view.camera) {
        CameraSpec camera = *view.camera;
        camera.lens = scene.camera.lens;
        camera.shutter_open = scene.camera.shutter_open;
        camera.shutter_close = scene.camera.shutter_close;
        camera.left_handed = scene.camera.left_handed;
        camera.aspect = scene.camera.aspect;
        scene.camera = std::move(camera);
    }
    scene.settings = check_page_settings(scene, view.settings);
    check_integrator_fits(scene);
    return scene;
}

void LiveRender::render_view(const View& view) {
    const auto give_up = [&] {
        const std::lock_guard lock(mutex_);
        return stale(view.version);
    };
    if (!slots_.acquire(give_up)) return;
    const SlotHold hold(slots_);
    Scene scene = scene_of(view);
    // The preview, unless the view is that small already.
    const RenderSettings& full = scene.settings;
    if (full.width >= 2 * kPreviewShrink && full.height >= 2 * kPreviewShrink) {
        Scene small = scene;
        SettingOverrides overrides;
        overrides.width = std::max(1, full.width / kPreviewShrink);
        overrides.height = std::max(1, full.height / kPreviewShrink);
        overrides.spp = 1;
        bool previewable = true;
        try {
            apply_setting_overrides(overrides, small.settings);
        } catch (const SettingsError&) {
            previewable = false;  // adaptive sampling that needs more samples, say
        }
        if (previewable) {
            if (give_up()) return;
            const World world(std::move(small), view.settings.accel);
            if (!run_job(world, view, /*preview=*/true)) return;
        }
    }
    if (give_up()) return;
    const CameraSpec camera = scene.camera;
    auto world = std::make_shared<const World>(std::move(scene), view.settings.accel);
    {
        const std::lock_guard lock(mutex_);
        world_ = world;
        world_view_ = view;
        world_camera_ = camera;
    }
    run_job(*world, view, /*preview=*/false);
}

bool LiveRender::run_job(const World& world, const View& view, bool preview) {
    std::mutex pass_mutex;
    std::condition_variable pass_done;
    int passes_signalled = 0;
    bool finished = false, complete = false;
    RenderOptions options;
    options.threads = threads_;
    options.aovs = view.settings.aovs;
    // Up to 16 passes, a sample a pixel or more each, for the page to refine; glint render
    // takes up to 16 samples in one.
    options.pass_size = std::max(1, (world.settings().samples_per_pixel + 15) / 16);
    // On the render's thread between passes: only a note, so that it goes on at once.
    options.after_pass = [&](const RenderState& state) {
        const std::lock_guard lock(pass_mutex);
        passes_signalled = state.passes_done();
        pass_done.notify_one();
    };
    RenderJob job(world, options);
    {
        const std::lock_guard lock(mutex_);
        if (stale(view.version)) return false;
        running_ = &job;  // a change from now on cancels it, even before it starts
    }
    const Clock::time_point start = Clock::now();
    std::thread runner([&] {
        bool done = false;
        try {
            done = job.run().complete;
        } catch (...) {
            done = false;  // only a stop or a lack of memory end a render early
        }
        const std::lock_guard lock(pass_mutex);
        complete = done;
        finished = true;
        pass_done.notify_one();
    });
    // However this ends (a PNG that cannot be made, say), the job stops and its thread is joined
    // before the job goes, and no change cancels it after.
    struct Finish {
        LiveRender& live;
        RenderJob& job;
        std::thread& runner;
        ~Finish() {
            job.cancel();
            runner.join();
            const std::lock_guard lock(live.mutex_);
            live.running_ = nullptr;
        }
    } finish{*this, job, runner};
    const RenderSettings& settings = world.settings();
    const int per_pass = pass_size_of(settings, options);
    const int passes_total = pass_count(settings.samples_per_pixel, per_pass);
    // A frame's image is resolved and encoded here while the render goes on, on the same cores:
    // about 25 ms for 800x600 pixels. A pass's frame that comes sooner than nineteen times the
    // last frame's making after it is left out (the next one shows it), so that the frames cost
    // the render at most a twentieth of its time (bench/serve/run.py measures it).
    Clock::time_point next_frame = start;
    for (int published = 0;;) {
        bool last = false;
        {
            std::unique_lock lock(pass_mutex);
            pass_done.wait(lock, [&] { return finished || passes_signalled > published; });
            last = finished;
            published = finished ? passes_total : passes_signalled;
            if (last && !complete) break;
        }
        const Clock::time_point making = Clock::now();
        if (!last && making < next_frame) continue;
        Frame frame;
        frame.version = view.version;
        frame.preview = preview;
        frame.width = settings.width;
        frame.height = settings.height;
        frame.passes_done = published;
        frame.passes_total = passes_total;
        frame.samples_total = settings.samples_per_pixel;
        frame.samples_done = std::min(settings.samples_per_pixel, published * per_pass);
        frame.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        frame.seconds_left = frame.seconds / published * (passes_total - published);
        RenderResult so_far = job.result_so_far();
        frame.image = std::make_shared<const Image>(std::move(so_far.image));
        frame.aovs = std::make_shared<const std::vector<AovImage>>(std::move(so_far.aovs));
        // The last frame's PNG is glint render's; the others are shown once and thrown away.
        frame.png = std::make_shared<const std::string>(
            png_bytes(*frame.image, last ? PngDeflate::fast : PngDeflate::stored));
        frame.error = view.scene_error;
        publish(std::move(frame));
        if (last) break;
        next_frame = Clock::now() + 19 * (Clock::now() - making);
    }
    return complete;
}

LiveRender::Explained LiveRender::explain(int x, int y, int sample, const std::string& integrator) {
    std::shared_ptr<const World> world;
    View view;
    CameraSpec camera;
    bool built = false;
    {
        const std::lock_guard lock(mutex_);
        world = world_;
        view = world_view_;
        camera = world_camera_;
        if (!integrator.empty() && explain_version_ == view.version &&
            explain_integrator_ == integrator) {
            world = explain_world_;
            built = true;
        }
    }
    if (!world) throw std::runtime_error("the view is not built yet");
    if (!integrator.empty() && !built &&
        integrator != integrator_name(world->settings().integrator)) {
        View other = view;
        other.settings.overrides.integrator = integrator;
        other.settings.aovs = {};
        world = std::make_shared<const World>(scene_of(other), other.settings.accel);
        const std::lock_guard lock(mutex_);
        explain_world_ = world;
        explain_version_ = view.version;
        explain_integrator_ = integrator;
    }
    Explained out;
    out.version = view.version;
    const PixelSample which{x, y, sample, 0};
    check_explainable(world->settings(), which);
    const RayTree tree = glint::explain(*world, which);
    out.tree_json = ray_tree_json(tree);
    // Missed rays drawn far enough to leave the picture.
    const float reach = 1e3f * std::max(1.0f, distance(camera.from, camera.at));
    out.overlay =
        ray_tree_overlay(tree, camera, world->settings().width, world->settings().height, reach);
    return out;
}

}  // namespace glint::serve
