// The memory a render will take beyond its loaded scene (the acceleration structure over the
// scene's primitives, the film and the images), worked out before any of it is built, so that a
// render too large for the machine is refused with a clear error instead of being killed for
// want of memory halfway through.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

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

// The memory this process may still take: the system's available memory (MemAvailable), or
// less where a control group limits the process. Nothing where neither can be read.
std::optional<std::uint64_t> available_memory();

// "1.5 GiB", "640 MiB", "12 KiB", "512 bytes".
std::string format_bytes(std::uint64_t bytes);

// A size as users write it: a whole number of bytes, or a number with K, M, G or T (powers of
// 1024, an optional "iB" or "B" after it): "512M", "1.5G", "2GiB". Nothing for anything else.
std::optional<std::uint64_t> parse_bytes(const std::string& text);

}  // namespace glint
