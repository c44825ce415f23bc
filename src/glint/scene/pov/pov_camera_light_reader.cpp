// Reads POV-Ray's camera, light_source and sky_sphere blocks as written; pov_scene.cpp aims the
// camera and maps the lights onto glint's, pov_sky.cpp bakes the sky.
#include <memory>
#include <optional>
#include <string_view>

#include "glint/scene/pov/pov_item_reader.h"

namespace glint {

namespace {

// POV-Ray's wide camera types (cylinder takes its kind after it).
std::optional<Projection> wide_projection(std::string_view w) {
    if (w == "fisheye") return Projection::fisheye;
    if (w == "ultra_wide_angle") return Projection::ultra_wide_angle;
    if (w == "panoramic") return Projection::panoramic;
    if (w == "cylinder") return Projection::cylindrical;
    if (w == "spherical") return Projection::spherical;
    return std::nullopt;
}

}  // namespace

PovCamera PovItemReader::camera(const PovToken& keyword) {
    parser_.expect("{", "after camera");
    PovCamera c;
    if (auto declared_camera = take_declared<PovCamera>()) {
        c = *declared_camera;
    }
    c.at = keyword.at;
    for (PovToken t = parser_.next(); !t.is_symbol("}"); t = parser_.next()) {
        const std::string& w = t.text;
        if (w == "perspective" || w == "orthographic") {
            c.orthographic = w == "orthographic";
            c.wide.reset();
        } else if (const auto wide = wide_projection(w)) {
            c.orthographic = false;
            c.wide = *wide;
            if (*wide == Projection::cylindrical)
                c.cylinder_kind = parser_.whole_number("after cylinder", 1, 4);
        } else if (w == "location")
            c.location = parser_.finite_vector("after location");
        else if (w == "look_at")
            c.look_at = parser_.finite_vector("after look_at");
        else if (w == "direction")
            c.direction = parser_.finite_vector("after direction");
        else if (w == "up" || w == "right") {
            (w == "up" ? c.up : c.right) = parser_.finite_vector("after " + w);
            c.sized = true;
        } else if (w == "sky")
            c.sky = parser_.finite_vector("after sky");
        else if (w == "angle") {
            // An orthographic camera's angle may come without a number: the view of a
            // perspective camera's default angle.
            c.angle = c.orthographic && !number_next() ? std::optional<double>(0)
                                                       : parser_.finite_float("after angle");
            // A spherical camera's vertical angle may follow its horizontal one.
            if (c.wide == Projection::spherical && (parser_.accept(",") || number_next()))
                c.vertical_angle = parser_.finite_float("as the spherical camera's vertical angle");
        } else if (w == "focal_point")
            c.focal_point = parser_.finite_vector("after focal_point");
        else if (w == "aperture")
            c.aperture = parser_.finite_float("after aperture");
        else if (w == "blur_samples") {
            c.blur_samples = parser_.whole_number("after blur_samples", 1, 1 << 16);
            if (parser_.accept(",")) parser_.finite_float("after blur_samples");
        } else if (w == "confidence" || w == "variance")
            parser_.finite_float("after " + w);
        else if (const auto step = transform_step(t))
            c.transform = *step * c.transform;
        else
            throw parser_.error_at(t, describe(t) + " is not supported in a camera yet",
                                   {kSeeCompatibility});
    }
    return c;
}

PovSkySphere PovItemReader::sky_sphere(const PovToken& keyword) {
    parser_.expect("{", "after sky_sphere");
    PovSkySphere sky;
    if (auto declared_sky = take_declared<PovSkySphere>()) {
        sky = *declared_sky;
    }
    for (PovToken t = parser_.next(); !t.is_symbol("}"); t = parser_.next()) {
        if (t.is_word("pigment"))
            sky.pigments.push_back(pigment({}));
        else if (t.is_word("emission"))
            sky.emission = parser_.color_expression("after emission");
        else if (const auto step = transform_step(t))
            sky.transform = *step * sky.transform;
        else if (t.kind == PovTokenKind::end)
            throw parser_.error_at(keyword, "sky_sphere { is not closed by }");
        else
            throw parser_.error_at(t, describe(t) + " is not supported in a sky_sphere yet",
                                   {kSeeCompatibility});
    }
    return sky;
}

PovFog PovItemReader::fog(const PovToken& keyword) {
    parser_.expect("{", "after fog");
    PovFog fog;
    fog.at = keyword.at;
    for (PovToken t = parser_.peek(); !t.is_symbol("}"); t = parser_.peek()) {
        const std::string& w = t.text;
        if (w == "color" || w == "colour" || w.starts_with("rgb")) {
            fog.color = parser_.color_expression("of the fog");
            continue;
        }
        parser_.next();
        if (w == "fog_type")
            fog.type = parser_.whole_number("after fog_type", 1, 2);
        else if (w == "distance")
            fog.distance = parser_.finite_float("after distance");
        else if (w == "fog_offset")
            fog.offset = parser_.finite_float("after fog_offset");
        else if (w == "fog_alt")
            fog.alt = parser_.finite_float("after fog_alt");
        else if (w == "up")
            fog.up = parser_.finite_vector("after up");
        else if (w == "turbulence")
            fog.turbulence = parser_.finite_vector("after turbulence");
        else if (w == "turb_depth")
            fog.turbulence_depth = parser_.finite_float("after turb_depth");
        else if (w == "octaves" || w == "omega" || w == "lambda") {
            parser_.finite_float("after " + w);
            if (!warned_fog_noise_)
                warnings_.push_back("fog " + w + ": glint's turbulence keeps its own octaves");
            warned_fog_noise_ = true;
        } else if (t.kind == PovTokenKind::end)
            throw parser_.error_at(keyword, "fog { is not closed by }");
        else
            throw parser_.error_at(t, describe(t) + " is not supported in a fog yet",
                                   {kSeeCompatibility});
    }
    parser_.next();
    return fog;
}

PovLight PovItemReader::light_source(const PovToken& keyword) {
    parser_.expect("{", "after light_source");
    PovLight light;
    if (auto declared_light = declared<PovObject>(parser_.peek_item());
        declared_light && declared_light->light) {
        parser_.next();
        light = *declared_light->light;
        light.transform = declared_light->transform * light.transform;
    } else {
        light.position = parser_.finite_vector("as the light's position");
        parser_.accept(",");
        light.color = parser_.color_expression("as the light's colour");
    }
    light.at = keyword.at;
    for (PovToken t = parser_.next(); !t.is_symbol("}"); t = parser_.next()) {
        const std::string& w = t.text;
        if (w == "spotlight")
            light.kind = PovLight::Kind::spot;
        else if (w == "parallel")
            light.kind = PovLight::Kind::parallel;
        else if (w == "point_at")
            light.point_at = parser_.finite_vector("after point_at");
        else if (w == "radius")
            light.radius = parser_.finite_float("after radius");
        else if (w == "falloff")
            light.falloff = parser_.finite_float("after falloff");
        else if (w == "tightness") {
            const PovToken at = parser_.peek();
            light.tightness = parser_.finite_float("after tightness");
            if (!(light.tightness >= 0)) throw parser_.error_at(at, "tightness must be >= 0");
        } else if (w == "area_light") {
            light.area_u = parser_.finite_vector("as the area light's first axis");
            parser_.accept(",");
            light.area_v = parser_.finite_vector("as the area light's second axis");
            parser_.accept(",");
            light.n1 = parser_.whole_number("as the area light's first count", 1, 64);
            parser_.accept(",");
            light.n2 = parser_.whole_number("as the area light's second count", 1, 64);
        } else if (w == "adaptive")
            parser_.finite_float("after adaptive");
        else if (w == "jitter" || w == "orient") {
        } else if (w == "circular")
            light.circular = true;
        else if (w == "fade_distance")
            light.fade_distance = parser_.finite_float("after fade_distance");
        else if (w == "fade_power")
            light.fade_power = parser_.finite_float("after fade_power");
        else if (w == "shadowless")
            light.shadowless = true;
        else if (w == "photons") {
            parser_.skip_braced(t);
            read_past("photons { } in a light_source",
                      "the Whitted and distributed integrators trace no photons");
        } else if (w == "media_interaction" || w == "media_attenuation") {
            const double on = optional_amount();
            if (w == "media_interaction")
                light.media_interaction = on != 0;
            else if (on != 0)  // the media inside objects dim every feeler that crosses them
                read_past("media_attenuation on", "the atmosphere does not dim shadow feelers");
        } else if (w == "looks_like") {
            parser_.expect("{", "after looks_like");
            const PovToken inner = parser_.next();
            if (!starts_object(inner.text) || inner.kind != PovTokenKind::identifier)
                throw parser_.error_at(
                    inner, "expected an object in looks_like { }, got " + describe(inner));
            light.looks_like = std::make_shared<const PovObject>(object(inner));
            parser_.expect("}", "after the looks_like object");
        } else if (const auto step = transform_step(t))
            light.transform = *step * light.transform;
        else
            throw parser_.error_at(t, describe(t) + " is not supported in a light_source yet",
                                   {kSeeCompatibility});
    }
    return light;
}

}  // namespace glint
