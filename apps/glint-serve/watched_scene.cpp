// Files are compared by size and modification time: an editor's save changes one or the other,
// and reading them whole at every look would cost as much as loading the scene.
#include "watched_scene.h"

#include <system_error>
#include <utility>

#include "glint/scene/scene_error.h"

namespace glint::serve {

WatchedScene::WatchedScene(std::filesystem::path file, LoadOptions options)
    : file_(std::move(file)), options_(std::move(options)) {
    auto scene = std::make_shared<const Scene>(load_scene(file_, options_));
    watch(scene.get());
    loaded_.scene = std::move(scene);
}

WatchedScene::Loaded WatchedScene::current() const {
    const std::lock_guard lock(mutex_);
    return loaded_;
}

WatchedScene::Stamp WatchedScene::stamp_of(const std::filesystem::path& path) {
    std::error_code error;
    Stamp stamp{path};
    stamp.time = std::filesystem::last_write_time(path, error);
    if (error) return stamp;
    stamp.size = std::filesystem::file_size(path, error);
    stamp.exists = !error;
    return stamp;
}

void WatchedScene::watch(const Scene* scene) {
    // A scene that failed to load is watched through its own file and the files the last good
    // one read: fixing either is a change.
    std::vector<Stamp> stamps{stamp_of(file_)};
    if (scene)
        for (const std::filesystem::path& path : scene->sources.files_read)
            stamps.push_back(stamp_of(path));
    else
        stamps.insert(stamps.end(), stamps_.begin() + (stamps_.empty() ? 0 : 1), stamps_.end());
    stamps_ = std::move(stamps);
}

bool WatchedScene::reload_if_changed() {
    bool changed = false;
    for (const Stamp& stamp : stamps_) changed = changed || stamp_of(stamp.path) != stamp;
    if (!changed) return false;
    std::shared_ptr<const Scene> scene;
    std::string error;
    try {
        scene = std::make_shared<const Scene>(load_scene(file_, options_));
    } catch (const std::exception& e) {
        error = load_error_text(e);
    }
    watch(scene.get());
    const std::lock_guard lock(mutex_);
    ++loaded_.generation;
    loaded_.error = std::move(error);
    if (scene) loaded_.scene = std::move(scene);
    return true;
}

std::string load_error_text(const std::exception& error) {
    if (const auto* scene_error = dynamic_cast<const SceneError*>(&error))
        return format_scene_error(*scene_error);
    return std::string("error: ") + error.what();
}

}  // namespace glint::serve
