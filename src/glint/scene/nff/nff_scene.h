// An NFF file (Haines' Neutral File Format of the Standard Procedural Databases) as plain data:
// what the file says, checked but not yet turned into a glint Scene.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "glint/math/color.h"
#include "glint/math/huge_page_allocator.h"
#include "glint/math/vector.h"
#include "glint/scene/scene_error.h"

namespace glint {

// Where an entity starts in the file: its keyword's 1-based line and column. The file name is
// kept once, in NffScene, rather than in each of a million objects.
struct NffLocation {
    std::uint32_t line = 0;
    std::uint32_t column = 0;
};

// `v`: from, at, up, angle, hither, resolution, in that order.
struct NffView {
    Point3 from, at;
    Vector3 up;  // non-zero and not parallel to at - from; not yet orthogonalised
    // The full field of view, in (0, 180). The spec measures it between the centres of the
    // outer pixels; the SPD's own exporters take it edge to edge.
    float angle_degrees = 45;
    float hither = 0;               // the near plane; a ray tracer may ignore it
    int width = 512, height = 512;  // within glint's image limits (scene.h)
    NffLocation location;
};

// `f r g b Kd Ks Shine T ior`, all >= 0. In the SPD, Ks is the mirror-reflection weight;
// Shine is 100000 for "no highlight"; ior is 0 where T = 0 and > 0 where T > 0.
struct NffMaterial {
    Color color;
    float kd = 0, ks = 0, shine = 0, transmittance = 0, ior = 0;
    NffLocation location;
};

// `l x y z [r g b]`: a point light; NFF gives no intensity, and the SPD never writes the colour.
struct NffLight {
    Point3 position;
    std::optional<Color> color;
    NffLocation location;
};

// `s x y z r`, r != 0. A negative r makes a sphere of radius |r| whose inside only is visible.
struct NffSphere {
    Point3 center;
    float radius = 1;          // > 0: |r|
    bool inside_only = false;  // r < 0
};

// `c`: a cone or cylinder without end caps; base != apex. Negative radii (both, or one with the
// other 0) make one whose inside only is visible.
struct NffCone {
    Point3 base;
    float base_radius = 1;  // >= 0, not both 0: as written, or their absolute values
    Point3 apex;
    float apex_radius = 1;
    bool inside_only = false;
};

// `p n`: a planar polygon of n >= 3 vertices, counter-clockwise seen from its visible side.
// Checked with polygon_problem(): at least 3 distinct vertices, an area, coplanar.
struct NffPolygon {
    std::vector<Point3> vertices;
};

// `pp n`: a polygon with a normal at each vertex for smooth shading. The normals are as written:
// non-zero, not normalised.
struct NffPatch {
    std::vector<Point3> vertices;
    std::vector<Normal3> normals;  // one per vertex
};

using NffPrimitive = std::variant<NffSphere, NffCone, NffPolygon, NffPatch>;

struct NffObject {
    NffPrimitive primitive;
    std::uint32_t material = 0;  // index into NffScene::materials
    NffLocation location;
};

struct NffScene {
    std::string file_name;               // as given to the parser, for locations
    std::optional<NffView> view;         // the renderer needs it: see require_view()
    std::optional<Color> background;     // black when absent
    std::vector<NffLight> lights;        // in file order
    LargeVector<NffMaterial> materials;  // in file order; objects index them
    LargeVector<NffObject> objects;      // in file order

    SourceLocation where(NffLocation at) const { return {file_name, int(at.line), int(at.column)}; }
};

}  // namespace glint
