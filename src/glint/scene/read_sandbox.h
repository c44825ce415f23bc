// The sandbox of a scene's reads: a scene reads files only inside its own folder and the folders
// its user allows (`--allow-read`), so that a scene from elsewhere cannot make glint read, say,
// ~/.ssh through a texture path. docs/reliability.md has what is checked and what is not.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glint/scene/scene_limits.h"

namespace glint {

struct ReadSandbox {
    // Absolute, with every symbolic link resolved; the scene's own folder first.
    std::vector<std::filesystem::path> folders;
    // The largest file of any kind the scene may read (`--max-file-size`); nothing: each kind's
    // own limit (kMaxSceneFileBytes, kMaxMeshFileBytes, ...).
    std::optional<std::uintmax_t> max_file_bytes;
    // What the scene may ask for: image size, samples, depth (and the size of images it reads).
    SceneLimits limits;
    // The files the scene read besides its own, resolved, each once, in the order first read
    // (record_read): what a resume file checks for changes. Shared by the sandbox's copies, as
    // Assimp's file system keeps one; a scene is loaded on one thread.
    std::shared_ptr<std::vector<std::filesystem::path>> files_read =
        std::make_shared<std::vector<std::filesystem::path>>();

    // The limit for a kind of file whose own limit is `kind_limit`.
    std::uintmax_t file_limit(std::uintmax_t kind_limit) const {
        return max_file_bytes.value_or(kind_limit);
    }
};

// A file limit as messages give it: "64 MiB", or "1000 bytes" when not whole mebibytes.
std::string describe_file_limit(std::uintmax_t bytes);

// The note that goes with a file refused for its size.
inline constexpr const char* kRaiseFileLimitNote = "raise the limit with --max-file-size SIZE";

// The sandbox of a scene (or model) file: its own folder and `allowed`. Throws SceneError for an
// allowed folder that does not exist or is not a folder.
ReadSandbox make_read_sandbox(const std::filesystem::path& scene_file,
                              std::span<const std::filesystem::path> allowed = {},
                              std::optional<std::uintmax_t> max_file_bytes = {});

// Where a path leads: absolute, with ".", ".." and the symbolic links of the part that exists
// resolved (std::filesystem::weakly_canonical). Nothing when it cannot be worked out (a loop
// of links, a folder that cannot be searched).
std::optional<std::filesystem::path> resolve_path(const std::filesystem::path& path);

// Whether `path` is `folder` or lies under it, compared component by component: /a/bc is not
// inside /a/b. Both are taken as they are; callers pass resolved paths.
bool is_inside(const std::filesystem::path& path, const std::filesystem::path& folder);

// Whether the sandbox lets the file at `path` (as the loader will open it) be read: it lies
// inside an allowed folder, and is a regular file if it exists (a pipe would block the open and
// a device like /dev/zero never end).
bool may_read(const ReadSandbox& sandbox, const std::filesystem::path& path);

// Notes that the scene read `path` (a file the sandbox allowed) into sandbox.files_read.
void record_read(const ReadSandbox& sandbox, const std::filesystem::path& path);

// Why a path is refused, for the error the caller places (at the YAML key, the OBJ line, ...).
struct ReadRefusal {
    std::string message;
    std::vector<std::string> notes;
};

// Nothing when the sandbox allows `path`; otherwise the error's text. `what` names the file's
// role ("texture", "mesh file") and `written` is the path as the file gives it.
std::optional<ReadRefusal> check_read(const ReadSandbox& sandbox, const std::filesystem::path& path,
                                      std::string_view what, std::string_view written);

}  // namespace glint
