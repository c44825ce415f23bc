// The polygon: validation and precomputation (Newell's normal, the projection), the ray-plane step
// and the two 2D inside tests of the lecture notes.
#include "glint/geometry/polygon.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "glint/sampling/warp.h"

namespace glint {

namespace {

struct Vec3d {
    double x = 0, y = 0, z = 0;
};

Vec3d centroid(std::span<const Point3> vertices) {
    Vec3d c;
    for (const Point3& p : vertices) c.x += p.x, c.y += p.y, c.z += p.z;
    const double count = double(vertices.size());
    return {c.x / count, c.y / count, c.z / count};
}

Vec3d newell_normal_d(std::span<const Point3> vertices) {
    // About the centroid: the sums then do not cancel when the polygon is far from the origin.
    const Vec3d c = centroid(vertices);
    Vec3d n;
    for (std::size_t i = 0, j = vertices.size() - 1; i < vertices.size(); j = i++) {
        const double xi = vertices[i].x - c.x, yi = vertices[i].y - c.y, zi = vertices[i].z - c.z;
        const double xj = vertices[j].x - c.x, yj = vertices[j].y - c.y, zj = vertices[j].z - c.z;
        n.x += (yj - yi) * (zj + zi);
        n.y += (zj - zi) * (xj + xi);
        n.z += (xj - xi) * (yj + yi);
    }
    return n;
}

double length(Vec3d v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

// Distance of p from the plane through c with the (not necessarily unit) normal n.
double plane_distance(Vec3d n, Vec3d c, Point3 p) {
    return std::abs(n.x * (p.x - c.x) + n.y * (p.y - c.y) + n.z * (p.z - c.z)) / length(n);
}

// (a - q) x (b - q) for a and b already relative to q. The two products are separate statements
// so that no compiler fuses them into an FMA: then cross(b, a) is exactly -cross(a, b), and an
// edge shared by two polygons is on the same side of a point for both.
double cross(double ax, double ay, double bx, double by) {
    const double p = ax * by;
    const double q = ay * bx;
    return p - q;
}

// The quadrant of a vertex relative to the point, by its sign pair with zero counting as + (the
// notes' rule): 0 = (+,+), 1 = (-,+), 2 = (-,-), 3 = (+,-), counter-clockwise.
int quadrant(double x, double y) {
    if (x >= 0) return y >= 0 ? 0 : 3;
    return y >= 0 ? 1 : 2;
}

// The notes' table of arc-length changes for a pair of successive sign pairs, in quarter turns
// (pi / 2). kEitherWay (+-pi) means the edge jumps to the opposite quadrant; which way it turns is
// the side of the point it passes, the sign of the cross product.
constexpr int kEitherWay = 2;
constexpr int kQuarterTurns[4][4] = {
    //  to (+,+)     (-,+)       (-,-)       (+,-)
    {0, 1, kEitherWay, -1},  // from (+,+)
    {-1, 0, 1, kEitherWay},  // from (-,+)
    {kEitherWay, -1, 0, 1},  // from (-,-)
    {1, kEitherWay, -1, 0},  // from (+,-)
};

// Which vertex to name when the polygon is not planar, and how far it is from the plane of the
// others: of the vertices farthest from the common plane, the one whose removal leaves the rest
// flattest (the one a user most likely mistyped); among equals (a twisted quad, where any
// vertex will do) the last. Only runs on the error path, so the copies do not matter.
std::pair<std::size_t, double> blame_vertex(std::span<const Point3> vertices, double diagonal2,
                                            std::size_t worst, double worst_distance) {
    const Vec3d n = newell_normal_d(vertices);
    const Vec3d c = centroid(vertices);
    std::vector<std::size_t> order(vertices.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    const std::size_t candidates = std::min<std::size_t>(8, order.size());
    std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(candidates), order.end(),
                      [&](std::size_t a, std::size_t b) {
                          return plane_distance(n, c, vertices[a]) >
                                 plane_distance(n, c, vertices[b]);
                      });
    const double same = 1e-9 * std::sqrt(diagonal2);
    std::pair<std::size_t, double> blamed{worst, worst_distance};
    double best_rest = kInfinity;
    for (std::size_t k = 0; k < candidates; ++k) {
        const std::size_t i = order[k];
        std::vector<Point3> others(vertices.begin(), vertices.end());
        others.erase(others.begin() + std::ptrdiff_t(i));
        const Vec3d n_others = newell_normal_d(others);
        if (!(length(n_others) > 1e-6 * diagonal2)) continue;
        const Vec3d c_others = centroid(others);
        double rest = 0;
        for (const Point3& p : others) rest = std::max(rest, plane_distance(n_others, c_others, p));
        if (rest < best_rest - same || (rest <= best_rest + same && i > blamed.first)) {
            best_rest = std::min(best_rest, rest);
            blamed = {i, plane_distance(n_others, c_others, vertices[i])};
        }
    }
    return blamed;
}

}  // namespace

Vector3 newell_normal(std::span<const Point3> vertices) {
    if (vertices.size() < 3) return {};
    const Vec3d n = newell_normal_d(vertices);
    return {float(n.x), float(n.y), float(n.z)};
}

// Both tests classify the point q* = q - (e, e'), 0 < e' << e infinitesimal, which lies on no
// edge: a vertex coordinate equal to q's is greater than q*'s (the notes' "zero counts as +"),
// and a point exactly on an edge's line is on the side of it that q* is. For an edge a -> b
// through q that side is the sign of e * (b - a).y - e' * (b - a).x, which is the sign of
// (b - a).y on every edge where it matters (those that cross the line y = q.y).
namespace {

// Whether the edge a -> b (relative to q) crosses the line through q towards +x, as q* sees it.
bool crosses(double ax, double ay, double bx, double by) {
    if ((ay >= 0) == (by >= 0)) return false;
    // The edge crosses the line y = q.y. It does so right of q* when both ends are right of it;
    // left when both are left; otherwise when q* is left of the upward edge.
    if (ax >= 0 && bx >= 0) return true;
    if (ax < 0 && bx < 0) return false;
    const double c = by >= 0 ? cross(ax, ay, bx, by) : cross(bx, by, ax, ay);
    return c >= 0;  // 0: q is on the edge, and q* left of it
}

}  // namespace

int crossing_count(std::span<const Point2> outline, double x, double y) {
    if (outline.empty()) return 0;
    int count = 0;
    double ax = outline.back().x - x, ay = outline.back().y - y;
    for (const Point2& b : outline) {
        const double bx = b.x - x, by = b.y - y;
        count += crosses(ax, ay, bx, by);
        ax = bx, ay = by;
    }
    return count;
}

int crossing_count(std::span<const Point2> outline, const EdgeBands& bands, double x, double y) {
    const int band = bands.band_of(y);
    const std::size_t n = outline.size();
    int count = 0;
    for (std::uint32_t k = bands.start[std::size_t(band)]; k < bands.start[std::size_t(band) + 1];
         ++k) {
        const std::size_t i = bands.edges[k];
        const Point2 a = outline[(i + n - 1) % n], b = outline[i];
        count += crosses(a.x - x, a.y - y, b.x - x, b.y - y);
    }
    return count;
}

namespace {

EdgeBands edge_bands(std::span<const Point2> outline, Point2 min, Point2 max) {
    EdgeBands bands;
    const std::size_t n = outline.size();
    if (n < kBandedOutline || !(max.y > min.y)) return bands;
    const auto count = int(std::clamp<std::size_t>(n / 4, 4, 64));
    bands.v_min = min.y;
    bands.scale = count / (double(max.y) - min.y);
    bands.start.assign(std::size_t(count) + 1, 0);
    // Count, then fill: an edge is listed in every band its closed v-range reaches, found with
    // band_of itself, so that the band of any v in the range lists it.
    const auto reach = [&](std::size_t i, auto&& visit) {
        const double ay = outline[(i + n - 1) % n].y, by = outline[i].y;
        for (int b = bands.band_of(std::min(ay, by)); b <= bands.band_of(std::max(ay, by)); ++b)
            visit(std::size_t(b));
    };
    for (std::size_t i = 0; i < n; ++i) reach(i, [&](std::size_t b) { ++bands.start[b + 1]; });
    for (std::size_t b = 0; b < std::size_t(count); ++b) bands.start[b + 1] += bands.start[b];
    bands.edges.resize(bands.start.back());
    std::vector<std::uint32_t> next(bands.start.begin(), bands.start.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
        reach(i, [&](std::size_t b) { bands.edges[next[b]++] = std::uint32_t(i); });
    return bands;
}

}  // namespace

int winding_number(std::span<const Point2> outline, double x, double y) {
    if (outline.empty()) return 0;
    int quarter_turns = 0;
    double ax = outline.back().x - x, ay = outline.back().y - y;
    int from = quadrant(ax, ay);
    for (const Point2& b : outline) {
        const double bx = b.x - x, by = b.y - y;
        const int to = quadrant(bx, by);
        int turn = kQuarterTurns[from][to];
        if (turn == kEitherWay) {
            // Counter-clockwise about q* (+pi) when q* is left of a -> b. On the edge (c == 0),
            // q* is left of it when the edge runs upwards.
            const double c = cross(ax, ay, bx, by);
            turn = (c > 0 || (c == 0 && by >= 0)) ? 2 : -2;
        }
        quarter_turns += turn;
        ax = bx, ay = by, from = to;
    }
    // A closed walk around the quadrants returns to its start: the total is a multiple of 2 pi.
    return quarter_turns / 4;
}

bool inside_outline(std::span<const Point2> outline, double x, double y, InsideTest test) {
    if (test == InsideTest::angle_sum) return winding_number(outline, x, y) != 0;
    return crossing_count(outline, x, y) % 2 == 1;
}

std::optional<PolygonProblem> polygon_problem(std::span<const Point3> vertices) {
    if (vertices.size() < 3) {
        return PolygonProblem{
            "a polygon needs at least 3 vertices, got " + std::to_string(vertices.size()), {}};
    }
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        if (!is_finite(vertices[i])) {
            return PolygonProblem{"polygon vertex " + std::to_string(i + 1) + " is not finite", i};
        }
    }
    Bounds3 box;
    for (const Point3& p : vertices) box = merge(box, p);
    const double dx = double(box.max.x) - box.min.x, dy = double(box.max.y) - box.min.y,
                 dz = double(box.max.z) - box.min.z;
    const double diagonal2 = dx * dx + dy * dy + dz * dz;

