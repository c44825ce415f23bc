// The memory a render will take beyond its loaded scene (the acceleration structure over the
// scene's primitives, the film and the images), worked out before any of it is built, so that a
// render too large for the machine is refused with a clear error instead of being killed for
// want of memory halfway through.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "glint/accel/make_aggregate.h"
#include "glint/render/film/aov.h"
#include "glint/scene/scene.h"

namespace glint {

struct MemoryEstimate {
    std::uint64_t references = 0;    // primitives, each mesh's triangles counted one by one
    std::uint64_t acceleration = 0;  // bytes: the structure over the references, shadow maps
    // Bytes: the render's state (the film's sums, each pixel's samples taken and, under adaptive
    // sampling, its error), the images made from it and the buffers of the files written.
    std::uint64_t film = 0;

    std::uint64_t total() const { return acceleration + film; }
};

// What a render does beside making its image.
struct RenderExtras {
    bool samples_image = false;  // writes the image of samples taken
    bool resuming = false;       // reads its state from a resume file first
    AovSet aovs;                 // writes these output variables
};

// An upper estimate for `scene` (after any change to its settings) rendered with `accel`.
MemoryEstimate estimate_render_memory(const Scene& scene, AccelKind accel,
                                      const RenderExtras& extras = {});

// Why a render of `scene` with `accel`, which needs `need`, is refused: more than `limit` where
// one is given (the setting named `limit_setting`, "--max-memory" on the command line), else
// than the memory available. Nothing when it fits, or when the available memory is unknown.
// "the render needs about 14 GiB of memory (the bvh 1.0 MiB for 6 primitives and triangles,
// the film 14 GiB for 16000x12000 pixels), more than the 1.0 GiB --max-memory allows; render
// fewer pixels, or set the limit with --max-memory SIZE".
std::optional<std::string> memory_refusal(const Scene& scene, AccelKind accel,
                                          const MemoryEstimate& need,
                                          std::optional<std::uint64_t> limit,
                                          std::string_view limit_setting);

// The memory this process may still take: the system's available memory (MemAvailable), or
// less where a control group limits the process. Nothing where neither can be read.
std::optional<std::uint64_t> available_memory();

// "1.5 GiB", "640 MiB", "12 KiB", "512 bytes".
std::string format_bytes(std::uint64_t bytes);
// A count with its thousands apart: "1,254,001".
std::string with_thousands(std::uint64_t n);

// A size as users write it: a whole number of bytes, or a number with K, M, G or T (powers of
// 1024, an optional "iB" or "B" after it): "512M", "1.5G", "2GiB". Nothing for anything else.
std::optional<std::uint64_t> parse_bytes(const std::string& text);

}  // namespace glint
