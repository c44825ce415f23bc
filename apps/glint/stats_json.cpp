// The --stats JSON written by hand: its few keys need no JSON library, only escaped strings.
#include "stats_json.h"

#include <sstream>

#include "glint/render/json_string.h"

namespace glint::cli {

namespace {

std::string seconds_or_null(std::optional<double> seconds) {
    if (!seconds) return "null";
    std::ostringstream text;
    text.precision(6);
    text << *seconds;
    return text.str();
}

}  // namespace

std::string stats_json(const RenderReport& report) {
    const RenderResult& r = *report.result;
    const double mrays = r.seconds > 0 ? double(r.rays.total()) / r.seconds / 1e6 : 0;
    std::ostringstream json;
    json.precision(6);
    json << "{\n"
         << "  \"scene\": " << json_string(report.scene) << ",\n"
         << "  \"output\": " << json_string(report.output) << ",\n"
         << "  \"width\": " << report.width << ",\n"
         << "  \"height\": " << report.height << ",\n"
         << "  \"samples_per_pixel\": " << report.samples_per_pixel << ",\n"
         << "  \"threads\": " << report.threads << ",\n"
         << "  \"complete\": " << (r.complete ? "true" : "false") << ",\n"
         << "  \"seconds\": " << r.seconds << ",\n"
         << "  \"rays\": {\n";
    for (std::size_t kind = 0; kind < kRayKindCount; ++kind) {
        json << "    \"" << kRayKindNames[kind] << "\": " << r.rays.traced[kind] << ",\n";
        if (RayKind(kind) == RayKind::primary)
            json << "    \"primary_hits\": " << r.rays.primary_hits << ",\n";
    }
    json << "    \"particles\": " << r.rays.particles << ",\n"
         << "    \"particles_seen\": " << r.rays.particles_seen << ",\n"
         << "    \"photons_stored\": " << r.rays.photons_stored << ",\n"
         << "    \"shadow_map_lookups\": " << r.rays.shadow_map_lookups << ",\n";
    json << "    \"total\": " << r.rays.total() << "\n"
         << "  },\n"
         << "  \"times\": {\n"
         << "    \"load\": " << seconds_or_null(report.phases.load) << ",\n"
         << "    \"build\": " << seconds_or_null(report.phases.build) << ",\n"
         << "    \"render\": " << r.seconds << ",\n"
         << "    \"write\": " << seconds_or_null(report.phases.write) << ",\n"
         << "    \"process\": " << report.process_seconds << "\n"
         << "  },\n"
         << "  \"mrays_per_second\": " << mrays << ",\n"
         << "  \"bad_samples\": " << r.bad_samples.count << "\n"
         << "}\n";
    return json.str();
}

}  // namespace glint::cli
