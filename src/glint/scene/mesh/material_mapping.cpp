// The MTL and glTF material mappings of docs/meshes.md.
#include "glint/scene/mesh/material_mapping.h"

#include <assimp/ObjMaterial.h>

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

// A value is used only when finite; a NaN in a file never reaches the renderer.
Color finite_or(Color c, Color fallback) { return is_finite(c) ? c : fallback; }

Color get_color(const aiMaterial& m, const char* key, unsigned type, unsigned index,
                Color fallback) {
    aiColor4D c;
    if (m.Get(key, type, index, c) != AI_SUCCESS) return fallback;
    return finite_or(Color{c.r, c.g, c.b}, fallback);
}

std::optional<float> get_float(const aiMaterial& m, const char* key, unsigned type,
                               unsigned index) {
    float v = 0;
    if (m.Get(key, type, index, v) != AI_SUCCESS || !std::isfinite(v)) return std::nullopt;
    return v;
}

// The texture of the given kind, if the material names one.
std::optional<ImageTexture> texture_of(const aiMaterial& m, aiTextureType type, Color scale,
                                       const TextureResolver& resolve) {
    aiString path;
    aiTextureMapMode modes[2] = {aiTextureMapMode_Wrap, aiTextureMapMode_Wrap};
    if (m.GetTextureCount(type) == 0 ||
        m.GetTexture(type, 0, &path, nullptr, nullptr, nullptr, nullptr, modes) != AI_SUCCESS ||
        path.length == 0) {
        return std::nullopt;
    }
    // glint has one wrap mode for both axes: clamp only when both are clamped.
    const bool clamp = modes[0] == aiTextureMapMode_Clamp && modes[1] == aiTextureMapMode_Clamp;
    return resolve(path.C_Str(), scale, clamp ? TextureWrap::clamp : TextureWrap::repeat);
}

Material map_obj(const aiMaterial& m, const TextureResolver& resolve) {
    Material out;
    const Color kd = get_color(m, AI_MATKEY_COLOR_DIFFUSE, Color::gray(0.6f));
    const Color ka = get_color(m, AI_MATKEY_COLOR_AMBIENT, Color{});
    const Color ks = get_color(m, AI_MATKEY_COLOR_SPECULAR, Color{});
    // The MTL colour Kd is the surface colour, with kd = 1 so that it is not scaled twice;
    // map_Kd is multiplied by Kd, as the MTL specification says.
    out.kd = 1;
    if (auto texture = texture_of(m, aiTextureType_DIFFUSE, kd, resolve)) {
        out.color = std::move(*texture);
    } else {
        out.color = kd;
    }
    // glint's ambient term is ka Ia C with C = Kd; MTL's is Ka Ia, so ka = Ka / Kd (means).
    out.ka = mean(kd) > 0 ? std::clamp(mean(ka) / mean(kd), 0.0f, 1.0f) : 0;
    out.ks = std::clamp(mean(ks), 0.0f, 1.0f);
    // Ns 0 (also Assimp's value when Ns is absent) would make the highlight a flat ks.
    out.shininess = std::max(1.0f, get_float(m, AI_MATKEY_SHININESS).value_or(1));
    const float ni = get_float(m, AI_MATKEY_REFRACTI).value_or(1);
    out.ior = ni > 0 ? ni : 1;
    // Assimp stores d as the opacity, and Tr as 1 - Tr; the later line wins.
    out.transmit = std::clamp(1 - get_float(m, AI_MATKEY_OPACITY).value_or(1), 0.0f, 1.0f);
    int illum = 2;
    m.Get(AI_MATKEY_OBJ_ILLUM, illum);
    // illum 3 to 7 add ray-traced reflection, weighted by the specular colour.
    if (illum >= 3 && illum <= 7) out.reflect = out.ks;
    out.emission = get_color(m, AI_MATKEY_COLOR_EMISSIVE, Color{});
    return out;
}

Material map_gltf(const aiMaterial& m, const TextureResolver& resolve) {
    Material out;
    // Assimp reports baseColorFactor as the base colour and as the diffuse colour.
    const Color base =
        get_color(m, AI_MATKEY_BASE_COLOR, get_color(m, AI_MATKEY_COLOR_DIFFUSE, Color{1, 1, 1}));
    out.kd = 1;
    std::optional<ImageTexture> texture = texture_of(m, aiTextureType_BASE_COLOR, base, resolve);
    if (!texture) texture = texture_of(m, aiTextureType_DIFFUSE, base, resolve);
    if (texture) {
        out.color = std::move(*texture);
    } else {
        out.color = base;
    }
    // glTF's defaults are metallic 1, roughness 1.
    const float metallic =
        std::clamp(get_float(m, AI_MATKEY_METALLIC_FACTOR).value_or(1), 0.f, 1.f);
    const float roughness =
        std::clamp(get_float(m, AI_MATKEY_ROUGHNESS_FACTOR).value_or(1), 0.f, 1.f);
    out.ks = 1 - roughness;
    out.shininess = shininess_from_roughness(roughness);
    // Only smooth metal mirrors: a rough one (glTF's default material) must not.
    out.reflect = metallic * (1 - roughness);
    out.transmit = std::clamp(get_float(m, AI_MATKEY_TRANSMISSION_FACTOR).value_or(0), 0.0f, 1.0f);
    const std::optional<float> ior = get_float(m, AI_MATKEY_REFRACTI);
    out.ior = ior && *ior > 0 ? *ior : (out.transmit > 0 ? 1.5f : 1.0f);
    const float strength = get_float(m, AI_MATKEY_EMISSIVE_INTENSITY).value_or(1);
    out.emission = get_color(m, AI_MATKEY_COLOR_EMISSIVE, Color{}) * strength;
    return out;
}

}  // namespace

float shininess_from_roughness(float roughness) {
    const float alpha = roughness * roughness;
    const float a2 = alpha * alpha;
    if (!(a2 > 2.0f / 10002.0f)) return 10000;  // 2 / a2 - 2 would pass the cap
    return std::clamp(2 / a2 - 2, 1.0f, 10000.0f);
}

Material map_material(const aiMaterial& material, MaterialConvention convention,
                      const TextureResolver& resolve_texture) {
    Material out = convention == MaterialConvention::gltf ? map_gltf(material, resolve_texture)
                                                          : map_obj(material, resolve_texture);
    aiString name;
    if (material.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
    return out;
}

}  // namespace glint
