// The checks of the particles' integrators (finite power for every light, a lens to reach) and
// of the beam integrator (planar polygons, a pinhole, one kr and kt a polygon).
#include "glint/scene/integrator_fit.h"

#include <cstdio>
#include <fstream>
#include <string>

namespace glint {

namespace {

std::string number(float x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(x));
    return text;
}

std::string kind_of(const Light& light) {
    if (std::holds_alternative<PointLight>(light)) return "point";
    if (std::holds_alternative<SpotLight>(light)) return "spot";
    if (std::holds_alternative<DirectionalLight>(light)) return "directional";
    return "area";
}

const Attenuation* attenuation_of(const Light& light) {
    if (const auto* p = std::get_if<PointLight>(&light)) return &p->attenuation;
    if (const auto* s = std::get_if<SpotLight>(&light)) return &s->attenuation;
    if (const auto* a = std::get_if<AreaLight>(&light)) return &a->attenuation;
    return nullptr;
}

// The text of the location's line in its file, for the error's excerpt; empty when unknown.
std::string line_of(const SourceLocation& where) {
    if (where.line <= 0) return {};
    std::ifstream in(where.file, std::ios::binary);
    std::string line;
    for (int i = 0; i < where.line && std::getline(in, line); ++i) {
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return in ? line : std::string();
}

// The place of the i-th material, light or object where the loader kept it, else the file's.
template <class Places>
SourceLocation place_of(const Scene& scene, const Places& places, std::size_t i) {
    if (i < places.size()) return {scene.sources.file, places[i].line, places[i].column};
    return {scene.sources.file, 0, 0};
}

// Beam tracing sweeps beams through planar polygons seen through a pinhole, and weighs each
// reflected and refracted beam by one kr and kt over the whole polygon.
void check_beam_fits(const Scene& scene) {
    const CameraSpec& camera = scene.camera;
    const SourceLocation file{scene.sources.file, 0, 0};
    if (camera.projection != Projection::perspective || camera.lens.radius > 0 ||
        !camera.motion.empty())
        throw SceneError(file,
                         "the beam integrator needs a still pinhole camera: its beams are "
                         "pyramids from one eye, and a lens, an orthographic or wide view or a "
                         "moving camera has many",
                         {"render it with the whitted or distributed integrator"});
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const auto unfit = beam_unfit_part(scene.objects[i].shape);
        if (!unfit) continue;
        const SourceLocation where = place_of(scene, scene.sources.objects, i);
        throw SceneError(where,
                         "object " + std::to_string(i) + " is " + *unfit +
                             ": the beam integrator traces scenes of planar polygons (polygons, "
                             "triangles, meshes and boxes), whose reflections are linear maps",
                         {"make it of polygons or a mesh, or render with the whitted integrator"},
                         line_of(where));
    }
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        const char* varying = m.fresnel                   ? "has fresnel: true"
                              : m.maps && m.maps->reflect ? "has a textured reflect"
                              : m.reflect_angular || m.reflect_metallic > 0
                                  ? "has a reflect that varies with the angle"
                              : m.reflect_color != Color{1, 1, 1} ? "has a reflect_color"
                              : m.tint > 0                        ? "has a tint"
                              : m.fade.fades()                    ? "has a fade"
                                                                  : nullptr;
        if (!varying) continue;
        const SourceLocation where = place_of(scene, scene.sources.materials, i);
        throw SceneError(where,
                         "material '" + m.name + "' " + varying +
                             ": the beam integrator weighs a polygon's reflected and refracted "
                             "beams by one grey kr and kt across the whole polygon",
                         {"give it constant reflect and transmit, or render with the whitted "
                          "integrator"},
                         line_of(where));
    }
}

}  // namespace

std::optional<std::string> beam_unfit_part(const Shape& shape) {
    if (std::holds_alternative<Polygon>(shape) || std::holds_alternative<Triangle>(shape) ||
        std::holds_alternative<TriangleMesh>(shape) || std::holds_alternative<Box>(shape))
        return std::nullopt;
    if (const auto* placed = std::get_if<Transformed>(&shape))
        return beam_unfit_part(*placed->shape);
    if (std::holds_alternative<Moving>(shape)) return std::string("a moving object");
    if (std::holds_alternative<Plane>(shape)) return std::string("an infinite plane");
    if (std::holds_alternative<Csg>(shape)) return std::string("a CSG object");
    const std::string name(shape_name(shape));
    const bool vowel = name.find_first_of("aeiou") == 0;
    return (vowel ? "an " : "a ") + name + ", which is curved";
}

// Participating media are marched along the rays of the Whitted family only.
void check_media_fit(const Scene& scene) {
    const IntegratorKind kind = scene.settings.integrator;
    if (kind == IntegratorKind::whitted || kind == IntegratorKind::distributed) return;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        if (m.media.empty()) continue;
        const SourceLocation where = place_of(scene, scene.sources.materials, i);
        throw SceneError(where,
                         "material '" + m.name + "' is filled with a participating medium: the " +
                             std::string(integrator_info(kind).name) +
                             " integrator does not march media along its rays",
                         {"render it with the whitted or distributed integrator"}, line_of(where));
    }
}

void check_integrator_fits(const Scene& scene) {
    check_media_fit(scene);
    if (scene.settings.integrator == IntegratorKind::beam) return check_beam_fits(scene);
    const IntegratorInfo& integrator = integrator_info(scene.settings.integrator);
    if (!integrator.traces_particles) return;
    const std::string name(integrator.name);
    if (scene.camera.projection != Projection::perspective)
        throw SceneError({scene.sources.file, 0, 0},
                         "the " + name + " integrator cannot see through " +
                             camera_named(scene.camera.projection) +
                             ": it joins the surfaces particles reach to the eye, and only a "
                             "perspective camera tells where on its film a point is seen",
                         {"render it with the path integrator, or a perspective camera"});
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        if (emits_finite_power(light)) continue;
        const Attenuation& a = *attenuation_of(light);
        SourceLocation where{scene.sources.file, 0, 0};
        if (i < scene.sources.lights.size())
            where = {scene.sources.file, scene.sources.lights[i].line,
                     scene.sources.lights[i].column};
        throw SceneError(where,
                         "light " + std::to_string(i) + " (" + kind_of(light) +
                             ") does not fall off as 1 / d^2 (attenuation constant " +
                             number(a.constant) + ", linear " + number(a.linear) + ", quadratic " +
                             number(a.quadratic) +
                             "): it has no finite power for "
                             "the " +
                             name + " integrator's particles to carry",
                         {"give it attenuation: {constant: 0, linear: 0, quadratic: 1} (and a "
                          "colour to match), or render with the path integrator"},
                         line_of(where));
    }
}

}  // namespace glint
