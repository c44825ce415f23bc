// The lint rules, one function each.
#include "glint/scene/lint.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "glint/geometry/cone_coverage.h"
#include "glint/geometry/point_inside.h"
#include "glint/math/constants.h"
#include "glint/scene/integrators.h"
#include "glint/scene/quote.h"

namespace glint {

namespace {

using Warnings = std::vector<LintWarning>;

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
}

std::string point(Point3 p) {
    return "(" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + ")";
}

std::string material_subject(const Material& m) { return "material " + quote(m.name); }

// The file:line:col of entry i of a SceneSources list, when the loader kept one.
template <typename Positions>
std::optional<SourceLocation> located(const Scene& scene, const Positions& positions,
                                      std::size_t i) {
    if (i >= positions.size() || positions[i].line == 0) return std::nullopt;
    return SourceLocation{scene.sources.file, positions[i].line, positions[i].column};
}

std::string_view light_kind(const Light& light) {
    if (std::holds_alternative<PointLight>(light)) return "point";
    if (std::holds_alternative<SpotLight>(light)) return "spot";
    if (std::holds_alternative<DirectionalLight>(light)) return "directional";
    return "area";
}

void no_lights(const Scene& scene, Warnings& out) {
    if (!scene.lights.empty()) return;
    // The physically based integrators take the sky's light (the background is a sky of one
    // colour); Whitted's and Cook's only show it.
    const bool sky_lights = integrator_info(scene.settings.integrator).physically_based &&
                            (scene.sky || !is_black(scene.settings.background));
    if (sky_lights) return;
    // A glowing object counts even when it lights nothing (emits_light: false): it is seen, as
    // a slit seen through a prism is.
    for (const SceneObject& object : scene.objects)
        if (emits(scene.materials[object.material])) return;
    out.push_back({"no-lights", "scene",
                   "the scene has no lights and no emitting objects: only the ambient term "
                   "(ka * ambient) lights it, so every surface is flat",
                   std::nullopt});
}

void camera_inside(const Scene& scene, Warnings& out) {
    const Point3 eye = scene.camera.from;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        if (point_inside(scene.objects[i].shape, eye) != true) continue;
        out.push_back({"camera-inside", "camera",
                       "the camera at " + point(eye) + " is inside " + object_subject(scene, i) +
                           ": every eye ray starts inside that solid and sees its inner side",
                       located(scene, scene.sources.objects, i)});
    }
}

// Where a light shines from, when it has one place: a point or spot light's position, an area
// light's centre.
std::optional<Point3> light_position(const Light& light) {
    if (const auto* p = std::get_if<PointLight>(&light)) return p->position;
    if (const auto* s = std::get_if<SpotLight>(&light)) return s->position;
    if (const auto* a = std::get_if<AreaLight>(&light)) return a->center;
    return std::nullopt;
}

void light_inside(const Scene& scene, Warnings& out) {
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const std::optional<Point3> at = light_position(scene.lights[l]);
        if (!at) continue;
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            // Objects that cast no shadow (an area light's own face) let the light out.
            if (!scene.objects[i].casts_shadow) continue;
            if (point_inside(scene.objects[i].shape, *at) != true) continue;
            out.push_back({"light-inside",
                           "light " + std::to_string(l) + " (" +
                               std::string(light_kind(scene.lights[l])) + ")",
                           "the light at " + point(*at) + " is inside " + object_subject(scene, i) +
                               ", which casts shadows: its light lights only the inside",
                           located(scene, scene.sources.lights, l)});
        }
    }
}

