// The top level of a POV-Ray scene: camera, light sources, background, global settings and
// objects, and the mapping of POV-Ray's finishes and objects onto glint's materials and shapes.
#include "glint/scene/pov/pov_scene.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include "glint/scene/pov/pov_item_reader.h"
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

PovVector axis(int i) {
    PovVector v = PovVector::of(0, 3);
    v[i] = 1;
    return v;
}

// POV-Ray's scene items, besides objects, that glint does not read yet: their error says so.
bool not_read_yet(const PovToken& token) {
    static const std::string_view kNotYet[] = {"fog", "media", "photons", "rainbow", "sky_sphere"};
    return token.kind == PovTokenKind::identifier &&
           std::find(std::begin(kNotYet), std::end(kNotYet), token.text) != std::end(kNotYet);
}

class Builder {
public:
    Builder(PovFiles& files, const ReadSandbox& sandbox)
        : files_(files), parser_(files, options(sandbox)), items_(parser_, scene_.warnings) {
        parser_.set_item_reader([this](const PovToken& keyword) -> std::optional<PovValue> {
            auto item = items_.read(keyword);
            if (!item) return std::nullopt;
            return std::make_shared<const PovItemRef>(PovItemRef{std::move(*item)});
        });
        scene_.ambient = {1, 1, 1};               // global_settings' ambient_light
        scene_.settings.min_weight = 1.0f / 255;  // adc_bailout
        scene_.camera = default_camera();
    }

