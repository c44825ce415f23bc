// NFF to Scene: the view and settings, lights scaled by their number, materials mapped to the
// classic model, and primitives as glint shapes. Triangles go into one mesh per material and
// kind (flat polygons, patches with vertex normals), so that scenes of a million of them stay
// compact and get a BVH of their own.
#include "glint/scene/nff/nff_to_scene.h"

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "glint/geometry/triangle_mesh.h"
#include "glint/scene/nff/nff_parser.h"

namespace glint {

namespace {

// The SPD writes this Shine for "no highlight".
constexpr float kNoHighlightShine = 100000;

Material to_material(const NffMaterial& f, std::size_t index) {
    Material m;
    m.name = "f" + std::to_string(index + 1);
    m.color = f.color;
    m.kd = f.kd;
    m.ka = f.kd;  // NFF has no ambient coefficient: the ambient light reflects as diffuse light
    // Ks is both the highlight strength and the mirror weight (the SPD's reflection weight).
    m.ks = f.shine >= kNoHighlightShine ? 0 : f.ks;
    m.shininess = f.shine >= kNoHighlightShine ? 1 : f.shine;
    // The SPD derives Shine from a highlight half-angle for (R.V)^n.
    m.highlight = Highlight::phong;
    m.reflect = std::min(f.ks, 1.0f);
    // The SPD's transmitters are all reflective (its rule 8 spawns a reflection ray at every
    // transmitting surface); where the file gives Ks = 0 (the gears' glass), the surface
    // reflects what a dielectric does head-on: the Fresnel reflectance ((n - 1) / (n + 1))^2.
    if (f.transmittance > 0 && m.reflect == 0) {
        const float r = (f.ior - 1) / (f.ior + 1);
        m.reflect = r * r;
    }
    m.transmit = std::min(f.transmittance, 1.0f);
    m.ior = f.transmittance > 0 ? f.ior : 1;
    return m;
}

// Triangles collected per (material, with normals or not), then built into meshes.
class MeshCollector {
public:
    // Room for the triangles that add() will be given, counted beforehand: a million of them
    // then fill their arrays without copying them as they grow.
    void reserve(std::uint32_t material, bool with_normals, std::size_t triangles) {
        MeshData& mesh = meshes_[{material, with_normals}];
        mesh.positions.reserve(mesh.positions.size() + 3 * triangles);
        if (with_normals) mesh.normals.reserve(mesh.normals.size() + 3 * triangles);
        mesh.triangles.reserve(mesh.triangles.size() + triangles);
    }

    void add(std::uint32_t material, const Point3* p, const Normal3* n) {
        MeshData& mesh = meshes_[{material, n != nullptr}];
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (int k = 0; k < 3; ++k) {
            mesh.positions.push_back(p[k]);
            if (n) mesh.normals.push_back(n[k]);
        }
        mesh.triangles.push_back({base, base + 1, base + 2});
    }

    void emit(LargeVector<SceneObject>& objects, std::vector<std::string>& warnings) {
        for (auto& [key, arrays] : meshes_) {
            MeshBuild built = build_mesh(std::move(arrays));
            if (!built.mesh) {
                // Only degenerate triangles (the parser checked everything else): nothing to draw.
                warnings.push_back(built.error);
                continue;
            }
            if (built.degenerate_dropped > 0) {
                warnings.push_back(std::to_string(built.degenerate_dropped) +
                                   " degenerate triangles dropped");
            }
            objects.push_back({TriangleMesh{built.mesh}, key.first});
        }
    }

private:
    std::map<std::pair<std::uint32_t, bool>, MeshData> meshes_;
};

// Spheres and cones that NFF makes visible from inside only; glint draws every surface from both
// sides, so the scene says how many there are and where the first one is.
struct InsideOnly {
    std::size_t spheres = 0, cones = 0;
    std::optional<NffLocation> first;

    void count(const NffObject& object) {
        const auto* s = std::get_if<NffSphere>(&object.primitive);
        const auto* c = std::get_if<NffCone>(&object.primitive);
        if (!(s && s->inside_only) && !(c && c->inside_only)) return;
        ++(s ? spheres : cones);
        if (!first) first = object.location;
    }

    std::optional<std::string> warning(const NffScene& nff) const {
        if (!first) return std::nullopt;
        const SourceLocation at = nff.where(*first);
        const auto count_of = [](std::size_t n, const char* what) {
            return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
        };
        std::string what;
        if (spheres + cones == 1) {
            what = spheres == 1 ? "a sphere with a negative radius" : "a cone with negative radii";
        } else {
            what = spheres > 0 ? count_of(spheres, "sphere") : "";
            if (cones > 0) what += (what.empty() ? "" : " and ") + count_of(cones, "cone");
            what += " with negative radii";
        }
        const bool one = spheres + cones == 1;
        return at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " +
               what + ", which NFF makes visible from inside only, " + (one ? "is" : "are") +
               " drawn from both sides with the absolute " +
               (one && spheres == 1 ? "radius" : "radii") + " (glint's surfaces are two-sided)" +
               (one ? "" : "; the first is here");
    }
};

struct ToShapes {
    std::uint32_t material;
    LargeVector<SceneObject>& objects;
    MeshCollector& triangles;

