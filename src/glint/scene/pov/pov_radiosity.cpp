#include "glint/scene/pov/pov_radiosity.h"

#include <algorithm>
#include <cstdio>

namespace glint {

namespace {

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
}

// A setting's value checked against POV-Ray's range for it.
double ranged(PovParser& parser, const std::string& name, double low, double high) {
    const PovToken at = parser.peek();
    const double value = parser.finite_float("after " + name);
    if (!(value >= low && value <= high))
        throw parser.error_at(at, name + " must be in [" + number(low) + ", " + number(high) +
                                      "], got " + number(value));
    return value;
}

}  // namespace

PovRadiosity read_pov_radiosity(PovParser& parser, PovItemReader& items) {
    PovRadiosity r;
    parser.expect("{", "after radiosity");
    for (PovToken t = parser.next(); !t.is_symbol("}"); t = parser.next()) {
        const std::string& w = t.text;
        if (w == "brightness") {
            const PovToken at = parser.peek();
            r.brightness = parser.finite_float("after brightness");
            if (!(r.brightness > 0))
                throw parser.error_at(at,
                                      "brightness must be above 0, got " + number(r.brightness));
        } else if (w == "recursion_limit") {
            // The diffuse bounces gathered: glint's paths bounce to max_trace_level.
            parser.whole_number("after recursion_limit", 1, 20);
        } else if (w == "count" || w == "nearest_count") {
            // How many rays a cached point gathers (and from what pool of directions), and how
            // many cached points a pixel blends: the cache's, which a path tracer has not.
            const int most = w == "count" ? 1600 : 20;
            parser.whole_number("after " + w, 1, most);
            if (parser.accept(",")) parser.whole_number("after " + w + "'s comma", 1, 1 << 24);
        } else if (w == "max_sample") {
            parser.finite_float("after max_sample");  // at most 0: no limit
        } else if (w == "error_bound" || w == "maximum_reuse" || w == "distance_maximum") {
            const PovToken at = parser.peek();
            if (parser.finite_float("after " + w) < 0)
                throw parser.error_at(at, w + " must not be negative");
        } else if (w == "adc_bailout" || w == "gray_threshold" || w == "low_error_factor" ||
                   w == "minimum_reuse" || w == "pretrace_start" || w == "pretrace_end") {
            ranged(parser, w, 0, 1);
        } else if (w == "always_sample" || w == "normal" || w == "media" || w == "subsurface") {
            items.optional_amount();
        } else if (w == "load_file" || w == "save_file") {
            parser.string_expression("after " + w);
        } else {
            throw parser.error_at(t, describe(t) + " is not a radiosity setting",
                                  {"docs/povray.md lists what glint reads"});
        }
    }
    return r;
}

void light_by_radiosity(const PovRadiosity& radiosity, bool legacy, Scene& scene,
                        std::vector<std::string>& warnings) {
    const bool media = !scene.atmosphere.empty() ||
                       std::any_of(scene.materials.begin(), scene.materials.end(),
                                   [](const Material& m) { return !m.media.empty(); });
    if (media) {
        warnings.push_back(
            "global_settings radiosity { } is ignored: the scene holds media, which the path "
            "integrator does not march, so glint renders it without the light surfaces reflect "
            "onto one another");
        return;
    }
    scene.settings.integrator = IntegratorKind::path;
    scene.settings.samples_per_pixel =
        std::max(scene.settings.samples_per_pixel, kPovRadiositySamples);
    if (legacy) {
        // POV-Ray 3.6 lights a surface by its ambient term as well as by what radiosity
        // gathers, and gathers that term from the surfaces around: a glow in its own colour.
        for (Material& m : scene.materials) {
            const Color glow = scene.ambient * m.ka;
            if (is_black(glow)) continue;
            MaterialMaps maps = m.maps ? *m.maps : MaterialMaps{};
            maps.color_emission += glow;
            m.maps = std::make_shared<const MaterialMaps>(std::move(maps));
        }
    }
    scene.ambient = Color{};
    if (radiosity.brightness != 1)
        warnings.push_back("radiosity's brightness " + number(radiosity.brightness) +
                           " is read past: glint's path tracer gathers the light as it is");
}

}  // namespace glint
