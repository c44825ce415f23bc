// Maps the materials Assimp reads (OBJ/MTL, glTF metallic-roughness) onto glint's classic Phong
// and Whitted material; the table is in docs/meshes.md. Internal to glint_scene: it includes
// Assimp's headers.
#pragma once

#include <assimp/material.h>

#include <functional>
#include <optional>
#include <string>

#include "glint/shading/material.h"

namespace glint {

// Which file format's meaning the material's values carry.
enum class MaterialConvention {
    obj,   // MTL: Kd, Ka, Ks, Ke, Ns, Ni, d/Tr, illum, map_Kd
    gltf,  // glTF 2.0 metallic-roughness, KHR_materials_transmission, KHR_materials_ior
};

// Returns the image texture for a texture path as Assimp reports it ("tex.png", "*0" for an
// embedded one), scaled by `scale`; throws SceneError when it cannot be loaded.
using TextureResolver =
    std::function<ImageTexture(const std::string& path, Color scale, TextureWrap wrap)>;

Material map_material(const aiMaterial& material, MaterialConvention convention,
                      const TextureResolver& resolve_texture);

// The glTF roughness to Blinn-Phong exponent conversion, n = 2 / alpha^2 - 2 with
// alpha = roughness^2 (Walter et al. 2007, eq. 30, with the GGX alpha of Karis 2013), clamped to
// [1, 10000] (roughness 0 would be a perfect mirror highlight).
float shininess_from_roughness(float roughness);

}  // namespace glint