    // |Newell| is twice the area. Relative to the size squared, it measures how far the outline
    // is from a line; below float precision the polygon has no usable normal (the same bound as
    // the YAML loader's triangles).
    const Vec3d n = newell_normal_d(vertices);
    const double area2 = length(n);
    if (!(area2 > 1e-6 * diagonal2)) {
        return PolygonProblem{
            "polygon has no area: its vertices are collinear or coincide (or its loops wind "
            "both ways and cancel)",
            {}};
    }
    if (vertices.size() == 3) return std::nullopt;  // three points are always coplanar

    const Vec3d c = centroid(vertices);
    std::size_t worst = 0;
    double worst_distance = 0;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const double d = plane_distance(n, c, vertices[i]);
        if (d > worst_distance) worst = i, worst_distance = d;
    }
    const double tolerance = kPolygonPlanarityTolerance * std::sqrt(diagonal2);
    if (worst_distance <= tolerance) return std::nullopt;

    const auto [culprit, off] = blame_vertex(vertices, diagonal2, worst, worst_distance);
    char distance[32];
    std::snprintf(distance, sizeof distance, "%.3g", off);
    return PolygonProblem{"polygon vertices are not coplanar: vertex " +
                              std::to_string(culprit + 1) + " is " + distance +
                              " off the plane of the others",
                          culprit};
}

std::vector<Point3> bridged_outline(std::span<const std::vector<Point3>> outlines) {
    std::vector<Point3> joined;
    if (outlines.empty()) return joined;
    joined = outlines[0];
    for (std::size_t i = 1; i < outlines.size(); ++i) {
        if (outlines[i].empty()) continue;
        joined.push_back(outlines[0].front());  // closes the first outline, starts the bridge
        joined.insert(joined.end(), outlines[i].begin(), outlines[i].end());
        joined.push_back(outlines[i].front());  // closes this one; the next edge bridges back
    }
    return joined;
}

namespace {

bool is_parallelogram(const std::vector<Point3>& v) {
    if (v.size() != 4) return false;
    const Vector3 gap = (v[0] - v[1]) + (v[2] - v[3]);  // zero when v0 + v2 = v1 + v3
    return length(gap) <= 1e-5f * (length(v[1] - v[0]) + length(v[3] - v[0]));
}

}  // namespace

std::variant<Polygon, std::string> make_polygon(std::vector<Point3> vertices, InsideTest test) {
    if (auto problem = polygon_problem(vertices)) return std::move(problem->message);
    Polygon polygon;
    const Vec3d n = newell_normal_d(vertices);
    const double l = length(n);
    polygon.normal = {float(n.x / l), float(n.y / l), float(n.z / l)};
    polygon.inside_test = test;
    const Vec3d c = centroid(vertices);
    polygon.plane_offset = float((n.x * c.x + n.y * c.y + n.z * c.z) / l);

    const double a[3] = {std::abs(n.x), std::abs(n.y), std::abs(n.z)};
    const int dominant = a[0] >= a[1] && a[0] >= a[2] ? 0 : (a[1] >= a[2] ? 1 : 2);
    polygon.axis_u = std::uint8_t((dominant + 1) % 3);
    polygon.axis_v = std::uint8_t((dominant + 2) % 3);
    PolygonOutline outline;
    outline.projected.reserve(vertices.size());
    outline.projected_min = {kInfinity, kInfinity};
    outline.projected_max = {-kInfinity, -kInfinity};
    for (const Point3& p : vertices) {
        const Point2 q{p[polygon.axis_u], p[polygon.axis_v]};
        outline.projected.push_back(q);
        outline.projected_min = {std::min(outline.projected_min.x, q.x),
                                 std::min(outline.projected_min.y, q.y)};
        outline.projected_max = {std::max(outline.projected_max.x, q.x),
                                 std::max(outline.projected_max.y, q.y)};
    }
    outline.bands = edge_bands(outline.projected, outline.projected_min, outline.projected_max);
    polygon.outline = std::make_shared<const PolygonOutline>(std::move(outline));
    if (is_parallelogram(vertices))
        polygon.parallelogram_pdf =
            1 / length(cross(vertices[1] - vertices[0], vertices[3] - vertices[0]));
    polygon.vertices = std::move(vertices);
    return polygon;
}

Bounds3 Polygon::bounds() const {
    Bounds3 box;
    for (const Point3& p : vertices) box = merge(box, p);
    return box;
}

std::optional<ShapeHit> Polygon::intersect(const Ray& ray, Interval t_range) const {
    // In double: the hit point feeds the inside test, whose edge cases are exact comparisons.
    const double n_dot_r = double(normal.x) * ray.direction.x + double(normal.y) * ray.direction.y +
                           double(normal.z) * ray.direction.z;
    if (n_dot_r == 0) return std::nullopt;  // parallel to the plane
    const double n_dot_o = double(normal.x) * ray.origin.x + double(normal.y) * ray.origin.y +
                           double(normal.z) * ray.origin.z;
    const double t = (plane_offset - n_dot_o) / n_dot_r;
    if (!std::isfinite(t) || !t_range.contains(float(t))) return std::nullopt;
    const double u = ray.origin[axis_u] + t * ray.direction[axis_u];
    const double v = ray.origin[axis_v] + t * ray.direction[axis_v];
    // Outside the bounds is outside; a point on them may still be inside (see crossing_count).
    const PolygonOutline& o = *outline;
    if (!(u >= o.projected_min.x && u <= o.projected_max.x && v >= o.projected_min.y &&
          v <= o.projected_max.y)) {
        return std::nullopt;
    }
    const bool inside = inside_test == InsideTest::even_odd && !o.bands.start.empty()
                            ? crossing_count(o.projected, o.bands, u, v) % 2 == 1
                            : inside_outline(o.projected, u, v, inside_test);
    if (!inside) return std::nullopt;
    return ShapeHit{float(t)};
}

SurfacePoint Polygon::surface_at(const Ray& ray, const ShapeHit& hit) const {
    SurfacePoint sp;
    const Point3 p = ray.at(hit.t);
    // Remove the error of t along the normal so the point lies on the plane.
    sp.p = p - to_vector(normal) * (dot(normal, to_vector(p)) - plane_offset);
    sp.normal = sp.shading_normal = normal;
    Vector3 s, t;
    orthonormal_basis(to_vector(normal), s, t);
    sp.uv = {dot(sp.p - vertices[0], s), dot(sp.p - vertices[0], t)};
    sp.dpdu = s;
    sp.dpdv = t;
    sp.has_derivatives = true;
    return sp;
}

bool is_convex(const Polygon& polygon) {
    const auto& v = polygon.vertices;
    const std::size_t n = v.size();
    bool left = false, right = false;
    for (std::size_t i = 0; i < n; ++i) {
        const float turn = dot(polygon.normal, cross(v[(i + 1) % n] - v[i], v[(i + 2) % n] - v[i]));
        left |= turn > 0;
        right |= turn < 0;
    }
    return !(left && right);
}

float Polygon::area() const { return 0.5f * length(newell_normal(vertices)); }

namespace {

// Twice the area of the fan's triangle (v0, v[i], v[i + 1]).
float fan_double_area(const std::vector<Point3>& v, std::size_t i) {
    return length(cross(v[i] - v[0], v[i + 1] - v[0]));
}

}  // namespace

SurfaceSample Polygon::sample(Point2 u) const {
    const auto& v = vertices;
    if (parallelogram_pdf > 0)
        return {v[0] + (v[1] - v[0]) * u.x + (v[3] - v[0]) * u.y, normal, parallelogram_pdf};
    // A fan triangle picked by its area with u.x, which is then stretched back over [0, 1).
    float total = 0;
    for (std::size_t i = 1; i + 1 < v.size(); ++i) total += fan_double_area(v, i);
    // Collinear runs of vertices make empty fans, which are never picked.
    float x = u.x * total, a = 0;
    std::size_t i = 0;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
        const float area_k = fan_double_area(v, k);
        if (!(area_k > 0)) continue;
        i = k;
        a = area_k;
        if (x < a) break;
        x -= a;
    }
    const Point2 b = sample_uniform_triangle({std::min(x / a, 0x1.fffffep-1f), u.y});
    return {v[0] + (v[i] - v[0]) * b.y + (v[i + 1] - v[0]) * (1 - b.x - b.y), normal, 2 / total};
}

}  // namespace glint