    Scene run() {
        for (PovToken t = parser_.next(); t.kind != PovTokenKind::end; t = parser_.next()) {
            const std::string& w = t.text;
            if (t.is_symbol(";")) continue;
            if (w == "camera")
                camera(t);
            else if (w == "light_source")
                light(t);
            else if (w == "background")
                background(t);
            else if (w == "global_settings")
                global_settings(t);
            else if (t.kind == PovTokenKind::identifier && PovItemReader::starts_object(w))
                add(items_.object(t), Transform{}, nullptr, nullptr, false);
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
        if (any_area_light_) scene_.settings.integrator = IntegratorKind::distributed;
        return std::move(scene_);
    }

private:
    static PovLanguageOptions options(const ReadSandbox& sandbox) {
        PovLanguageOptions o;
        o.include_folders = default_pov_include_folders();
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
        return c;
    }

    void camera(const PovToken& keyword) {
        parser_.expect("{", "after camera");
        PovVector location = PovVector::of(0, 3), direction = axis(2), up = axis(1), sky = axis(1);
        PovVector right = scaled(axis(0), 1.33);
        std::optional<PovVector> look_at, focal_point;
        std::optional<double> angle, aperture;
        bool orthographic = false;
        for (PovToken t = parser_.next(); !t.is_symbol("}"); t = parser_.next()) {
            const std::string& w = t.text;
            if (w == "perspective")
                orthographic = false;
            else if (w == "orthographic")
                orthographic = true;
            else if (w == "location")
                location = parser_.finite_vector("after location");
            else if (w == "look_at")
                look_at = parser_.finite_vector("after look_at");
            else if (w == "direction")
                direction = parser_.finite_vector("after direction");
            else if (w == "up")
                up = parser_.finite_vector("after up");
            else if (w == "right")
                right = parser_.finite_vector("after right");
            else if (w == "sky")
                sky = parser_.finite_vector("after sky");
            else if (w == "angle")
                angle = parser_.finite_float("after angle");
            else if (w == "focal_point")
                focal_point = parser_.finite_vector("after focal_point");
            else if (w == "aperture")
                aperture = parser_.finite_float("after aperture");
            else if (w == "blur_samples") {
                scene_.settings.samples_per_pixel =
                    parser_.whole_number("after blur_samples", 1, 1 << 16);
                if (parser_.accept(",")) parser_.finite_float("after blur_samples");
            } else if (w == "confidence" || w == "variance")
                parser_.finite_float("after " + w);
            else
                throw parser_.error_at(t, describe(t) + " is not supported in a camera yet",
                                       {"docs/povray.md lists what glint reads"});
        }
        // As POV-Ray: the angle sets the direction's length against right's.
        if (angle) {
            if (!(*angle > 0 && *angle < 180))
                throw parser_.error_at(keyword, "camera angle must be in (0, 180)");
            direction =
                scaled(direction, 0.5 * norm(right) / std::tan(*angle * std::numbers::pi / 360) /
                                      norm(direction));
        }
        const double handed = dot3(right, cross3(up, direction));
        if (look_at) {
            PovVector d = *look_at;
            for (int i = 0; i < 3; ++i) d[i] -= location[i];
            if (!(norm(d) > 0)) throw parser_.error_at(keyword, "camera look_at is its location");
            const double length_d = norm(direction), length_r = norm(right), length_u = norm(up);
            direction = scaled(d, length_d / norm(d));
            PovVector r = cross3(sky, direction);
            if (!(norm(r) > 0))
                throw parser_.error_at(keyword, "camera sky is parallel to its view");
            right = scaled(r, length_r / norm(r));
            if (handed < 0) right = scaled(right, -1);
            PovVector u = cross3(direction, right);
            if (handed < 0) u = scaled(u, -1);
            up = scaled(u, length_u / norm(u));
        }
        CameraSpec& c = scene_.camera;
        c.from = to_point(location);
        c.at = to_point(location) + to_vector(direction);
        c.up = to_vector(up);
        c.left_handed = handed >= 0;
        if (orthographic) {
            c.projection = Projection::orthographic;
            c.height = float(norm(up));
        } else {
            c.projection = Projection::perspective;
            c.fov = float(2 * std::atan(0.5 * norm(up) / norm(direction)) * 180 / std::numbers::pi);
        }
        if (aperture && *aperture > 0) {
            c.lens.radius = float(*aperture / 2);
            if (focal_point) {
                PovVector f = *focal_point;
                for (int i = 0; i < 3; ++i) f[i] -= location[i];
                c.lens.focus_distance = float(dot3(f, direction) / norm(direction));
            }
            scene_.settings.integrator = IntegratorKind::distributed;
        }
    }

    void light(const PovToken& keyword) {
        parser_.expect("{", "after light_source");
        const PovVector position = parser_.finite_vector("as the light's position");
        parser_.accept(",");
        const PovVector color = parser_.color_expression("as the light's colour");
        enum class Kind { point, spot, parallel } kind = Kind::point;
        PovVector point_at = PovVector::of(0, 3);
        double radius = 30, falloff = 45;
        std::optional<PovVector> area_u, area_v;
        int n1 = 1, n2 = 1;
        bool circular = false;
        std::optional<double> fade_distance;
        double fade_power = 0;
        Transform placed;
        for (PovToken t = parser_.next(); !t.is_symbol("}"); t = parser_.next()) {
            const std::string& w = t.text;
            if (w == "spotlight")
                kind = Kind::spot;
            else if (w == "parallel")
                kind = Kind::parallel;
            else if (w == "point_at")
                point_at = parser_.finite_vector("after point_at");
            else if (w == "radius")
                radius = parser_.finite_float("after radius");
            else if (w == "falloff")
                falloff = parser_.finite_float("after falloff");
            else if (w == "tightness")
                parser_.finite_float("after tightness");
            else if (w == "area_light") {
                area_u = parser_.finite_vector("as the area light's first axis");
                parser_.expect(",", "after the area light's first axis");
                area_v = parser_.finite_vector("as the area light's second axis");
                parser_.expect(",", "after the area light's second axis");
                n1 = parser_.whole_number("as the area light's first count", 1, 64);
                parser_.expect(",", "after the area light's first count");
                n2 = parser_.whole_number("as the area light's second count", 1, 64);
            } else if (w == "adaptive")
                parser_.finite_float("after adaptive");
            else if (w == "jitter" || w == "orient") {
            } else if (w == "circular")
                circular = true;
            else if (w == "fade_distance")
                fade_distance = parser_.finite_float("after fade_distance");
            else if (w == "fade_power")
                fade_power = parser_.finite_float("after fade_power");
            else if (w == "shadowless") {
                scene_.warnings.push_back(files_.name(keyword.at.file) + ":" +
                                          std::to_string(keyword.at.line) +
                                          ": shadowless light_source casts shadows in glint");
            } else if (w == "media_interaction" || w == "media_attenuation")
                items_.optional_amount();  // POV-Ray's media only
            else if (const auto step = items_.transform_step(t))
                placed = *step * placed;
            else
                throw parser_.error_at(t, describe(t) + " is not supported in a light_source yet",
                                       {"docs/povray.md lists what glint reads"});
        }
        const Point3 at = placed(to_point(position));
        const Point3 target = placed(to_point(point_at));
        const Color c = rgb(color);
        Attenuation attenuation;
        if (fade_distance && fade_power > 0) {
            // POV-Ray's 2 / (1 + (d / fade_distance)^fade_power), exactly for powers 1 and 2.
            const float fd = float(*fade_distance);
            if (fade_power < 1.5)
                attenuation = {0.5f, 1 / (2 * fd), 0};
            else
                attenuation = {0.5f, 0, 1 / (2 * fd * fd)};
        }
        if (kind == Kind::parallel) {
            scene_.lights.push_back(DirectionalLight{normalize(target - at), c});
            return;
        }
        if (kind == Kind::spot) {
            SpotLight s;
            s.position = at;
            s.direction = normalize(target - at);
            const double cone = std::max(falloff, radius);
            s.cos_cone = float(std::cos(cone * std::numbers::pi / 180));
            s.cos_falloff = float(std::cos(std::min(radius, cone) * std::numbers::pi / 180));
            s.color = c;
            s.attenuation = attenuation;
            scene_.lights.push_back(s);
            return;
        }
        if (area_u) {
            std::optional<AreaLight> area;
            if (circular) {
                area = disk_light(at,
                                  Normal3(normalize(cross(to_vector(*area_u), to_vector(*area_v)))),
                                  float(norm(*area_u) / 2));
            } else {
                area = rectangle_light(at, placed(to_vector(*area_u)), placed(to_vector(*area_v)));
            }
            if (area) {
                area->color = c;
                area->attenuation = attenuation;
                area->shadow_rays = n1 * n2;
                scene_.lights.push_back(*area);
                any_area_light_ = true;
                return;
            }
        }
        scene_.lights.push_back(PointLight{at, c, attenuation});
    }

    void background(const PovToken&) {
        parser_.expect("{", "after background");
        scene_.settings.background = rgb(parser_.color_expression("as the background"));
        parser_.expect("}", "after the background's colour");
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
            else if (w == "assumed_gamma")
                parser_.finite_float("after assumed_gamma");
            else if (w == "max_intersections" || w == "number_of_waves" || w == "noise_generator")
                parser_.finite_float("after " + w);
            else if (w == "charset")
                parser_.next();
            else if (w == "radiosity" || w == "photons" || w == "subsurface") {
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

    std::uint32_t material(const std::shared_ptr<const PovTexture>& texture,
                           const std::shared_ptr<const PovInterior>& interior) {
        const auto key = std::make_pair(texture, interior);
        if (const auto found = materials_.find(key); found != materials_.end())
            return found->second;
        const PovTexture& t = *texture;
        Material m;
        m.name = "pov" + std::to_string(scene_.materials.size());
        const PovPigment& p = t.pigment;
        if (p.kind == PovPigment::Kind::unsupported)
            throw files_.error_at(p.at,
                                  "pigment pattern " + quote(p.pattern) + " is not supported yet",
                                  {"docs/povray.md lists what glint reads"});
        if (p.kind == PovPigment::Kind::checker) {
            CheckerTexture checker;
            checker.even = rgb(p.color);
            checker.odd = rgb(p.other);
            m.color = checker;
        } else {
            m.color = rgb(p.color);
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
        m.reflect = float(std::clamp(f.reflection, 0.0, 1.0));
        if (f.emission > 0 && p.kind == PovPigment::Kind::color)
            m.emission = rgb(p.color) * float(f.emission);
        m.transmit = float(std::clamp(p.color[3] + p.color[4], 0.0, 1.0));
        if (interior) m.ior = float(interior->ior);
        scene_.materials.push_back(std::move(m));
        const auto index = std::uint32_t(scene_.materials.size() - 1);
        materials_.emplace(key, index);
        return index;
    }

    // The object's shape as one glint shape (a CSG of its children, each placed), or nothing for
    // a group, whose children are objects of their own.
    Shape placed_shape(const PovObject& object) {
        refuse_unread(object);
        Shape shape;
        if (object.shape) {
            shape = *object.shape;
        } else {
            const CsgOperation op =
                object.csg == PovObject::Csg::merge          ? CsgOperation::merge
                : object.csg == PovObject::Csg::intersection ? CsgOperation::intersection
                : object.csg == PovObject::Csg::difference   ? CsgOperation::difference
                                                             : CsgOperation::union_of;
            shape = placed_shape(*object.children[0]);
            for (std::size_t i = 1; i < object.children.size(); ++i) {
                Csg csg;
                csg.operation = op;
                csg.a = std::make_shared<const Shape>(std::move(shape));
                csg.b = std::make_shared<const Shape>(placed_shape(*object.children[i]));
                shape = csg;
            }
        }
        if (object.transform == Transform{}) return shape;
        return Transformed(object.transform, std::make_shared<const Shape>(std::move(shape)));
    }

    void add(const PovObject& object, const Transform& parent,
             std::shared_ptr<const PovTexture> texture, std::shared_ptr<const PovInterior> interior,
             bool no_shadow) {
        refuse_unread(object);
        if (object.texture) texture = object.texture;
        if (!texture) texture = object.fallback;
        if (object.interior) interior = object.interior;
        no_shadow = no_shadow || object.no_shadow;
        const Transform placement = parent * object.transform;
        if (!object.shape && object.csg == PovObject::Csg::group) {
            for (const auto& child : object.children)
                add(*child, placement, texture, interior, no_shadow);
            return;
        }
        PovObject local = object;
        local.transform = Transform{};
        Shape shape = placed_shape(local);
        if (!(placement == Transform{}))
            shape = Transformed(placement, std::make_shared<const Shape>(std::move(shape)));
        SceneObject o{std::move(shape), material(texture, interior)};
        o.casts_shadow = !no_shadow;
        scene_.objects.push_back(std::move(o));
    }

    PovFiles& files_;
    Scene scene_;
    PovParser parser_;
    PovItemReader items_;
    // By the texture and interior themselves, held so that a freed one's address is never
    // taken for a new one's.
    std::map<std::pair<std::shared_ptr<const PovTexture>, std::shared_ptr<const PovInterior>>,
             std::uint32_t>
        materials_;
    bool any_area_light_ = false;
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