    void operator()(const NffSphere& s) const {
        objects.push_back({Sphere{s.center, s.radius}, material});
    }
    void operator()(const NffCone& c) const {
        // NFF cones and cylinders are open: no end caps.
        if (c.base_radius == c.apex_radius) {
            objects.push_back({Cylinder{c.base, c.apex, c.base_radius, false}, material});
        } else {
            objects.push_back(
                {Cone{c.base, c.base_radius, c.apex, c.apex_radius, false}, material});
        }
    }
    void operator()(const NffPolygon& p) const {
        if (p.vertices.size() == 3) {
            triangles.add(material, p.vertices.data(), nullptr);
            return;
        }
        // Checked by the parser, so make_polygon succeeds; concave ones (the gears) included.
        objects.push_back({std::get<Polygon>(make_polygon(p.vertices)), material});
    }
    void operator()(const NffPatch& p) const {
        // A fan; every patch of the SPD is a triangle.
        for (std::size_t i = 1; i + 1 < p.vertices.size(); ++i) {
            const Point3 v[3] = {p.vertices[0], p.vertices[i], p.vertices[i + 1]};
            const Normal3 n[3] = {p.normals[0], p.normals[i], p.normals[i + 1]};
            triangles.add(material, v, n);
        }
    }
};

}  // namespace

Scene nff_to_scene(const NffScene& nff) {
    const NffView& view = require_view(nff);
    Scene scene;
    RenderSettings& s = scene.settings;
    s.width = view.width;
    s.height = view.height;
    s.max_depth = 5;   // the eye ray is depth 1
    s.min_weight = 0;  // no adaptive cut-off of the ray tree
    s.background = nff.background.value_or(Color{});

    scene.camera.from = view.from;
    scene.camera.at = view.at;
    scene.camera.up = view.up;
    scene.camera.fov = view.angle_degrees;

    // NFF gives lights no intensity. The SPD's README gives each of N lights, and the ambient
    // light, the relative intensity sqrt(N) / 2N.
    const float n = static_cast<float>(std::max<std::size_t>(1, nff.lights.size()));
    const float intensity = std::sqrt(n) / (2 * n);
    for (const NffLight& l : nff.lights) {
        scene.lights.push_back(
            PointLight{l.position, l.color.value_or(Color::gray(1)) * intensity});
    }
    scene.ambient = Color::gray(intensity);

    // The SPD repeats an "f" line before most objects (the lattice writes 270,641 of them, of
    // four materials): equal ones become one material, named after the first.
    std::vector<std::uint32_t> material_of(nff.materials.size());
    std::map<std::array<float, 8>, std::uint32_t> seen;
    for (std::size_t i = 0; i < nff.materials.size(); ++i) {
        const NffMaterial& f = nff.materials[i];
        const std::array<float, 8> key{f.color.r, f.color.g, f.color.b,       f.kd,
                                       f.ks,      f.shine,   f.transmittance, f.ior};
        const auto [at, added] = seen.try_emplace(key, std::uint32_t(scene.materials.size()));
        if (added) scene.materials.push_back(to_material(f, i));
        material_of[i] = at->second;
    }
    MeshCollector triangles;
    std::map<std::pair<std::uint32_t, bool>, std::size_t> triangle_counts;
    std::size_t shapes = 0;
    for (const NffObject& object : nff.objects) {
        const auto* p = std::get_if<NffPolygon>(&object.primitive);
        const auto* patch = std::get_if<NffPatch>(&object.primitive);
        if (p && p->vertices.size() == 3) {
            ++triangle_counts[{material_of[object.material], false}];
        } else if (patch) {
            triangle_counts[{material_of[object.material], true}] += patch->vertices.size() - 2;
        } else {
            ++shapes;
        }
    }
    for (const auto& [key, count] : triangle_counts)
        triangles.reserve(key.first, key.second, count);
    scene.objects.reserve(shapes);
    InsideOnly inside_only;
    for (const NffObject& object : nff.objects) {
        std::visit(ToShapes{material_of[object.material], scene.objects, triangles},
                   object.primitive);
        inside_only.count(object);
    }
    triangles.emit(scene.objects, scene.warnings);
    if (const auto warning = inside_only.warning(nff)) scene.warnings.push_back(*warning);
    return scene;
}

Scene load_nff_scene(const std::filesystem::path& file, std::uint64_t max_bytes,
                     const SceneLimits& limits) {
    return nff_to_scene(load_nff(file, max_bytes, limits.image_pixels));
}

}  // namespace glint