// For Whitted's and Cook's tracers a note (the notes' k_local + k_refl + k_trans = 1 is a
// guide there, and scenes break it for effect); for the physically based integrators, which
// scale the parts down so that no surface makes light, a warning.
void energy(const Scene& scene, Warnings& out) {
    const IntegratorInfo& integrator = integrator_info(scene.settings.integrator);
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        const double sum = double(m.kd) + m.ks + m.reflect + m.transmit;
        // Float sums of tenths are off by an ulp or so; a real excess is larger.
        if (!(sum > 1 + 1e-5)) continue;
        const std::string parts = "kd + ks + reflect + transmit = " + number(m.kd) + " + " +
                                  number(m.ks) + " + " + number(m.reflect) + " + " +
                                  number(m.transmit) + " = " + number(sum) + " > 1";
        if (integrator.physically_based)
            out.push_back({"energy", material_subject(m),
                           parts + ": the " + std::string(integrator.name) +
                               " integrator scales the four down by 1/" + number(sum) +
                               ", so that the surface gives back no more light than it receives",
                           located(scene, scene.sources.materials, i)});
        else
            out.push_back({"energy", material_subject(m),
                           parts + ": the surface can give back more light than it receives "
                                   "(k_local + k_refl + k_trans should be at most 1)",
                           located(scene, scene.sources.materials, i), /*note=*/true});
    }
}

// The ambient term is Whitted's stand-in for the light that surfaces reflect onto one another,
// which the physically based integrators compute: they leave it out.
void ambient(const Scene& scene, Warnings& out) {
    const IntegratorInfo& integrator = integrator_info(scene.settings.integrator);
    if (!integrator.physically_based || is_black(scene.ambient)) return;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        if (!(m.ka > 0)) continue;
        out.push_back({"ambient", material_subject(m),
                       "ka " + number(m.ka) + " with the scene's ambient light: the " +
                           std::string(integrator.name) +
                           " integrator leaves the ambient term out, since it computes the "
                           "light it stands in for",
                       located(scene, scene.sources.materials, i), /*note=*/true});
    }
}

void ior(const Scene& scene, Warnings& out) {
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        if (!(m.transmit > 0) || m.ior != 1 || m.dispersion.model != DispersionModel::none)
            continue;
        out.push_back({"ior", material_subject(m),
                       "transmits (transmit " + number(m.transmit) +
                           ") with an index of refraction of 1, which bends nothing: give it "
                           "an ior (glass about 1.5, water 1.33)",
                       located(scene, scene.sources.materials, i)});
    }
}

void unused_material(const Scene& scene, Warnings& out) {
    std::vector<bool> used(scene.materials.size(), false);
    for (const SceneObject& object : scene.objects) used[object.material] = true;
    for (std::size_t i = 0; i < used.size(); ++i) {
        if (used[i]) continue;
        out.push_back({"unused-material", material_subject(scene.materials[i]),
                       "is defined but no object uses it",
                       located(scene, scene.sources.materials, i)});
    }
}

// The view's frame and window: a box is out of view when all its corners lie beyond one side of
// the view's pyramid (perspective) or slab (orthographic), or behind the eye. A box that crosses
// a corner of the pyramid may be out of view without being found: the rule never warns wrongly.
// A wide projection's view may span a full turn: it is taken to see everything.
class View {
public:
    View(const CameraSpec& c, const RenderSettings& s)
        : eye_(c.from),
          forward_(normalize(c.at - c.from)),
          right_(normalize(cross(forward_, c.up))),
          up_(cross(right_, forward_)),
          perspective_(c.projection == Projection::perspective),
          wide_(!perspective_ && c.projection != Projection::orthographic),
          lens_(c.lens.radius) {
        half_height_ = perspective_ ? std::tan(radians(c.fov) / 2) : c.height / 2;
        half_width_ = half_height_ * (c.aspect > 0 ? c.aspect : float(s.width) / float(s.height));
    }

