// The checks of the particles' integrators: finite power for every light, a lens to reach.
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

}  // namespace

void check_integrator_fits(const Scene& scene) {
    const IntegratorInfo& integrator = integrator_info(scene.settings.integrator);
    if (!integrator.traces_particles) return;
    const std::string name(integrator.name);
    if (scene.camera.projection != Projection::perspective)
        throw SceneError({scene.sources.file, 0, 0},
                         "the " + name +
                             " integrator cannot see through an orthographic camera: it joins "
                             "the surfaces particles reach to the eye through its lens, and an "
                             "orthographic camera sees each point along one direction only",
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
