// The scene a server shows: loaded from its file, and loaded again when that file or any file
// it read (meshes, textures, material libraries) changes. A version that fails to load leaves
// the last good scene in place beside its error, as glint prints it.
#pragma once

#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "glint/scene/load_scene.h"
#include "glint/scene/scene.h"

namespace glint::serve {

class WatchedScene {
public:
    // Loads the scene; throws what load_scene throws, for the server to refuse to start.
    WatchedScene(std::filesystem::path file, LoadOptions options);

    struct Loaded {
        int generation = 0;                  // one more each time the files changed
        std::shared_ptr<const Scene> scene;  // the last that loaded
        std::string error;                   // the newest version's error; empty when it loaded
    };
    Loaded current() const;
    const std::filesystem::path& file() const { return file_; }

    // Looks at the files' sizes and times, and loads the scene again when one changed and has
    // stayed as it is since the previous look: an editor that empties the file, then writes it,
    // is not caught in between. Returns whether it loaded. Called by one thread at a time.
    bool reload_if_changed();

private:
    struct Stamp {
        std::filesystem::path path;
        std::filesystem::file_time_type time;
        std::uintmax_t size = 0;
        bool exists = false;
        bool operator==(const Stamp&) const = default;
    };
    static Stamp stamp_of(const std::filesystem::path& path);
    // Watches what `scene` read (or, when it failed, what was watched), stamped as `seen`
    // before the load where it can be.
    void watch(const Scene* scene, const std::vector<Stamp>& seen);

    std::filesystem::path file_;
    LoadOptions options_;
    std::vector<Stamp> stamps_;    // the scene file's first
    std::vector<Stamp> settling_;  // what the last look saw, when it differed from stamps_
    mutable std::mutex mutex_;     // over loaded_
    Loaded loaded_;
};

// A load's failure as glint prints it: a scene error at its place, with the line and a caret.
std::string load_error_text(const std::exception& error);

}  // namespace glint::serve