    bool sees(const Bounds3& box) const {
        if (wide_) return true;
        // The aperture's rays start up to its radius from the eye: grown boxes stay conservative.
        const Vector3 grow{lens_, lens_, lens_};
        const Bounds3 b{box.min - grow, box.max + grow};
        // Per side, whether every corner is beyond it: behind, right, left, top, bottom.
        std::array<bool, 5> beyond{true, true, true, true, true};
        for (int k = 0; k < 8; ++k) {
            const Point3 corner{(k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y,
                                (k & 4) ? b.max.z : b.min.z};
            const Vector3 d = corner - eye_;
            const float z = dot(d, forward_), x = dot(d, right_), y = dot(d, up_);
            const float w = perspective_ ? half_width_ * z : half_width_;
            const float h = perspective_ ? half_height_ * z : half_height_;
            beyond[0] = beyond[0] && !(z > 0);
            beyond[1] = beyond[1] && x > w;
            beyond[2] = beyond[2] && x < -w;
            beyond[3] = beyond[3] && y > h;
            beyond[4] = beyond[4] && y < -h;
        }
        return std::none_of(beyond.begin(), beyond.end(), [](bool side) { return side; });
    }

private:
    Point3 eye_;
    Vector3 forward_, right_, up_;
    bool perspective_, wide_;
    float lens_;
    float half_width_ = 1, half_height_ = 1;
};

void out_of_view(const Scene& scene, Warnings& out) {
    // A moving camera sweeps a view this check does not follow.
    if (!scene.camera.motion.empty()) return;
    const View view(scene.camera, scene.settings);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Bounds3 b = bounds(scene.objects[i].shape);
        if (!b.is_finite() || view.sees(b)) continue;
        out.push_back({"out-of-view", object_subject(scene, i),
                       "lies wholly outside the camera's view (or behind it): no eye ray sees it; "
                       "it shows only in reflections, refractions and shadows, if at all",
                       located(scene, scene.sources.objects, i)});
    }
}

// image.photons is read by the photon integrator alone, image.next_event by the integrators
// that sample lights by next-event estimation (path, photon).
void unused_setting(const Scene& scene, Warnings& out) {
    const IntegratorKind kind = scene.settings.integrator;
    const std::string name(integrator_info(kind).name);
    const auto at = [&](const std::optional<TextPosition>& p) -> std::optional<SourceLocation> {
        if (!p) return std::nullopt;
        return SourceLocation{scene.sources.file, p->line, p->column};
    };
    if (scene.sources.photons && kind != IntegratorKind::photon)
        out.push_back({"unused-setting", "image.photons",
                       "the " + name +
                           " integrator sends no photons: image.photons is for "
                           "integrator: photon",
                       at(scene.sources.photons)});
    if (scene.sources.next_event && kind != IntegratorKind::path && kind != IntegratorKind::photon)
        out.push_back({"unused-setting", "image.next_event",
                       "the " + name + " integrator " +
                           (kind == IntegratorKind::light
                                ? std::string("joins particles to the eye and samples no lights")
                                : std::string("samples every light at every point")) +
                           ": image.next_event is for the path and photon integrators",
                       at(scene.sources.next_event)});
}

// The cone integrator covers spheres, planes, polygons, triangles and disks by their outlines;
// other objects it sees along the cone's axis only.
void cone_fallback(const Scene& scene, Warnings& out) {
    if (scene.settings.integrator != IntegratorKind::cone) return;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        if (has_cone_test(scene.objects[i].shape)) continue;
        out.push_back({"cone-fallback", object_subject(scene, i),
                       "has no cone test: the cone integrator sees it by the cone's axis ray, "
                       "all of the cone or none, so its edges are not anti-aliased",
                       located(scene, scene.sources.objects, i), /*note=*/true});
    }
}

}  // namespace

std::string object_subject(const Scene& scene, std::size_t index) {
    return "object " + std::to_string(index) + " (" +
           std::string(shape_name(scene.objects[index].shape)) + ")";
}

std::vector<LintWarning> lint_scene(const Scene& scene) {
    Warnings out;
    no_lights(scene, out);
    camera_inside(scene, out);
    light_inside(scene, out);
    energy(scene, out);
    ambient(scene, out);
    ior(scene, out);
    unused_material(scene, out);
    out_of_view(scene, out);
    unused_setting(scene, out);
    cone_fallback(scene, out);
    return out;
}

}  // namespace glint
