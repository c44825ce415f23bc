// The resume file an interrupted render leaves beside its image ("image.png.resume"): what the
// render was, to refuse continuing another, and its RenderState, zlib-compressed. The format is
// described in docs/cli.md.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "glint/render/render.h"
#include "glint/render/render_part.h"
#include "glint/render/render_state.h"
#include "glint/scene/scene.h"

namespace glint {

// A file a scene was made from, as it was when the render began.
struct FileStamp {
    std::string path;  // absolute
    std::uint64_t size = 0;
    std::uint32_t crc = 0;  // CRC-32 of its bytes
    bool readable = true;   // false: not a regular file, or it could not be read
    bool operator==(const FileStamp&) const = default;
};

// Everything that decides a render's image (the acceleration structure and the thread count do
// not), and the version of glint that rendered it.
struct RenderIdentity {
    std::string glint_version;
    std::string scene_path;  // absolute
    // The scene file first, then every file it read (Scene::sources.files_read).
    std::vector<FileStamp> files;
    int width = 0, height = 0, samples_per_pixel = 0;
    std::uint64_t seed = 0;
    IntegratorKind integrator{};
    SamplerKind sampler{};
    FilterSpec filter;
    int max_depth = 0;
    std::optional<AdaptiveSampling> adaptive;
    int tile_size = 0;
    int pass_size = 0;           // samples_per_pass
    WorkingSpace working_space;  // what the film's values are decoded from
    RenderPart part;             // the part of the render (render_part.h); whole by default
};

// The identity of a render of `scene_file`, which read `files_read`, with the settings it was
// loaded with and the options given. Every file is read here, to stamp it.
RenderIdentity identify_render(const std::filesystem::path& scene_file,
                               std::span<const std::filesystem::path> files_read,
                               const RenderSettings& settings, const RenderOptions& options,
                               std::string_view glint_version, const RenderPart& part = {});

// What differs between the render a file was written for and this one, first difference first
// ("written for seed 3, not 7"); empty when they are the same.
std::string identity_difference(const RenderIdentity& was, const RenderIdentity& now);

// The settings a render of `identity` was made with, as far as its state needs them (its image,
// film, samples and integrator): to read a saved state without its scene.
RenderSettings settings_of(const RenderIdentity& identity);

// A resume file that cannot be used: missing, of another render, truncated or corrupt. Its
// message names the file and says what is wrong.
struct ResumeError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "<output>.resume": image.png -> image.png.resume.
std::filesystem::path resume_path(const std::filesystem::path& output);

// Writes the file atomically (a temporary renamed into place); throws ImageError on failure.
void write_resume_file(const std::filesystem::path& file, const RenderIdentity& identity,
                       const RenderState& state);

// The state saved in `file`, which must have been written for `expected`, whose settings and
// tile and pass sizes are `settings` and expected's. Throws ResumeError naming the first
// difference ("... was written for seed 3, not 7") or the damage.
RenderState read_resume_file(const std::filesystem::path& file, const RenderIdentity& expected,
                             const RenderSettings& settings);

// A render's saved identity and state, read without knowing which render it is (a part file,
// to merge); throws ResumeError naming the damage.
struct SavedRender {
    RenderIdentity identity;
    RenderState state;
};
SavedRender read_saved_render(const std::filesystem::path& file);

}  // namespace glint
