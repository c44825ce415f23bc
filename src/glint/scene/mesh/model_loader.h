// Importing triangle meshes with their materials, lights and cameras from model files (OBJ/MTL,
// PLY, glTF 2.0, STL) through Assimp. Like every loader it only describes: the result is plain
// data that the scene loaders place into a Scene. docs/meshes.md has the formats and mappings.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/camera/camera_spec.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/math/bounds.h"
#include "glint/scene/read_sandbox.h"
#include "glint/shading/light.h"
#include "glint/shading/material.h"

namespace glint {

struct ModelOptions {
    // When set, vertex normals are (re)computed with this crease angle in degrees, [0, 180], and
    // the file's normals are ignored; otherwise the file's normals are kept, and meshes without
    // them are shaded flat.
    std::optional<float> crease_angle_degrees;
    // The folders whose files the model may use (MTL files, textures, glTF buffers and images);
    // nothing: the model file's folder only.
    std::optional<ReadSandbox> sandbox;
};

// A camera of the file (glTF perspective or orthographic), placed in world space.
struct ModelCamera {
    CameraSpec spec;
    std::string name;
};

// The triangles of one material (and one vertex layout), in world space: node transforms are
// applied, and every node that uses a mesh gets its own copy (glint instances at its own level).
struct ModelPart {
    std::shared_ptr<const MeshData> mesh;
    std::uint32_t material = 0;  // index into Model::materials
};

struct Model {
    std::vector<ModelPart> parts;
    std::vector<Material> materials;  // mapped from the file's; see docs/meshes.md
    // glTF KHR_lights_punctual: point lights with 1/d^2 falloff, directional lights; spot lights
    // come in as point lights, with a warning.
    std::vector<Light> lights;
    std::vector<ModelCamera> cameras;
    Bounds3 bounds;                     // of all parts
    std::vector<std::string> warnings;  // "3 degenerate triangles dropped", ...
};

// glTF gives point lights in candela and directional ones in lux; glint's light colour takes
// them 1:1 (as three.js does), so intensity 1 at distance 1 gives an irradiance of 1.
inline constexpr float kGltfLightUnitsToGlint = 1;

// Reads a model file; the extension picks the format (.obj, .ply, .gltf, .glb, .stl, any case).
// Throws SceneError only: file:line:col for bad lines of OBJ, MTL, ASCII PLY and ASCII STL files
// (checked before Assimp reads them), the file and Assimp's message for files Assimp refuses,
// the file and a clear message for what Assimp only logs (glTF indices out of range) and for
// what validation after import finds (no triangles, non-finite coordinates), and for a file the
// model names outside the sandbox (at the OBJ or MTL line that names it, or the glTF file).
Model load_model(const std::filesystem::path& file, const ModelOptions& options = {});

}  // namespace glint
