// glint-mpi's scene on every rank without a shared file system: rank 0 loads it (in its sandbox)
// and sends the scene file and every file it read; each other rank writes them under a folder of
// its own, at their absolute paths, and loads the scene from there.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>

#include "glint/scene/load_scene.h"
#include "glint/scene/scene.h"

namespace glint::cli {

// Rank 0: sends the scene file, the files `scene` read and the folders it may read; returns the
// bytes of the files.
std::uint64_t share_scene(const std::filesystem::path& scene_file, const Scene& scene,
                          const LoadOptions& options);
// Rank 0: tells the other ranks that loading failed.
void share_failure();

// What rank 0 tells the others instead of a frame when it shares frames out whole next
// (cluster/frame_share.h).
constexpr int kWholeFrames = -1;

// Rank 0: tells the others the frame to set up next (0 for a still), kWholeFrames, or that there
// is none.
void share_frame(int frame);
void share_end_of_frames();

// Every other rank: the frame rank 0 sets up next, or kWholeFrames; none when it has rendered
// them all.
std::optional<int> receive_frame();

// Every other rank: the scene as rank 0 loaded it, its files written under `folder` (which must
// exist, and is the ranks' own); none when rank 0 failed. `options` are the command's, its
// folders moved under `folder`.
std::optional<Scene> receive_scene(const std::filesystem::path& folder, LoadOptions options);

}  // namespace glint::cli
