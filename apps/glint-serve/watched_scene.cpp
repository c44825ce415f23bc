// Files are compared by size and modification time: an editor's save changes one or the other,
// and reading them whole at every look would cost as much as loading the scene. They are stamped
// before they are read, so that a save while the scene loads is seen at the next look. A change
// is loaded at the look after the one that saw it, if nothing changed in between: a save that
// truncates the file and then writes it would otherwise load, now and then, as an empty scene.
#include "watched_scene.h"

#include <algorithm>
#include <system_error>
#include <utility>

#include "glint/scene/scene_error.h"

namespace glint::serve {

WatchedScene::WatchedScene(std::filesystem::path file, LoadOptions options)
    : file_(std::move(file)), options_(std::move(options)) {
    const std::vector<Stamp> seen{stamp_of(file_)};
    auto scene = std::make_shared<const Scene>(load_scene(file_, options_));
    watch(scene.get(), seen);
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

void WatchedScene::watch(const Scene* scene, const std::vector<Stamp>& seen) {
    // A scene that failed to load is watched through its own file and the files the last good
    // one read: fixing either is a change. A file read for the first time can only be stamped
    // after the load that found it.
    std::vector<Stamp> stamps{seen.front()};
    if (scene) {
        for (const std::filesystem::path& path : scene->sources.files_read) {
            const auto before = std::find_if(seen.begin(), seen.end(),
                                             [&](const Stamp& s) { return s.path == path; });
            stamps.push_back(before != seen.end() ? *before : stamp_of(path));
        }
    } else {
        stamps.insert(stamps.end(), seen.begin() + 1, seen.end());
    }
    stamps_ = std::move(stamps);
}

bool WatchedScene::reload_if_changed() {
    std::vector<Stamp> seen;
    for (const Stamp& stamp : stamps_) seen.push_back(stamp_of(stamp.path));
    if (seen == stamps_) {
        settling_.clear();
        return false;
    }
    if (seen != settling_) {  // still changing, or changed just now: look again first
        settling_ = std::move(seen);
        return false;
    }
    settling_.clear();
    std::shared_ptr<const Scene> scene;
    std::string error;
    try {
        scene = std::make_shared<const Scene>(load_scene(file_, options_));
    } catch (const std::exception& e) {
        error = load_error_text(e);
    }
    watch(scene.get(), seen);
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
