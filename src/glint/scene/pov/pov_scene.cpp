// The top level of a POV-Ray scene: camera, light sources, background, global settings and
// objects, and the mapping of POV-Ray's finishes and objects onto glint's materials and shapes.
#include "glint/scene/pov/pov_scene.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <tuple>

#include "glint/scene/pov/pov_item_reader.h"
#include "glint/scene/pov/pov_radiosity.h"
#include "glint/scene/pov/pov_sky.h"
#include "glint/scene/quote.h"
#include "glint/scene/scene_error.h"

namespace glint {

namespace {

constexpr std::uintmax_t kMaxPovFileBytes = std::uintmax_t(64) << 20;

Color rgb(const PovVector& v) { return {float(v[0]), float(v[1]), float(v[2])}; }

double norm(const PovVector& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

PovVector scaled(const PovVector& v, double s) {
    PovVector r = v;
    for (int i = 0; i < 3; ++i) r[i] = v[i] * s;
    return r;
}

PovVector cross3(const PovVector& a, const PovVector& b) {
    PovVector r = PovVector::of(0, 3);
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
    return r;
}

double dot3(const PovVector& a, const PovVector& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// POV-Ray's scene items, besides objects, that glint does not read yet: their error says so.
bool not_read_yet(const PovToken& token) {
    static const std::string_view kNotYet[] = {"photons", "rainbow"};
    return token.kind == PovTokenKind::identifier &&
           std::find(std::begin(kNotYet), std::end(kNotYet), token.text) != std::end(kNotYet);
}

// The filter and transmit a pigment lets through. A colour map's can vary over the pattern,
// and glint's material has one: the least of its entries', so the object stays as opaque as
// its most opaque part.
double transmitted(const PovPigment& p) {
    if (p.kind != PovPigment::Kind::pattern) return p.color[3] + p.color[4];
    double least = 1;
    for (const PovColorStop& stop : p.map.stops)
        least = std::min(least,
                         stop.pigment ? transmitted(*stop.pigment) : stop.color[3] + stop.color[4]);
    return least;
}

// The share of what the pigment lets through that its filter lets through, coloured by the
// pigment: the material's tint. From the entry that lets the least through, as transmitted().
double filtered_share(const PovVector& c) {
    const double through = c[3] + c[4];
    return through > 0 ? std::clamp(c[3] / through, 0.0, 1.0) : 0.0;
}
double filtered_share(const PovPigment& p) {
    if (p.kind != PovPigment::Kind::pattern) return filtered_share(p.color);
    double least = 2, share = 0;
    for (const PovColorStop& stop : p.map.stops) {
        const double through =
            stop.pigment ? transmitted(*stop.pigment) : stop.color[3] + stop.color[4];
        if (through < least) {
            least = through;
            share = stop.pigment ? filtered_share(*stop.pigment) : filtered_share(stop.color);
        }
    }
    return share;
}

// The first pigment glint does not read yet, at any depth of its pigment_maps.
const PovPigment* unread_pigment(const PovPigment& p) {
    if (p.kind == PovPigment::Kind::unsupported) return &p;
    for (const PovColorStop& stop : p.map.stops)
        if (const PovPigment* unread = stop.pigment ? unread_pigment(*stop.pigment) : nullptr)
            return unread;
    return nullptr;
}

// Images with their texels encoded by a function, each image once however many materials
// show it.
class ImageEncoder {
public:
    explicit ImageEncoder(std::function<Color(Color)> encode) : encode_(std::move(encode)) {}

    // The texture with the images in it, through pigment maps and layers, encoded.
    Texture operator()(const Texture& texture) {
        if (const auto* image = std::get_if<ImageTexture>(&texture)) {
            ImageTexture e = *image;
            e.image = encoded(image->image);
            return e;
        }
        if (const auto* projected = std::get_if<ProjectedImagePtr>(&texture)) {
            auto e = std::make_shared<ProjectedImage>(**projected);
            e->image.image = encoded(e->image.image);
            return e;
        }
        if (const auto* map = std::get_if<PigmentMapPtr>(&texture)) {
            auto e = std::make_shared<PigmentMap>(**map);
            for (PigmentMap::Entry& entry : e->entries) entry.texture = (*this)(entry.texture);
            return e;
        }
        if (const auto* layered = std::get_if<LayeredTexturePtr>(&texture)) {
            auto e = std::make_shared<LayeredTexture>(**layered);
            for (LayeredTexture::Layer& layer : e->layers) layer.color = (*this)(layer.color);
            return e;
        }
        return texture;
    }

private:
    std::shared_ptr<const MipMap> encoded(const std::shared_ptr<const MipMap>& image) {
        std::shared_ptr<const MipMap>& done = done_[image];
        if (!done) {
            Image base = image->base();
            for (Color& texel : base.pixels) texel = encode_(texel);
            done = std::make_shared<const MipMap>(std::move(base));
        }
        return done;
    }

    std::function<Color(Color)> encode_;
    // By the image itself, held so that a freed one's address is never taken for another's.
    std::map<std::shared_ptr<const MipMap>, std::shared_ptr<const MipMap>> done_;
};

bool holds_image(const Texture& texture) {
    if (std::holds_alternative<ImageTexture>(texture) ||
        std::holds_alternative<ProjectedImagePtr>(texture))
        return true;
    if (const auto* map = std::get_if<PigmentMapPtr>(&texture))
        return std::any_of((*map)->entries.begin(), (*map)->entries.end(),
                           [](const PigmentMap::Entry& e) { return holds_image(e.texture); });
    if (const auto* layered = std::get_if<LayeredTexturePtr>(&texture))
        return std::any_of(
            (*layered)->layers.begin(), (*layered)->layers.end(),
            [](const LayeredTexture::Layer& layer) { return holds_image(layer.color); });
    return false;
}

class Builder {
public:
    Builder(PovFiles& files, const ReadSandbox& sandbox)
        : files_(files), parser_(files, options(sandbox)), items_(parser_, scene_.warnings) {
        parser_.set_extent_reader([this](const PovItemRef& ref, const PovToken& at) {
            const auto* object = std::get_if<PovObject>(&ref.item);
            if (!object) throw parser_.error_at(at, "min_extent and max_extent take an object");
            // POV-Ray's huge bound where an object is unbounded.
            const auto corner = [](Point3 p, float huge) {
                const auto c = [&](float v) { return std::isfinite(v) ? double(v) : double(huge); };
                return PovVector{{c(p.x), c(p.y), c(p.z)}};
            };
            const Bounds3 b = items_.extent(*object);
            if (b.is_empty()) return std::pair{PovVector{}, PovVector{}};
            return std::pair{corner(b.min, -1e10f), corner(b.max, 1e10f)};
        });
        parser_.set_trace_reader(
            [this](const std::shared_ptr<const PovItemRef>& ref, const PovVector& from,
                   const PovVector& direction,
                   const PovToken& at) { return trace(ref, from, direction, at); });
        parser_.set_item_reader([this](const PovToken& keyword) -> std::optional<PovValue> {
            auto item = items_.read(keyword);
            if (!item) return std::nullopt;
            return std::make_shared<const PovItemRef>(PovItemRef{std::move(*item)});
        });
        scene_.ambient = {1, 1, 1};               // global_settings' ambient_light
        scene_.settings.min_weight = 1.0f / 255;  // adc_bailout
        // POV-Ray's shadow rays pass through transparent objects, dimmed by what they let through.
        scene_.settings.transparent_shadows = true;
        scene_.camera = default_camera();
    }

    Scene run() {
        for (PovToken t = parser_.next(); t.kind != PovTokenKind::end; t = parser_.next()) {
            const std::string& w = t.text;
            if (t.is_symbol(";")) continue;
            if (w == "camera")
                camera(items_.camera(t));
            else if (w == "sky_sphere") {
                sky_ = items_.sky_sphere(t);
                for (const PovPigment& p : sky_->pigments) refuse_unread(p);
            } else if (w == "background")
                background(t);
            else if (w == "fog")
                fog(items_.fog(t));
            else if (w == "media")
                atmosphere(t);
            else if (w == "global_settings")
                global_settings(t);
            else if (t.is_word("default"))
                items_.read(t);
            else if (t.kind == PovTokenKind::identifier && PovItemReader::starts_object(w))
                add(items_.object(t), Transform{}, nullptr, Transform{}, nullptr, false);
            else if (not_read_yet(t))
                throw parser_.error_at(t, "POV-Ray's " + w + " is not supported yet",
                                       {"docs/povray.md lists what glint reads"});
            else
                throw parser_.error_at(t,
                                       "expected an object, camera, light_source, background "
                                       "or global_settings, got " +
                                           describe(t),
                                       {"docs/povray.md lists what glint reads"});
        }
        for (const std::string& message : parser_.messages())
            scene_.warnings.push_back("#debug: " + message);
        choose_working_space_and_bake_sky();
        if (any_area_light_) scene_.settings.integrator = IntegratorKind::distributed;
        if (radiosity_) {
            const std::optional<double> version = parser_.scene_version();
            light_by_radiosity(*radiosity_, !(version && *version >= 3.7), scene_, scene_.warnings);
        }
        return std::move(scene_);
    }

private:
    static PovLanguageOptions options(const ReadSandbox& sandbox) {
        PovLanguageOptions o;
        // The folders the user allows (--allow-read) are POV-Ray's library paths (+L) too:
        // #include looks there after the scene's folder, before the standard includes.
        o.include_folders.assign(sandbox.folders.begin() + (sandbox.folders.empty() ? 0 : 1),
                                 sandbox.folders.end());
        o.include_folders.insert(o.include_folders.end(), o.standard_include_folders.begin(),
                                 o.standard_include_folders.end());
        o.sandbox = &sandbox;
        o.max_loop_iterations = sandbox.limits.script_loop_iterations;
        return o;
    }

    // POV-Ray's camera without a camera block: at the origin looking along +z, right 1.33 x.
    CameraSpec default_camera() {
        CameraSpec c;
        c.from = {0, 0, 0};
        c.at = {0, 0, 1};
        c.up = {0, 1, 0};
        c.fov = float(2 * std::atan(0.5) * 180 / std::numbers::pi);
        c.left_handed = true;
        c.aspect = 1.33f;
        return c;
    }

    // POV-Ray's camera aimed as POV-Ray aims it, onto glint's (left-handed unless `right`
    // says otherwise).
    void camera(const PovCamera& pov) {
        PovVector direction = pov.direction, up = pov.up, right = pov.right;
        // As POV-Ray: the angle sets the direction's length against right's; a wide camera's
        // is its field of view (wide_camera).
        if (pov.angle && !pov.wide && !(pov.orthographic && *pov.angle == 0)) {
            if (!(*pov.angle > 0 && *pov.angle < 180))
                throw files_.error_at(pov.at, "camera angle must be in (0, 180)");
            direction = scaled(direction, 0.5 * norm(right) /
                                              std::tan(*pov.angle * std::numbers::pi / 360) /
                                              norm(direction));
        }
        // As POV-Ray: left-handed when right . (up x direction) > 0; not when it is 0 (up along
        // the direction, as `up z` leaves the default direction).
        const bool left_handed = dot3(right, cross3(up, direction)) > 0;
        if (pov.look_at) {
            PovVector d = *pov.look_at;
            for (int i = 0; i < 3; ++i) d[i] -= pov.location[i];
            if (!(norm(d) > 0)) throw files_.error_at(pov.at, "camera look_at is its location");
            const double length_d = norm(direction), length_r = norm(right), length_u = norm(up);
            direction = scaled(d, length_d / norm(d));
            PovVector r = cross3(pov.sky, direction);
            if (!(norm(r) > 1e-10 * norm(pov.sky) * norm(direction))) {
                // Looking along the sky: as POV-Ray, the right vector as given stays.
                r = right;
                if (!(norm(cross3(r, direction)) > 1e-10 * norm(r) * norm(direction)))
                    throw files_.error_at(pov.at,
                                          "camera sky and right are both parallel to its view");
                scene_.warnings.push_back(files_.name(pov.at.file) + ":" +
                                          std::to_string(pov.at.line) +
                                          ": the camera looks along its sky: its right vector "
                                          "is kept as given");
            }
            right = scaled(r, length_r / norm(r));
            if (!left_handed) right = scaled(right, -1);
            PovVector u = cross3(direction, right);
            if (!left_handed) u = scaled(u, -1);
            up = scaled(u, length_u / norm(u));
        }
        if (pov.orthographic && (!pov.sized || pov.angle)) {
            // As POV-Ray: the view at look_at is a perspective camera's of the same vectors.
            PovVector d = pov.look_at.value_or(PovVector{{0, 0, 1}});
            for (int i = 0; i < 3; ++i) d[i] -= pov.location[i];
            const double k = norm(d) / norm(direction);
            if (std::isfinite(k) && k > 0) {
                right = scaled(right, k);
                up = scaled(up, k);
            }
        }
        const Transform& t = pov.transform;
        const Vector3 view = t(to_vector(direction)), up_placed = t(to_vector(up));
        CameraSpec& c = scene_.camera;
        c.from = t(to_point(pov.location));
        c.at = c.from + view;
        c.up = up_placed;
        c.left_handed = left_handed;
        // As POV-Ray: right's length against up's is the view's shape, whatever the image's.
        // The shape image_width / image_height gives the reader is taken for the image's own,
        // at whatever size the image is rendered.
        const double aspect = length(t(to_vector(right))) / length(up_placed);
        const PovLanguageOptions& o = parser_.options();
        const double image_aspect = double(o.image_width) / o.image_height;
        const bool own =
            std::isfinite(aspect) && aspect > 0 && std::abs(aspect / image_aspect - 1) > 1e-6;
        c.aspect = own ? float(aspect) : 0;
        if (pov.wide) {
            wide_camera(pov, length(t(to_vector(right))), length(up_placed));
        } else if (pov.orthographic) {
            c.projection = Projection::orthographic;
            c.height = length(up_placed);
        } else {
            c.projection = Projection::perspective;
            c.fov = float(2 * std::atan(0.5 * length(up_placed) / length(view)) * 180 /
                          std::numbers::pi);
        }
        if (pov.blur_samples) scene_.settings.samples_per_pixel = *pov.blur_samples;
        if (pov.aperture && *pov.aperture > 0) {
            c.lens.radius = float(*pov.aperture / 2);
            if (pov.focal_point) {
                const Vector3 to_focus = t(to_point(*pov.focal_point)) - c.from;
                c.lens.focus_distance = dot(to_focus, view) / length(view);
            }
            scene_.settings.integrator = IntegratorKind::distributed;
        }
    }

    // POV-Ray's wide cameras: their angle (90 degrees unless given) is the field of view; a
    // cylinder's kind picks its axis (1 and 3 up, 2 and 4 right) and whether it looks parallel
    // along it (3 and 4), its extent along the axis that vector's length.
    void wide_camera(const PovCamera& pov, double right_length, double up_length) {
        CameraSpec& c = scene_.camera;
        c.projection = *pov.wide;
        const double angle = pov.angle.value_or(c.projection == Projection::spherical ? 360 : 90);
        if (!(angle > 0 && angle <= 360))
            throw files_.error_at(
                pov.at, "camera angle must be in (0, 360] for " + camera_named(c.projection));
        c.fov = float(angle);
        if (c.projection == Projection::spherical) {
            const double vertical = pov.vertical_angle.value_or(std::min(angle / 2, 180.0));
            if (!(vertical > 0 && vertical <= 180))
                throw files_.error_at(pov.at,
                                      "a spherical camera's vertical angle must be in "
                                      "(0, 180]");
            c.vertical_fov = float(vertical);
        }
        if (c.projection == Projection::cylindrical) {
            c.cylinder_axis_across = pov.cylinder_kind == 2 || pov.cylinder_kind == 4;
            c.cylinder_parallel = pov.cylinder_kind >= 3;
            c.height = float(c.cylinder_axis_across ? right_length : up_length);
        }
    }

    // A light_source onto glint's point, spot, directional, rectangle or disk light.
    void light(const PovLight& pov, const Transform& parent) {
        const Transform placed = parent * pov.transform;
        const bool shadows = !pov.shadowless;
        const Point3 at = placed(to_point(pov.position));
        if (pov.looks_like) {
            // POV-Ray moves the object to the light; it casts no shadow, so the light shines.
            add(*pov.looks_like, placed * Transform::translate(to_vector(pov.position)), nullptr,
                Transform{}, nullptr, true);
        }
        const Point3 target = placed(to_point(pov.point_at));
        const Color c = rgb(pov.color);
        Attenuation attenuation;
        if (pov.fade_distance && pov.fade_power > 0) {
            // POV-Ray's 2 / (1 + (d / fade_distance)^fade_power), exactly for powers 1 and 2.
            const float fd = float(*pov.fade_distance);
            if (pov.fade_power < 1.5)
                attenuation = {0.5f, 1 / (2 * fd), 0};
            else
                attenuation = {0.5f, 0, 1 / (2 * fd * fd)};
        }
        if (pov.kind == PovLight::Kind::parallel) {
            scene_.lights.push_back(
                DirectionalLight{normalize(target - at), c, shadows, pov.media_interaction});
            return;
        }
        if (pov.kind == PovLight::Kind::spot) {
            SpotLight s;
            s.position = at;
            s.direction = normalize(target - at);
            const double cone = std::max(pov.falloff, pov.radius);
            s.cos_cone = float(std::cos(cone * std::numbers::pi / 180));
            s.cos_falloff = float(std::cos(std::min(pov.radius, cone) * std::numbers::pi / 180));
            s.tightness = float(pov.tightness);
            s.color = c;
            s.attenuation = attenuation;
            s.casts_shadows = shadows;
            s.in_media = pov.media_interaction;
            scene_.lights.push_back(s);
            return;
        }
        if (pov.area_u) {
            const Vector3 u = placed(to_vector(*pov.area_u)), v = placed(to_vector(*pov.area_v));
            const std::optional<AreaLight> area =
                pov.circular ? disk_light(at, Normal3(normalize(cross(u, v))), length(u) / 2)
                             : rectangle_light(at, u, v);
            if (area) {
                AreaLight a = *area;
                a.color = c;
                a.attenuation = attenuation;
                a.shadow_rays = pov.n1 * pov.n2;
                a.casts_shadows = shadows;
                a.in_media = pov.media_interaction;
                scene_.lights.push_back(a);
                any_area_light_ = true;
                return;
            }
        }
        scene_.lights.push_back(PointLight{at, c, attenuation, shadows, pov.media_interaction});
    }

    void background(const PovToken&) {
        parser_.expect("{", "after background");
        scene_.settings.background = rgb(parser_.color_expression("as the background"));
        parser_.expect("}", "after the background's colour");
    }

    // POV-Ray's fog onto glint's: its colour's filter and transmit are the fog's.
    void fog(const PovFog& f) {
        if (f.distance == 0) {
            scene_.warnings.push_back("a fog without a distance does nothing: it is left out");
            return;
        }
        if (f.distance < 0)
            throw files_.error_at(f.at,
                                  "fog distance must be > 0, got " + format_pov_number(f.distance));
        Fog fog;
        fog.color = rgb(f.color);
        fog.filter = float(std::clamp(f.color[3], 0.0, 1.0));
        fog.transmit = float(std::clamp(f.color[4], 0.0, 1.0));
        fog.distance = float(f.distance);
        if (f.type == 2) {
            if (!(f.alt > 0))
                throw files_.error_at(f.at, "ground fog (fog_type 2) needs fog_alt > 0, got " +
                                                format_pov_number(f.alt));
            const Vector3 up{float(f.up[0]), float(f.up[1]), float(f.up[2])};
            if (length(up) == 0) throw files_.error_at(f.at, "fog up must not be zero");
            fog.kind = FogKind::ground;
            fog.offset = float(f.offset);
            fog.altitude = float(f.alt);
            fog.up = normalize(up);
        }
        fog.turbulence = {float(f.turbulence[0]), float(f.turbulence[1]), float(f.turbulence[2])};
        fog.turbulence_depth = float(std::max(f.turbulence_depth, 0.0));
        scene_.fogs.push_back(fog);
    }

    void global_settings(const PovToken&) {
        parser_.expect("{", "after global_settings");
        for (PovToken t = parser_.next(); !t.is_symbol("}"); t = parser_.next()) {
            const std::string& w = t.text;
            if (w == "ambient_light")
                scene_.ambient = rgb(parser_.color_expression("after ambient_light"));
            else if (w == "max_trace_level")
                scene_.settings.max_depth = parser_.whole_number("after max_trace_level", 1, 256);
            else if (w == "adc_bailout")
                scene_.settings.min_weight = float(parser_.finite_float("after adc_bailout"));
            else if (w == "assumed_gamma") {
                const PovToken at = parser_.peek();
                assumed_gamma_ = parser_.finite_float("after assumed_gamma");
                if (!(*assumed_gamma_ > 0 && *assumed_gamma_ <= 10))
                    throw parser_.error_at(at, "assumed_gamma must be in (0, 10]");
            } else if (w == "max_intersections" || w == "number_of_waves" || w == "noise_generator")
                parser_.finite_float("after " + w);
            else if (w == "charset")
                parser_.next();
            else if (w == "radiosity")
                radiosity_ = read_pov_radiosity(parser_, items_);
            else if (w == "photons" || w == "subsurface") {
                parser_.skip_braced(t);
                scene_.warnings.push_back("global_settings " + w +
                                          " { } is ignored: glint renders without it");
            } else
                throw parser_.error_at(t, describe(t) + " is not supported in global_settings yet",
                                       {"docs/povray.md lists what glint reads"});
        }
    }

    // An object read past (as include files declare many): using it stops the scene here.
    void refuse_unread(const PovObject& object) const {
        if (object.unread)
            throw files_.error_at(object.unread->at,
                                  "POV-Ray's " + object.unread->what + " is not supported yet",
                                  {"docs/povray.md lists what glint reads"});
    }

    // A pigment glint does not read yet, at any depth of its pigment maps, stops the scene.
    void refuse_unread(const PovPigment& pigment) const {
        if (const PovPigment* unread = unread_pigment(pigment))
            throw files_.error_at(
                unread->at,
                unread->uses.empty()
                    ? "pigment pattern " + quote(unread->pattern) + " is not supported yet"
                    : "the pigment's function uses " + unread->uses +
                          ", which glint does not compute yet",
                {"docs/povray.md lists what glint reads"});
    }

    // The glint material of a texture and interior. A pattern's material also depends on where
    // its texture lies (`frame`: the texture's space to the scene's), as it is placed by it.
    // Layers become one colour source (LayeredTexture) under the top layer's finish, each
    // layer's ambient and diffuse coefficients weighed against its; the top-most normal tilts
    // them all.
    std::uint32_t material(const std::shared_ptr<const PovTexture>& texture,
                           const std::shared_ptr<const PovInterior>& interior,
                           const Transform& frame, bool hollow = false) {
        std::vector<const PovTexture*> layers;  // from the top down
        for (auto layer = texture->above.rbegin(); layer != texture->above.rend(); ++layer)
            layers.push_back(&*layer);
        layers.push_back(texture.get());
        std::optional<PovNormal> normal;
        bool placed = false;
        for (const PovTexture* layer : layers) {
            refuse_unread(layer->pigment);
            if (!normal) normal = layer->normal;
            const PovPigment& p = layer->pigment;
            placed = placed || (p.kind == PovPigment::Kind::pattern && !p.uv_mapping) ||
                     (p.kind == PovPigment::Kind::image && !p.uv_mapping);
        }
        const bool tilted = normal && normal->unsupported.empty();
        placed = placed || tilted;
        const MaterialKey key{texture, interior, placed ? frame.matrix().m : Matrix4::identity().m,
                              hollow};
        if (const auto found = materials_.find(key); found != materials_.end())
            return found->second;
        const PovTexture& t = *layers.front();
        const PovPigment& p = t.pigment;
        Material m;
        m.name = "pov" + std::to_string(scene_.materials.size());
        if (normal && !tilted && warned_normals_.insert(normal->unsupported).second)
            scene_.warnings.push_back("normal pattern " + quote(normal->unsupported) +
                                      " is not supported yet: surfaces with it stay smooth");
        if (tilted) {
            MaterialMaps maps;
            maps.normal_pattern = normal->pattern;
            maps.normal_pattern->to_pattern = (frame * normal->transform).inverse();
            if (normal->pigment) {
                refuse_unread(*normal->pigment);
                maps.normal_pattern->pigment =
                    std::make_shared<const Texture>(texture_of(*normal->pigment, Transform{}));
            }
            m.maps = std::make_shared<const MaterialMaps>(std::move(maps));
        }
        const PovFinish& f = t.finish;
        m.ka = float(f.ambient);
        m.kd = float(f.diffuse);
        if (f.phong > 0) {
            m.highlight = Highlight::phong;
            m.ks = float(f.phong);
            m.shininess = float(f.phong_size);
        } else if (f.specular > 0) {
            m.highlight = Highlight::blinn;
            m.ks = float(f.specular);
            m.shininess = float(1 / std::max(f.roughness, 1e-4));
        } else {
            m.ks = 0;
        }
        m.brilliance = float(std::max(f.brilliance, 0.0));
        m.metallic = float(std::clamp(f.metallic, 0.0, 1.0));
        m.reflect = float(std::clamp(f.reflection, 0.0, 1.0));
        if (f.reflection_min && (*f.reflection_min != f.reflection || f.fresnel))
            m.reflect_angular = AngularReflection{float(std::clamp(*f.reflection_min, 0.0, 1.0)),
                                                  float(f.reflection_falloff), f.fresnel};
        m.reflect_metallic = float(f.reflection_metallic);
        m.reflect_color = f.reflection_color;
        if (f.emission > 0 && p.kind == PovPigment::Kind::color) {
            m.emission = rgb(p.color) * float(f.emission);
        } else if (f.emission > 0) {
            MaterialMaps maps = m.maps ? *m.maps : MaterialMaps{};
            maps.color_emission = Color{1, 1, 1} * float(f.emission);
            m.maps = std::make_shared<const MaterialMaps>(std::move(maps));
        }
        if (layers.size() == 1) {
            m.color = texture_of(p, frame);
            m.transmit = float(std::clamp(transmitted(p), 0.0, 1.0));
            m.tint = float(filtered_share(p));
            // What a pigment lets through it does not reflect diffusely: POV-Ray scales the
            // ambient and diffuse terms by its opacity (the highlights it leaves).
            m.ka *= 1 - m.transmit;
            m.kd *= 1 - m.transmit;
        } else {
            auto layered = std::make_shared<LayeredTexture>();
            const std::optional<double> version = parser_.scene_version();
            layered->legacy_opacity = !version || *version < 3.7;
            double passed = 1;  // what every layer lets through, where the least gets through
            // Without a coefficient of its own on top, the layers' are the weights themselves.
            if (!(m.ka > 0)) m.ka = 1;
            if (!(m.kd > 0)) m.kd = 1;
            for (const PovTexture* layer : layers) {
                layered->layers.push_back({texture_of(layer->pigment, frame),
                                           texture_of(filter_and_transmit(layer->pigment), frame),
                                           float(layer->finish.diffuse) / m.kd,
                                           float(layer->finish.ambient) / m.ka});
                passed *= transmitted(layer->pigment);
            }
            m.color = LayeredTexturePtr(std::move(layered));
            m.transmit = float(std::clamp(passed, 0.0, 1.0));
        }
        if (interior) m.ior = float(interior->ior);
        // Powers from 1000 on are Beer-Lambert's law in glint as in POV-Ray.
        if (interior) m.fade = interior->fade;
        if (interior && interior->dispersion != 1) disperse(m, *interior);
        m.hollow = hollow;
        if (interior) {
            for (const PovMedium& medium : interior->media) {
                m.media.push_back(medium_of(medium));  // placed already (placed_interior)
            }
        }
        scene_.materials.push_back(std::move(m));
        const auto index = std::uint32_t(scene_.materials.size() - 1);
        materials_.emplace(key, index);
        return index;
    }

    // The pigment with each colour's filter and transmit in place of its red and green (and
    // nothing else), for a layer's second colour source (LayeredTexture).
    static PovPigment filter_and_transmit(const PovPigment& pigment) {
        const auto swapped = [](const PovVector& c) { return PovVector{{c[3], c[4], 0, 0, 0}, 5}; };
        PovPigment p = pigment;
        if (p.kind == PovPigment::Kind::image) p.kind = PovPigment::Kind::color;
        p.color = swapped(p.color);
        for (PovColorStop& stop : p.map.stops) {
            stop.color = swapped(stop.color);
            if (stop.pigment)
                stop.pigment =
                    std::make_shared<const PovPigment>(filter_and_transmit(*stop.pigment));
        }
        return p;
    }

    // glint's colour source for a pigment lying in `frame` (its texture's space to the scene's).
    static Texture texture_of(const PovPigment& p, const Transform& frame) {
        const bool mapped = std::any_of(p.map.stops.begin(), p.map.stops.end(),
                                        [](const PovColorStop& s) { return s.pigment != nullptr; });
        if (p.kind == PovPigment::Kind::pattern && mapped) {
            // Each entry's pigment lies in the map's pattern space.
            auto map = std::make_shared<PigmentMap>();
            map->spec = p.spec;
            map->average = p.average;
            // Laid over the uv, the map and its entries lie in uv space, placed by the
            // pigment's own transforms only.
            const Transform entry_frame = p.uv_mapping ? p.transform : frame * p.transform;
            for (const PovColorStop& stop : p.map.stops)
                map->entries.push_back({float(stop.at), stop.pigment
                                                            ? texture_of(*stop.pigment, entry_frame)
                                                            : Texture{rgb(stop.color)}});
            map->to_pattern = entry_frame.inverse();
            map->uv_mapping = p.uv_mapping;
            return map;
        }
        if (p.kind == PovPigment::Kind::pattern) {
            auto pattern = std::make_shared<PatternTexture>();
            pattern->spec = p.spec;
            for (const PovColorStop& stop : p.map.stops)
                pattern->colors.push_back({float(stop.at), rgb(stop.color)});
            // Laid over the uv, placed by its own transforms only.
            pattern->to_pattern = (p.uv_mapping ? p.transform : frame * p.transform).inverse();
            pattern->uv_mapping = p.uv_mapping;
            return pattern;
        }
        if (p.kind == PovPigment::Kind::image && !p.uv_mapping) {
            auto image = std::make_shared<ProjectedImage>(*p.image);
            image->to_projection = (frame * p.transform).inverse();
            return image;
        }
        if (p.kind == PovPigment::Kind::image) return p.image->image;  // on the surface's uv
        return rgb(p.color);
    }

    // POV-Ray's dispersion: the index ior D^(t - 1/2) from the red end (t = 0) of the spectrum to
    // the violet (t = 1), onto glint's Cauchy formula n = A + B / lambda^2 through its ends,
    // taken at 700 and 400 nm; glint's distributed integrator draws the wavelengths.
    void disperse(Material& m, const PovInterior& interior) {
        const double red = interior.ior / std::sqrt(interior.dispersion);
        const double violet = interior.ior * std::sqrt(interior.dispersion);
        const double b = (violet - red) / (1 / (0.4 * 0.4) - 1 / (0.7 * 0.7));
        const double a = red - b / (0.7 * 0.7);
        m.dispersion.model = DispersionModel::cauchy;
        m.dispersion.c = {float(a), float(b)};
        m.ior = refractive_index(m.dispersion, m.ior, kReferenceWavelength);
        scene_.settings.integrator = IntegratorKind::distributed;
        scene_.settings.samples_per_pixel =
            std::max(scene_.settings.samples_per_pixel, interior.dispersion_samples);
    }

    // Where the textures of a CSG's operands lie and what they are seen through: the scene's
    // placement of the CSG object's parent space, and the interior handed down.
    struct OperandPaint {
        Transform frame;
        std::shared_ptr<const PovInterior> interior;
    };

    // The object's shape as one glint shape (a CSG of its children, each placed), or nothing for
    // a group, whose children are objects of their own. With `paint`, a CSG's operands that
    // have their own texture show it (none for clipping objects, which show nothing).
    Shape placed_shape(const PovObject& object, const OperandPaint* paint = nullptr) {
        refuse_unread(object);
        Shape shape;
        if (object.shape) {
            shape = *object.shape;
            // A quadric is exact however large its box: one that nothing bounds is cut far out.
            if (!object.polynomial.empty() && bounds(shape).is_empty() &&
                std::holds_alternative<Quadric>(shape)) {
                const Bounds3 region = loosened(far_bounded(own_extent(shape)));
                if (!region.is_empty()) bound_polynomial(shape, region);
            }
            if (!object.polynomial.empty() && bounds(shape).is_empty())
                throw files_.error_at(object.at,
                                      "POV-Ray's " + object.polynomial +
                                          " needs bounded_by or clipped_by in glint: its surface "
                                          "is unbounded, and glint searches it within their box",
                                      {"docs/povray.md lists what glint reads"});
        } else {
            // Lights among the operands shine (add_lights) but are no part of the solid.
            std::vector<const PovObject*> operands;
            for (const auto& child : object.children)
                if (!child->light) operands.push_back(child.get());
            if (operands.empty())
                throw files_.error_at(object.at, "a CSG of lights alone has no surface");
            shape = csg_of(object, operands, paint);
        }
        if (object.clipped_by)
            shape =
                combined(std::move(shape), placed_shape(*object.clipped_by), CsgOperation::clip);
        if (object.transform == Transform{}) return shape;
        return Transformed(object.transform, std::make_shared<const Shape>(std::move(shape)));
    }

    // POV-Ray's CSG onto glint's. An inverse operand is the rest of space: an intersection
    // takes it away, a difference keeps it (difference { A B } is intersection { A, B inverse }).
    // So every CSG is what it keeps, less what it takes away; each side is a balanced tree, as
    // glint's CSG walks its operands' hits again at every level: a chain of n levels (a
    // polyhedron of planes) would cost exponentially in n, a tree costs in its depth, log n.
    Shape csg_of(const PovObject& object, const std::vector<const PovObject*>& operands,
                 const OperandPaint* paint) {
        const bool intersection = object.csg == PovObject::Csg::intersection;
        const bool difference = object.csg == PovObject::Csg::difference;
        std::vector<Operand> kept, taken;
        // An intersection bounds an unbounded polynomial operand by its other operands' box.
        Bounds3 common{{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}};
        const bool needs_common =
            intersection && std::any_of(operands.begin(), operands.end(), [](const PovObject* o) {
                return unbounded_polynomial(*o);
            });
        if (needs_common)
            for (const PovObject* operand : operands)
                if (!operand->inverse) common = overlap(common, items_.extent(*operand));
        for (std::size_t i = 0; i < operands.size(); ++i) {
            PovObject bounded;
            const PovObject* operand_ptr = operands[i];
            if (intersection && unbounded_polynomial(*operand_ptr)) {
                bounded = *operand_ptr;
                Bounds3 region = bounded.transform.inverse()(common);
                if (std::holds_alternative<Quadric>(*bounded.shape)) region = far_bounded(region);
                if (region.is_finite() && !region.is_empty())
                    bound_polynomial(*bounded.shape, loosened(region));
                operand_ptr = &bounded;
            }
            const PovObject& operand = *operand_ptr;
            if (operand.inverse && !(intersection || (difference && i > 0)))
                throw files_.error_at(operand.at,
                                      "an inverse object is supported only as an operand of "
                                      "intersection, or of difference after its first",
                                      {"docs/povray.md lists what glint reads"});
            const bool keeps = intersection ? !operand.inverse
                               : difference ? i == 0 || operand.inverse
                                            : true;
            Operand placed;
            if (paint) {
                // An operand's texture lies in the CSG's own space.
                const Transform frame = paint->frame * object.transform;
                const OperandPaint own{frame, operand.interior
                                                  ? placed_interior(operand.interior, frame)
                                                  : paint->interior};
                placed.shape = placed_shape(operand, &own);
                if (operand.texture)
                    placed.material =
                        material(operand.texture, own.interior, own.frame, operand.hollow) + 1;
            } else {
                placed.shape = placed_shape(operand);
            }
            (keeps ? kept : taken).push_back(std::move(placed));
        }
        if (kept.empty())
            throw files_.error_at(object.at,
                                  "an intersection of inverse objects alone is not supported",
                                  {"docs/povray.md lists what glint reads"});
        const CsgOperation op = object.csg == PovObject::Csg::merge ? CsgOperation::merge
                                : intersection || difference        ? CsgOperation::intersection
                                                                    : CsgOperation::union_of;
        Operand shape = balanced(kept, 0, kept.size(), op);
        if (taken.empty()) return shape.shape;
        // What is taken away is one solid: its parts merged, so that where two of them overlap
        // a point inside one stays inside what is taken (a union's inner surfaces would say
        // the ray leaves it there).
        return combined(std::move(shape), balanced(taken, 0, taken.size(), CsgOperation::merge),
                        CsgOperation::difference)
            .shape;
    }

    static bool unbounded_polynomial(const PovObject& object) {
        return !object.polynomial.empty() && object.shape && bounds(*object.shape).is_empty();
    }

    static Shape combined(Shape a, Shape b, CsgOperation operation) {
        return combined(Operand{std::move(a)}, Operand{std::move(b)}, operation).shape;
    }

    // An operand of a CSG, with the material (index + 1) it shows, 0 for the CSG's own.
    struct Operand {
        Shape shape;
        std::uint32_t material = 0;
    };

    static Operand combined(Operand a, Operand b, CsgOperation operation) {
        return {glint::csg_of(std::move(a.shape), std::move(b.shape), operation, a.material,
                              b.material)};
    }

    // The operands [begin, end) joined by `op` (associative) two halves at a time.
    static Operand balanced(std::vector<Operand>& shapes, std::size_t begin, std::size_t end,
                            CsgOperation op) {
        if (end - begin == 1) return std::move(shapes[begin]);
        const std::size_t middle = begin + (end - begin) / 2;
        return combined(balanced(shapes, begin, middle, op), balanced(shapes, middle, end, op), op);
    }

    // glint's medium of a POV-Ray medium whose densities lie in the scene's space.
    Medium medium_of(const PovMedium& pov) const {
        Medium medium = pov.medium;
        for (const PovPigment& density : pov.densities) {
            refuse_unread(density);
            medium.density.push_back(texture_of(density, Transform{}));
        }
        return medium;
    }

    // media { } outside objects: the scene's atmosphere, its densities in the scene's space.
    void atmosphere(const PovToken& keyword) {
        if (scene_.atmosphere.size() == kMaxMedia)
            throw parser_.error_at(
                keyword, "the scene holds at most " + std::to_string(kMaxMedia) + " media");
        scene_.atmosphere.push_back(medium_of(items_.media(keyword)));
    }

    // The interior with its media's densities placed in the scene's space by `frame`, the
    // space the interior lies in (its object's parent's), as a texture lies in its frame.
    static std::shared_ptr<const PovInterior> placed_interior(
        const std::shared_ptr<const PovInterior>& interior, const Transform& frame) {
        if (!interior->has_densities() || frame == Transform{}) return interior;
        PovInterior placed = *interior;
        placed.move(frame);
        return std::make_shared<const PovInterior>(std::move(placed));
    }

    // `texture_frame`: where the texture handed down lies (its space to the scene's). An
    // object's own texture lies in its parent's space, and moves with the object's transforms
    // written after it (PovItemReader::modifiers).
    void add(const PovObject& object, const Transform& parent,
             std::shared_ptr<const PovTexture> texture, Transform texture_frame,
             std::shared_ptr<const PovInterior> interior, bool no_shadow,
             std::shared_ptr<const Shape> clip = nullptr) {
        refuse_unread(object);
        if (object.texture || !texture) {
            texture = object.texture ? object.texture : object.fallback;
            texture_frame = parent;
        }
        if (object.interior) interior = placed_interior(object.interior, parent);
        no_shadow = no_shadow || object.no_shadow;
        const Transform placement = parent * object.transform;
        if (object.light) {
            light(*object.light, placement);
            return;
        }
        if (!object.shape && object.csg != PovObject::Csg::group) add_lights(object, placement);
        if (!object.shape && object.csg == PovObject::Csg::group) {
            // A clipped group clips each of its objects, in the scene's space.
            if (object.clipped_by) {
                Shape own = Transformed(
                    placement, std::make_shared<const Shape>(placed_shape(*object.clipped_by)));
                clip = std::make_shared<const Shape>(
                    clip ? combined(*clip, std::move(own), CsgOperation::intersection) : own);
            }
            for (const auto& child : object.children)
                add(*child, placement, texture, texture_frame, interior, no_shadow, clip);
            return;
        }
        PovObject local = object;
        local.transform = Transform{};
        const OperandPaint paint{placement, interior};
        Shape shape = placed_shape(local, &paint);
        if (!(placement == Transform{}))
            shape = Transformed(placement, std::make_shared<const Shape>(std::move(shape)));
        if (clip) shape = combined(std::move(shape), *clip, CsgOperation::clip);
        SceneObject o{std::move(shape), material(texture, interior, texture_frame, object.hollow)};
        o.casts_shadow = !no_shadow;
        scene_.objects.push_back(std::move(o));
    }

    // POV-Ray does its arithmetic on colours as written, and takes the result for encoded
    // with assumed_gamma; a scene older than 3.7 that gives none is not gamma-corrected at all:
    // its results are the image file's values. glint does likewise in its working space, which
    // the image is decoded from (WorkingSpace). Images, which glint reads as linear light, are
    // encoded into it, as POV-Ray does. The sky is baked last, in the same space.
    void choose_working_space_and_bake_sky() {
        using Transfer = WorkingSpace::Transfer;
        const std::optional<double> version = parser_.scene_version();
        WorkingSpace& space = scene_.settings.working_space;
        if (assumed_gamma_ && *assumed_gamma_ != 1)
            space = {Transfer::gamma, float(*assumed_gamma_)};
        else if (!assumed_gamma_ && !(version && *version >= 3.7))
            space = {Transfer::srgb, 1};
        const auto into_space = [space](Color c) { return encode(space, c); };
        if (space.transfer != Transfer::linear) {
            ImageEncoder encode_images(into_space);
            for (Material& m : scene_.materials)
                if (holds_image(m.color)) m.color = encode_images(m.color);
        }
        if (sky_) scene_.sky = bake_sky(*sky_, scene_.settings.background, into_space);
    }

    // trace(): the object's shape, built once for the calls in a row that trace the same object
    // (a loop placing things on a surface), met by the ray.
    std::optional<PovParser::TraceHit> trace(const std::shared_ptr<const PovItemRef>& ref,
                                             const PovVector& from, const PovVector& direction,
                                             const PovToken& at) {
        const auto* object = std::get_if<PovObject>(&ref->item);
        if (!object) throw parser_.error_at(at, "trace takes an object");
        if (ref != traced_) {
            traced_shape_ = placed_shape(*object);
            traced_ = ref;
        }
        const Vector3 d{float(direction[0]), float(direction[1]), float(direction[2])};
        const Point3 o{float(from[0]), float(from[1]), float(from[2])};
        if (!(length(d) > 0) || !std::isfinite(length(d)))
            throw parser_.error_at(at, "trace's direction is zero or beyond a float's range");
        if (!std::isfinite(o.x) || !std::isfinite(o.y) || !std::isfinite(o.z))
            throw parser_.error_at(at, "trace's start is beyond a float's range");
        const Ray ray{o, normalize(d)};
        const std::optional<ShapeHit> hit = intersect(traced_shape_, ray, {0, kInfinity});
        if (!hit) return std::nullopt;
        const SurfacePoint sp = surface_at(traced_shape_, ray, *hit);
        const auto vector = [](auto v) {
            return PovVector{{double(v.x), double(v.y), double(v.z)}};
        };
        return PovParser::TraceHit{vector(sp.p), vector(sp.shading_normal)};
    }

    // The lights inside a CSG's operands, at any depth.
    void add_lights(const PovObject& object, const Transform& placement) {
        for (const auto& child : object.children) {
            if (child->light)
                light(*child->light, placement * child->transform);
            else
                add_lights(*child, placement * child->transform);
        }
    }

    PovFiles& files_;
    Scene scene_;
    PovParser parser_;
    PovItemReader items_;
    // By the texture and interior themselves, held so that a freed one's address is never
    // taken for a new one's.
    using MaterialKey = std::tuple<std::shared_ptr<const PovTexture>,
                                   std::shared_ptr<const PovInterior>, decltype(Matrix4::m), bool>;
    std::map<MaterialKey, std::uint32_t> materials_;
    bool any_area_light_ = false;
    std::optional<double> assumed_gamma_;
    std::optional<PovRadiosity> radiosity_;
    std::shared_ptr<const PovItemRef> traced_;  // the object trace() met last, and its shape
    Shape traced_shape_;
    std::optional<PovSkySphere> sky_;
    std::set<std::string> warned_normals_;
};

}  // namespace

Scene parse_pov_scene(std::string text, const std::filesystem::path& as_file,
                      const ReadSandbox& sandbox) {
    PovFiles files;
    files.add(as_file.string(), std::move(text));
    Scene scene = Builder(files, sandbox).run();
    scene.sources.file = as_file.string();
    return scene;
}

Scene load_pov_scene(const std::filesystem::path& file, const ReadSandbox& sandbox) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(file, error);
    if (error) throw SceneError({file.string(), 0, 0}, "cannot read the scene: " + error.message());
    if (size > sandbox.file_limit(kMaxPovFileBytes))
        throw SceneError({file.string(), 0, 0},
                         "scene file is larger than " +
                             describe_file_limit(sandbox.file_limit(kMaxPovFileBytes)),
                         {kRaiseFileLimitNote});
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return parse_pov_scene(text.str(), file, sandbox);
}

}  // namespace glint
