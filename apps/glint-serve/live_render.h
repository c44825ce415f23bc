// One page's render of the scene, with the page's own camera and settings, rendered again from
// the start whenever they or the scene's files change: a coarse preview first, then the image
// pass by pass, each as a PNG for the page to fetch. A change cancels the render in flight at
// once. The render is the library's render job, on a thread of this render's own.
#pragma once

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "glint/accel/make_aggregate.h"
#include "glint/render/explain/ray_tree_overlay.h"
#include "glint/render/render_job.h"
#include "glint/render/world.h"
#include "glint/scene/setting_overrides.h"
#include "render_slots.h"
#include "watched_scene.h"

namespace glint::serve {

// What the page may choose besides the camera.
struct PageSettings {
    SettingOverrides overrides;  // integrator, spp and max_depth are the page's
    AccelKind accel = AccelKind::bvh;
    AovSet aovs;  // the output variables recorded, for the page's views of them
};

// What the page is told after the preview and after each pass.
struct Frame {
    int sequence = 0;  // one more for each frame of this render, errors included
    int version = 0;   // of the view (camera, settings and scene) the frame shows
    bool preview = false;
    int width = 0, height = 0;  // of the image in the PNG
    int passes_done = 0, passes_total = 0;
    int samples_done = 0, samples_total = 0;  // a pixel's
    double seconds = 0;                       // since the view's render started
    double seconds_left = 0;                  // estimated from the passes so far
    std::shared_ptr<const Image> image;       // the image so far, linear; the last for an error
    std::shared_ptr<const std::string> png;   // the same as a PNG
    std::shared_ptr<const std::vector<AovImage>> aovs;  // PageSettings::aovs so far
    // Why the view cannot be rendered (a setting it cannot take), or why the scene's files no
    // longer load, as glint prints it. A frame of the error alone (no passes) keeps the last
    // image; while the files stay broken, the last good scene's frames carry it too.
    std::string error;
};

class LiveRender {
public:
    // Starts rendering the scene's view at once, in `slots`' turn, on `threads` (0: all cores).
    LiveRender(const WatchedScene& scene, RenderSlots& slots, int threads);
    // Cancels the render in flight and waits for its thread.
    ~LiveRender();
    LiveRender(const LiveRender&) = delete;
    LiveRender& operator=(const LiveRender&) = delete;

    // Each change returns the version of the view it makes, which the frames that show it carry.
    // The view's camera: the page's from, at, up and projection over the scene's camera, whose
    // lens and shutter stay (a camera path is dropped: the page has moved the camera off it).
    int set_camera(const CameraSpec& camera);
    // Back to the scene's own camera, which follows the file as it changes.
    int reset_camera();
    // Settings checked by check_page_settings.
    int set_settings(const PageSettings& settings);
    CameraSpec camera() const;
    PageSettings settings() const;

    Frame latest() const;
    // The first frame after `sequence`, waiting up to `timeout`; the latest when none came.
    Frame frame_after(int sequence, std::chrono::milliseconds timeout) const;

    // The ray tree of one sample of the view last rendered, as `glint explain --format json`
    // writes it, and drawn over the image: traced by the view's integrator, or by the one
    // named (in a world of the view built for it). Throws SettingsError for a pixel, sample or
    // integrator it cannot take, and std::runtime_error before the first view is built.
    struct Explained {
        std::string tree_json;
        std::vector<OverlaySegment> overlay;
        int version = 0;
    };
    Explained explain(int x, int y, int sample, const std::string& integrator = {});

private:
    struct View {
        int version = 0;
        std::shared_ptr<const Scene> scene;
        std::optional<CameraSpec> camera;
        PageSettings settings;
        std::string scene_error;  // why the scene's files no longer load: `scene` is the last good
    };
    void run();
    void render_view(const View& view);
    Scene scene_of(const View& view) const;
    // Runs the job to its end or a stop, publishing a frame after each pass; false when stopped.
    bool run_job(const World& world, const View& view, bool preview);
    void publish(Frame frame);
    int changed();                  // under mutex_: a new version, the render in flight cancelled
    bool stale(int version) const;  // under mutex_

    const WatchedScene& scene_;
    RenderSlots& slots_;
    int threads_;

    mutable std::mutex mutex_;
    std::condition_variable changed_;  // the view changed, or the render is closing
    mutable std::condition_variable published_;
    int version_ = 0;
    bool closing_ = false;
    std::optional<CameraSpec> camera_;  // none: the scene's
    PageSettings settings_;
    RenderJob* running_ = nullptr;  // the job in flight, for a change to cancel
    std::shared_ptr<const World> world_;
    View world_view_;
    CameraSpec world_camera_;  // the world's, as the view made it
    // A world of world_view_ for another integrator's ray trees, and its integrator.
    std::shared_ptr<const World> explain_world_;
    int explain_version_ = -1;
    std::string explain_integrator_;
    Frame latest_;
    std::thread thread_;
};

// The scene's settings with the page's; throws SettingsError for settings the scene cannot be
// rendered with, as glint render's options and Python's arguments are checked.
RenderSettings check_page_settings(const Scene& scene, const PageSettings& settings);

}  // namespace glint::serve
