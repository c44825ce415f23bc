// A model file as a scene: its own cameras and lights when it has them, else a camera that frames
// it and a key and fill light.
#include "glint/scene/mesh/model_scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "glint/math/constants.h"

namespace glint {

namespace {

// Looks at the model's bounding sphere from the front (+z, glTF's convention), a little from
// above and to the side, from far enough that the sphere fills the vertical field of view.
CameraSpec framing_camera(const Bounds3& bounds) {
    CameraSpec camera;
    const Point3 center = bounds.center();
    const float radius = std::max(length(bounds.diagonal()) / 2, 1e-6f);
    camera.fov = 40;
    const float distance = 1.1f * radius / std::sin(radians(camera.fov / 2));
    camera.from = center + normalize(Vector3{0.45f, 0.35f, 1}) * distance;
    camera.at = center;
    return camera;
}

}  // namespace

Scene model_to_scene(const Model& model) {
    Scene scene;
    scene.settings.background = {0.3f, 0.32f, 0.36f};
    scene.camera = model.cameras.empty() ? framing_camera(model.bounds) : model.cameras[0].spec;
    if (model.lights.empty()) {
        // A key light over the camera's left shoulder and a dim fill from the other side.
        const Vector3 view = normalize(scene.camera.at - scene.camera.from);
        const Vector3 right = normalize(cross(view, scene.camera.up));
        scene.lights.push_back(DirectionalLight{
            normalize(view - 0.6f * right + Vector3{0, -0.8f, 0}), Color::gray(0.85f)});
        scene.lights.push_back(DirectionalLight{normalize(view + right), Color::gray(0.25f)});
        scene.ambient = Color::gray(0.15f);
    } else {
        scene.lights = model.lights;
        scene.ambient = Color::gray(0.05f);
    }
    scene.materials = model.materials;
    if (scene.materials.empty()) scene.materials.push_back(Material{});
    for (const ModelPart& part : model.parts) {
        scene.objects.push_back({TriangleMesh{part.mesh}, part.material});
    }
    scene.warnings = model.warnings;
    return scene;
}

Scene load_model_scene(const std::filesystem::path& file, const ReadSandbox& sandbox) {
    ModelOptions options;
    options.sandbox = sandbox;
    return model_to_scene(load_model(file, options));
}

Scene load_model_scene(const std::filesystem::path& file) {
    return model_to_scene(load_model(file));
}

}  // namespace glint
