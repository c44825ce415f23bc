// The render's memory worked out from counts: references times what each structure was measured
// to take per reference, pixels times the film's bytes a pixel.
#include "glint/render/memory_estimate.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "glint/accel/primitive_refs.h"
#include "glint/render/eye_sample.h"
#include "glint/render/film/film.h"
#include "glint/render/film/pixel_error.h"
#include "glint/render/integrators/photon_map.h"

namespace glint {

namespace {

// Bytes a reference at most: the structure's nodes, lists and reference copies, and a mesh's
// own data. Measured with `glint bench` (its bytes_per_prim) over the SPD scenes, the Stanford
// bunny and spot, whose largest were bvh 78, grid 78, kdtree 376 and embree 333 (on 9
// primitives; 166 on 68,276), and given room.
std::uint64_t bytes_per_reference(AccelKind accel) {
    switch (accel) {
        case AccelKind::list:
            return sizeof(PrimitiveRef);
        case AccelKind::bvh:
            return 96;
        case AccelKind::grid:
            return 128;
        case AccelKind::kdtree:
            return 512;
#ifdef GLINT_HAVE_EMBREE
        case AccelKind::embree:
            return 256;
#endif
    }
    return 512;
}

// What any structure takes however few its primitives (Embree's scene and device, a grid's
// smallest array of cells).
constexpr std::uint64_t kStructureBaseBytes = std::uint64_t(1) << 20;

// The resume file's pieces and zlib's buffers (a state is written as it is packed), and room
// for the few bytes zlib adds to data it cannot pack.
constexpr std::uint64_t kFileBufferBytes = std::uint64_t(4) << 20;

// The value of /proc/meminfo's line "Key:  123 kB", in bytes.
std::optional<std::uint64_t> meminfo_value(const std::string& key) {
    std::ifstream in("/proc/meminfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind(key + ":", 0) != 0) continue;
        std::istringstream fields(line.substr(key.size() + 1));
        std::uint64_t kib = 0;
        if (fields >> kib) return kib * 1024;
    }
    return std::nullopt;
}

std::optional<std::uint64_t> file_number(const char* path) {
    std::ifstream in(path);
    std::uint64_t value = 0;
    if (in >> value) return value;  // "max" (no limit) reads as nothing
    return std::nullopt;
}

}  // namespace

MemoryEstimate estimate_render_memory(const Scene& scene, AccelKind accel,
                                      const RenderExtras& extras) {
    MemoryEstimate e;
    for (const SceneObject& object : scene.objects) e.references += reference_count(object.shape);
    e.acceleration = kStructureBaseBytes + e.references * bytes_per_reference(accel) +
                     scene.objects.size() * sizeof(Primitive);  // the world's copy of the shapes

    const RenderSettings& s = scene.settings;
    const std::uint64_t pixels = std::uint64_t(s.width) * std::uint64_t(s.height);
    const FilterSpec filter = filter_of(s);
    // Films of a pixel's own samples: the one-pixel box's and adaptive sampling's.
    const bool one_pixel =
        (filter.kind == FilterKind::box && filter.radius == 0.5f) || importance_samples_filter(s);
    // The state: the sums, the samples taken, and the error under adaptive sampling.
    std::uint64_t state = (one_pixel ? sizeof(BoxSum) : sizeof(PixelSum)) + sizeof(std::uint32_t);
    if (s.adaptive) state += sizeof(PixelError);
    // The resolved image, and the 8-bit copy a PNG is written from.
    std::uint64_t images = sizeof(Color) + 4;
    if (extras.samples_image) images += 2 * sizeof(Color);  // the counts, and the copy written
    // A resume file read holds the file's bytes and the state unpacked from them, each no larger
    // than the state (but for zlib's few bytes over on data it cannot pack).
    const std::uint64_t resume = extras.resuming ? 2 * state : 0;
    // Each output variable: a film of the image's kind (an id per pixel instead for the ids),
    // the layer resolved, and the copy written (an 8-bit one, or the EXR's floats).
    std::uint64_t aovs = 0;
    for (const Aov a : extras.aovs.list()) {
        const AovKind kind = aov_info(a).kind;
        aovs += kind == AovKind::id      ? sizeof(std::int32_t)
                : kind == AovKind::pixel ? 0
                                         : (one_pixel ? sizeof(BoxSum) : sizeof(PixelSum));
        aovs += 2 * sizeof(Color);
    }
    // The light integrator's film of particles: three 64-bit sums a pixel.
    if (integrator_info(s.integrator).traces_particles) state += 3 * sizeof(std::int64_t);
    e.film = pixels * (state + images + resume + aovs) + kFileBufferBytes;
    // The photon integrator's map of a pass: each photon traced into its block, joined, and
    // sorted into the grid (three copies at most), and two buckets a photon.
    if (s.integrator == IntegratorKind::photon)
        e.film += std::uint64_t(s.photons.per_pass) * (3 * sizeof(Photon) + 2 * 4 + 8);
    // Shadow maps: six faces of depths a light (one for a directional light; counted as six).
    if (s.shadows == ShadowMethod::map) {
        const std::uint64_t face = std::uint64_t(s.shadow_map.resolution) *
                                   std::uint64_t(s.shadow_map.resolution) * sizeof(float);
        e.acceleration += std::uint64_t(scene.lights.size()) * 6 * face;
    }
    return e;
}

std::optional<std::uint64_t> available_memory() {
    std::optional<std::uint64_t> available = meminfo_value("MemAvailable");
    // Under a control group (a container, a systemd slice) its limit may be the tighter one.
    const auto limit = file_number("/sys/fs/cgroup/memory.max");
    const auto used = file_number("/sys/fs/cgroup/memory.current");
    if (limit && used) {
        const std::uint64_t room = *limit > *used ? *limit - *used : 0;
        if (!available || room < *available) available = room;
    }
    return available;
}

std::optional<std::string> memory_refusal(const Scene& scene, AccelKind accel,
                                          const MemoryEstimate& need,
                                          std::optional<std::uint64_t> limit,
                                          std::string_view limit_setting) {
    const std::optional<std::uint64_t> room = limit ? limit : available_memory();
    if (!room || need.total() <= *room) return std::nullopt;
    const RenderSettings& s = scene.settings;
    const std::string setting(limit_setting);
    return "the render needs about " + format_bytes(need.total()) + " of memory (the " +
           std::string(accel_name(accel)) + " " + format_bytes(need.acceleration) + " for " +
           with_thousands(need.references) + " primitives and triangles, the film " +
           format_bytes(need.film) + " for " + std::to_string(s.width) + "x" +
           std::to_string(s.height) + " pixels), more than the " + format_bytes(*room) +
           (limit ? " " + setting + " allows" : std::string(" this machine has available")) +
           "; render fewer pixels, or set the limit with " + setting + " SIZE";
}

std::string with_thousands(std::uint64_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string format_bytes(std::uint64_t bytes) {
    const char* units[] = {"KiB", "MiB", "GiB", "TiB", "PiB"};
    if (bytes < 1024) return std::to_string(bytes) + " bytes";
    double value = double(bytes) / 1024;
    int unit = 0;
    while (value >= 1024 && unit < 4) {
        value /= 1024;
        ++unit;
    }
    char text[32];
    std::snprintf(text, sizeof text, value < 10 ? "%.1f %s" : "%.0f %s", value, units[unit]);
    return text;
}

std::optional<std::uint64_t> parse_bytes(const std::string& text) {
    std::size_t end = 0;
    double number = 0;
    try {
        number = std::stod(text, &end);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (!std::isfinite(number) || number < 0 || text.find_first_of("eExXpP") != std::string::npos)
        return std::nullopt;
    std::string unit = text.substr(end);
    for (const char* suffix : {"iB", "B"}) {
        const std::string s = suffix;
        if (unit.size() > s.size() && unit.compare(unit.size() - s.size(), s.size(), s) == 0) {
            unit.resize(unit.size() - s.size());
            break;
        }
    }
    double scale = 1;
    if (unit == "K" || unit == "k")
        scale = 0x1p10;
    else if (unit == "M")
        scale = 0x1p20;
    else if (unit == "G")
        scale = 0x1p30;
    else if (unit == "T")
        scale = 0x1p40;
    else if (!unit.empty() && unit != "B")
        return std::nullopt;
    const double bytes = number * scale;
    if (bytes >= 0x1p63) return std::nullopt;
    if (unit.empty() && bytes != std::floor(bytes)) return std::nullopt;  // half a byte
    return std::uint64_t(std::llround(bytes));
}

}  // namespace glint
