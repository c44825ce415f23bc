// Turns an NFF description into a glint Scene, rendered as the Standard Procedural Databases
// prescribe: the file's view and resolution, a ray tree of depth 5 without adaptive cut-off, and
// the light and material conventions documented in docs/nff.md.
#pragma once

#include <cstdint>
#include <filesystem>

#include "glint/scene/nff/nff_parser.h"
#include "glint/scene/nff/nff_scene.h"
#include "glint/scene/scene.h"

namespace glint {

// Throws SceneError when the file has no view.
Scene nff_to_scene(const NffScene& nff);

// load_nff (plain or gzip-compressed, at most max_bytes uncompressed) then nff_to_scene, with a
// view of no more pixels than limits allow. Throws SceneError only.
Scene load_nff_scene(const std::filesystem::path& file, std::uint64_t max_bytes = kMaxNffFileBytes,
                     const SceneLimits& limits = {});

}  // namespace glint
