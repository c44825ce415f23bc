// A planar polygon of n >= 3 vertices, convex, concave or self-intersecting, with the two inside
// tests of the lecture notes: the even-odd crossing count and the arc-length (angle-sum) method.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "glint/geometry/surface_point.h"
#include "glint/geometry/surface_sample.h"
#include "glint/math/bounds.h"
#include "glint/math/interval.h"
#include "glint/math/ray.h"

namespace glint {

// Which points of a self-intersecting outline are inside. On simple polygons the two agree.
enum class InsideTest {
    // Inside when a ray from the point crosses the outline an odd number of times (the German
    // notes' "even/odd-Regel"). A pentagram's centre pentagon is outside.
    even_odd,
    // Inside when the arcs the edges sweep around the point sum to a non-zero multiple of 2 pi,
    // i.e. the winding number is not zero (the Chinese notes' 弧长法 with its quadrant
    // sign-pair table). A pentagram's centre pentagon is inside: it is wound twice.
    angle_sum,
};

// For outlines of many edges: which edges reach each horizontal band of the outline's bounds.
// Only an edge whose v-range holds the point's v can cross the horizontal line through it, so the
// crossing count over the edges of the point's band is the count over all of them, exactly.
struct EdgeBands {
    double v_min = 0, scale = 0;       // band of v: floor((v - v_min) * scale), clamped
    std::vector<std::uint32_t> start;  // bands + 1 offsets into edges; empty: no bands
    std::vector<std::uint32_t> edges;  // edge i runs from projected[i - 1] (cyclically) to [i]

    int band_of(double v) const {
        const double f = (v - v_min) * scale;
        const int last = int(start.size()) - 2;
        if (!(f > 0)) return 0;  // NaN too
        return f < double(last) ? int(f) : last;
    }
};

// Outlines of at least this many vertices get EdgeBands (the gears' 144-gons).
inline constexpr std::size_t kBandedOutline = 16;

// The outline projected along the normal's dominant axis, for the 2D inside test: built once by
// make_polygon and shared by the polygon's copies, so that a Shape stays small.
struct PolygonOutline {
    std::vector<Point2> projected;        // (vertices[i][axis_u], vertices[i][axis_v])
    Point2 projected_min, projected_max;  // bounds of `projected`, for a quick rejection
    EdgeBands bands;                      // of `projected`, for large outlines
};

struct Polygon {
    // Build with make_polygon(); the fields after inside_test are precomputed for intersection.
    std::vector<Point3> vertices;  // as given, in order; the last joins the first
    // Unit, from Newell's method: right-handed with the vertex order (counter-clockwise seen from
    // the side it points to). One-sided NFF polygons are seen from this side.
    Normal3 normal{0, 0, 1};
    InsideTest inside_test = InsideTest::even_odd;

    // The plane is dot(normal, p) = plane_offset (the notes' N.P = -D).
    float plane_offset = 0;
    // The 2D test runs on the vertices projected along the normal's dominant axis, keeping axes
    // axis_u and axis_v in cyclic order: projecting scales areas by |normal[dominant]| >= 1/sqrt 3
    // and never folds the outline.
    std::uint8_t axis_u = 0, axis_v = 1;
    std::shared_ptr<const PolygonOutline> outline;  // never null once made
    // When the vertices make a parallelogram, which sample() maps u onto bilinearly, one over
    // its area; else 0.
    float parallelogram_pdf = 0;

    Bounds3 bounds() const;
    // The notes' plane step t = -(D + N.P0) / (N.R), then the inside test on the projected hit
    // point. Two-sided; allocates nothing.
    std::optional<ShapeHit> intersect(const Ray& ray, Interval t_range) const;
    // uv: the point's position in the plane, in scene units, along two perpendicular in-plane
    // axes (orthonormal_basis of the normal), measured from vertices[0].
    SurfacePoint surface_at(const Ray& ray, const ShapeHit& hit) const;
    // Its area, half the length of Newell's vector area; and, for a convex polygon only, a point
    // drawn uniformly by area from u in [0,1)^2, which lets it light a scene: a parallelogram
    // (a rectangle light) bilinearly, which keeps a stratified pattern's strata, any other by
    // its fan of triangles from vertex 0.
    float area() const;
    SurfaceSample sample(Point2 u) const;
};

// Whether the polygon turns the same way at every vertex (collinear runs allowed): what
// Polygon::sample needs.
bool is_convex(const Polygon& polygon);

// Vertices may stray from their common plane by this fraction of the polygon's bounding-box
// diagonal (rounding in files that print 3 to 6 digits), as measured from the plane of the others.
inline constexpr double kPolygonPlanarityTolerance = 1e-3;

// What is wrong with a polygon's vertices, for an error message.
struct PolygonProblem {
    // Says what is wrong, with vertices numbered from 1 ("polygon vertices are not coplanar:
    // vertex 4 is 0.2 off the plane of the others").
    std::string message;
    std::optional<std::size_t> vertex;  // 0-based index of the vertex it names, if one
};

// Nothing when the vertices make a usable polygon: at least 3, all finite, a non-zero area, and
// planar within kPolygonPlanarityTolerance. Allocates only when there is a problem.
std::optional<PolygonProblem> polygon_problem(std::span<const Point3> vertices);

// Checks (polygon_problem) and precomputes. Never throws; a bad polygon gives the message.
std::variant<Polygon, std::string> make_polygon(std::vector<Point3> vertices,
                                                InsideTest test = InsideTest::even_odd);

// Outlines with holes (or several outlines) as the one outline a Polygon has: the first outline,
// then each other one, reached from the first's first vertex by a bridge and left back along it.
// A bridge is an edge walked once each way, so it crosses a ray from any point twice or not at
// all and winds zero round it: each inside test counts as over the separate outlines. Holes
// need the even-odd test, or to wind against their outline for the angle-sum test.
std::vector<Point3> bridged_outline(std::span<const std::vector<Point3>> outlines);

// Newell's method (Sutherland, Sproull and Schumacker 1974; Tampieri, Graphics Gems III): the
// sum over the edges of (y_i - y_j)(z_i + z_j), ... is twice the vector area, exact for any
// planar outline and a robust average normal for a nearly planar one. Not normalised;
// computed in double about the vertices' centroid.
Vector3 newell_normal(std::span<const Point3> vertices);

// The 2D inside tests on a closed outline, for a point (x, y). Points exactly on an edge or a
// vertex are classified as the point an infinitesimal step towards -x and -y would be (the
// notes' rule "a zero coordinate counts as +" applied to the vertices relative to the point), by
// both tests alike. So the two agree on every simple outline, and of polygons that tile the plane
// each point belongs to exactly one.
//
// The number of edges a ray from the point towards +x crosses (Haines, "Point in Polygon
// Strategies", Graphics Gems IV, the crossings test).
int crossing_count(std::span<const Point2> outline, double x, double y);
// The same count over the edges of the band that holds y: equal to crossing_count's.
int crossing_count(std::span<const Point2> outline, const EdgeBands& bands, double x, double y);
// The winding number by the arc-length method: each edge turns the vertex-minus-point vector
// through the quadrants of the notes' sign-pair table (0, +-pi/2, or +-pi decided by the edge's
// side of the point); the total is 2 pi times the winding number.
int winding_number(std::span<const Point2> outline, double x, double y);
bool inside_outline(std::span<const Point2> outline, double x, double y, InsideTest test);

}  // namespace glint
