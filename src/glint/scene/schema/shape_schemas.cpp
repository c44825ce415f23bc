// The keys every object takes and those of each shape (docs/scene-format.md, "objects").
#include "glint/scene/schema/schema_tables.h"

namespace glint {

namespace {

const KeySchema kOperands{"objects", "list of shape maps", "required",
                          "the operands; a difference of `[a, b, c]` is `(a − b) − c`",
                          "at least 2; each a solid (a clip's first: any surface)"};
const KeySchema kCenter{"center", "point", "required", "the centre", ""};
const KeySchema kRadius{"radius", "number", "required", "the radius", "> 0", kPositive};
const KeySchema kOppositeCorner{"max", "point", "required", "the opposite corner", ""};
const KeySchema kPlacedCenter{"center", "point", "`[0, 0, 0]`", "where the set is placed", ""};
const KeySchema kFractalScale{"scale", "number", "1", "its size", "> 0", kPositive};

}  // namespace

std::vector<EntitySchema> shape_schemas() {
    return {
        {EntityFamily::object,
         "object",
         {
             {"type", "string", "required", "the shape",
              "`box`, `cone`, `cylinder`, `difference`, `disk`, `implicit`, `instance`, "
              "`intersection`, `julia`, `lathe`, `mandelbulb`, `merge`, `mesh`, `plane`, "
              "`polygon`, `prism`, `quadric`, `sphere`, `torus`, `triangle`, `union`"},
             {"transform", "list of steps", "none",
              "places the shape: see [transforms](#transforms)", ""},
             {"motion", "list of keyframes", "none",
              "moves the shape while the shutter is open: see [motion](#motion)", ""},
             {"material", "string or map", "the default material",
              "a name from `materials`, or a material map written inline", "a defined name"},
             {"casts_shadow", "bool", "true", "whether the object blocks shadow feelers", ""},
             {"emits_light", "bool", "true",
              "with an emitting material: whether the object lights the scene (`distributed`; see "
              "[objects that emit light](#objects-that-emit-light))",
              ""},
         }},
        {EntityFamily::shape,
         "sphere",
         {
             kCenter,
             kRadius,
         }},
        {EntityFamily::shape,
         "plane",
         {
             {"point", "point", "required", "any point of the plane", ""},
             {"normal", "vector", "required",
              "the plane's normal; its side is the front; normalised", "non-zero"},
         }},
        {EntityFamily::shape,
         "triangle",
         {
             {"vertices", "list of 3 points", "required", "the corners",
              "not collinear (relative to the triangle's size)"},
             {"uvs", "list of 3 `[u, v]`", "`[[0, 0], [1, 0], [0, 1]]`",
              "texture coordinates at the corners", "finite"},
         }},
        {EntityFamily::shape,
         "box",
         {
             {"min", "point", "required", "the corner with the smallest coordinates",
              "`min` < `max` on every axis"},
             kOppositeCorner,
         }},
        {EntityFamily::shape,
         "polygon",
         {
             {"vertices", "list of points", "required",
              "the outline in order; the last joins the first",
              "at least 3, coplanar (within 1e-3 of the polygon's size), with an area"},
             {"inside_test", "string", "`even_odd`",
              "the notes' inside test: `even_odd` counts edge crossings, `angle_sum` sums the "
              "angles the edges subtend (the winding number). They agree on simple polygons; on "
              "self-intersecting ones `even_odd` leaves doubly covered parts out",
              "`even_odd`, `angle_sum`"},
         }},
        {EntityFamily::shape,
         "prism",
         {
             {"points", "list of `[x, z]`", "required",
              "the outlines in the x-z plane, by `spline`; an outline ends where a point repeats "
              "its first (for `quadratic` and `cubic`, its second), and the next point starts "
              "another; outlines inside others cut holes (the even-odd rule)",
              "enough for the spline; an unclosed last outline is closed by a straight edge"},
             {"spline", "string", "`linear`",
              "POV-Ray's splines: `linear` joins the points by straight edges, `quadratic` and "
              "`cubic` (Catmull-Rom) pass through them with the first point setting the slope, "
              "`bezier` takes four points a curve",
              "`linear`, `quadratic`, `cubic`, `bezier`"},
             {"bottom", "number", "0", "the height along y the outlines are swept from", "< top"},
             {"top", "number", "1", "the height they are swept to", "> bottom"},
             {"open", "bool", "false",
              "without the caps at bottom and top: walls only, not a solid", ""},
         }},
        {EntityFamily::shape,
         "lathe",
         {
             {"points", "list of `[r, y]`", "required",
              "the curve in the plane of the radius r and the height y, by `spline`, turned round "
              "the y axis; a curve that ends where it starts makes a solid",
              "enough for the spline (a `bezier` curve four points a piece)"},
             {"spline", "string", "`linear`",
              "POV-Ray's splines, as for `prism`: for `quadratic` and `cubic` the first point (and "
              "for `cubic` the last) only sets a slope",
              "`linear`, `quadratic`, `cubic`, `bezier`"},
         }},
        {EntityFamily::shape,
         "disk",
         {
             kCenter,
             {"normal", "vector", "`[0, 1, 0]`", "the front side; normalised", "non-zero"},
             {"radius", "number", "required", "the outer radius", "> 0", kPositive},
             {"inner_radius", "number", "0", "the radius of the hole", "[0, radius)", kNonNegative},
         }},
        {EntityFamily::shape,
         "cylinder",
         {
             {"base", "point", "required", "the centre of one end", ""},
             {"top", "point", "required", "the centre of the other end", "not `base`"},
             kRadius,
             {"capped", "bool", "true",
              "closed by disks at both ends (a solid, usable in CSG); `false` leaves a tube", ""},
         }},
        {EntityFamily::shape,
         "cone",
         {
             {"base", "point", "required", "the centre of the wide end", ""},
             {"base_radius", "number", "required", "its radius", ">= 0", kNonNegative},
             {"apex", "point", "required", "the centre of the other end", "not `base`"},
             {"apex_radius", "number", "0", "its radius; 0 is a pointed cone", ">= 0, not both 0",
              kNonNegative},
             {"capped", "bool", "true", "closed by disks at the ends with a radius", ""},
         }},
        {EntityFamily::shape,
         "torus",
         {
             {"center", "point", "`[0, 0, 0]`", "the centre", ""},
             {"axis", "vector", "`[0, 1, 0]`", "the axis through the hole; normalised", "non-zero"},
             {"major_radius", "number", "required",
              "distance from the axis to the middle of the tube", "> minor_radius", kPositive},
             {"minor_radius", "number", "required", "the radius of the tube", "> 0", kPositive},
         }},
        {EntityFamily::shape,
         "quadric",
         {
             {"coefficients", "list of 10 numbers", "required", "`[A, B, C, D, E, F, G, H, I, J]`",
              "not all second- and first-order ones zero"},
             {"min", "point", "required",
              "the corner of the box the surface is kept inside with the smallest coordinates",
              "`min` < `max` on every axis"},
             kOppositeCorner,
         }},
        {EntityFamily::shape,
         "implicit",
         {
             {"function", "string", "required",
              "the expression: numbers, `x y z`, constants, `+ - * / ^`, `sin cos exp log sqrt abs "
              "min max`, `pi`",
              "see docs/implicit-surfaces.md"},
             {"constants", "map of name to number", "none",
              "named constants the expression may use", ""},
             {"min", "point", "required",
              "the corner of the region searched with the smallest coordinates",
              "`min` < `max` on every axis"},
             kOppositeCorner,
             {"tolerance", "number", "1e-4 × the region's largest extent",
              "resolution of the root search along a ray, scene units", "> 0", kPositive},
             {"max_segments", "integer", "4096",
              "pieces of a ray the search may examine before it gives up (a miss)", "1..16777216",
              Range{1, 1 << 24}},
         }},
        {EntityFamily::shape,
         "julia",
         {
             {"c", "`[r, i, j, k]`", "required", "the constant quaternion", ""},
             {"slice_w", "number", "0", "the fourth coordinate of the 3D slice", ""},
             kPlacedCenter,
             kFractalScale,
             {"iterations", "integer", "10", "iterations of the map per estimate", "1..1000",
              Range{1, 1000}},
             {"epsilon", "number", "1e-3 × scale",
              "a hit is where the distance estimate falls below this (scene units)", "> 0",
              kPositive},
             {"bailout", "number", "4", "escape radius of the iteration",
              ">= the proven escape radius", kPositive},
             {"max_steps", "integer", "512",
              "sphere-tracing steps per ray before it counts as a miss", "1..1048576",
              Range{1, 1 << 20}},
         }},
        {EntityFamily::shape,
         "mandelbulb",
         {
             {"power", "number", "8", "the power of the iteration", "(1, 64]",
              Range{1, 64, true, false}},
             kPlacedCenter,
             kFractalScale,
             {"iterations", "integer", "12", "iterations per estimate", "1..1000", Range{1, 1000}},
             {"epsilon", "number", "1e-3 × scale", "surface threshold (scene units)", "> 0",
              kPositive},
             {"bailout", "number", "2", "escape radius", ">= the proven escape radius", kPositive},
             {"max_steps", "integer", "512", "sphere-tracing steps per ray", "1..1048576",
              Range{1, 1 << 20}},
         }},
        {EntityFamily::shape,
         "mesh",
         {
             {"file", "string", "required", "the model file, relative to the scene file",
              "in the folders the scene may read ([general rules](#general-rules))"},
             {"crease_angle", "number", "none",
              "recompute vertex normals, smoothing across edges whose faces meet at less than this "
              "angle (degrees); without it the file's normals are kept (or faces are flat)",
              "[0, 180]", Range{0, 180}},
         }},
        {EntityFamily::shape, "union", {kOperands}},
        {EntityFamily::shape, "merge", {kOperands}},
        {EntityFamily::shape, "intersection", {kOperands}},
        {EntityFamily::shape, "difference", {kOperands}},
        {EntityFamily::shape, "clip", {kOperands}},
        {EntityFamily::shape,
         "instance",
         {
             {"of", "string", "required", "the name of a definition",
              "a name from `define`, defined earlier"},
         }},
    };
}

}  // namespace glint
