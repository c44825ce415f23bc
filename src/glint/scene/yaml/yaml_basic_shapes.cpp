// Parsers of the flat and simple shapes: sphere, plane, triangle, box, polygon, prism, lathe. Each
// checks what makes its shape degenerate, so that the renderer never sees one.
#include <algorithm>
#include <cmath>

#include "glint/geometry/spline_outlines.h"
#include "glint/scene/yaml/yaml_shape_parsers.h"

namespace glint {

Shape parse_sphere(const MapReader& object, ShapeReader&) {
    return Sphere{object.point("center"), object.number("radius")};
}

Shape parse_plane(const MapReader& object, ShapeReader&) {
    return Plane{object.point("point"), Normal3(object.direction("normal"))};
}

Shape parse_triangle(const MapReader& object, ShapeReader&) {
    const YamlSource& source = object.source();
    Triangle triangle;
    const MapEntry& vertices = object.require("vertices");
    const auto points =
        read_sequence(source, vertices.value, object.field("vertices"), "a list of 3 points", 3);
    for (std::size_t i = 0; i < 3; ++i) {
        triangle.vertices[i] =
            read_point(source, points[i], {object.what(), "vertices[" + std::to_string(i) + "]"});
    }
    if (const MapEntry* uvs = object.find("uvs")) {
        const auto pairs =
            read_sequence(source, uvs->value, object.field("uvs"), "a list of 3 [u, v] pairs", 3);
        for (std::size_t i = 0; i < 3; ++i) {
            triangle.uvs[i] =
                read_point2(source, pairs[i], {object.what(), "uvs[" + std::to_string(i) + "]"});
        }
    }
    // Twice the area over the longest edge squared is the height relative to that edge: a
    // scale-free measure of how far from a line the vertices are. Below float precision, a
    // triangle has no usable normal.
    const auto& v = triangle.vertices;
    const float longest = std::max(
        {length_squared(v[1] - v[0]), length_squared(v[2] - v[1]), length_squared(v[0] - v[2])});
    const float area2 = double_area(triangle);
    if (!std::isfinite(area2) || !std::isfinite(longest)) {
        throw source.error_at(vertices.value, "triangle is too large: its area overflows a float");
    }
    if (!(area2 > 1e-6f * longest)) {
        throw source.error_at(vertices.value,
                              "triangle vertices are collinear, so the triangle has no area");
    }
    return triangle;
}

Shape parse_box(const MapReader& object, ShapeReader&) {
    const Box box{object.point("min"), object.point("max")};
    constexpr const char* kAxes[] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        if (box.min[axis] < box.max[axis]) continue;
        const std::string a = kAxes[axis];
        throw object.source().error_at(object.require("min").value,
                                       "box min must be less than max on every axis, got min." + a +
                                           " = " + format_number(box.min[axis]) + " and max." + a +
                                           " = " + format_number(box.max[axis]));
    }
    return box;
}

namespace {
constexpr std::string_view kInsideTests[] = {"angle_sum", "even_odd"};
}  // namespace

Shape parse_polygon(const MapReader& object, ShapeReader&) {
    const YamlSource& source = object.source();
    const MapEntry& entry = object.require("vertices");
    const auto items =
        read_sequence(source, entry.value, object.field("vertices"), "a list of at least 3 points");
    std::vector<Point3> vertices;
    vertices.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        vertices.push_back(
            read_point(source, items[i], {object.what(), "vertices[" + std::to_string(i) + "]"}));
    }
    if (const auto problem = polygon_problem(vertices)) {
        const bool at_vertex = problem->vertex && *problem->vertex < items.size();
        throw source.error_at(at_vertex ? items[*problem->vertex] : entry.value, problem->message);
    }
    const InsideTest test = object.choice("inside_test", kInsideTests, "inside test",
                                          "inside tests", "even_odd") == "angle_sum"
                                ? InsideTest::angle_sum
                                : InsideTest::even_odd;
    return std::get<Polygon>(make_polygon(std::move(vertices), test));
}

constexpr std::string_view kSplines[] = {"bezier", "cubic", "linear", "quadratic"};

namespace {

// The points of a prism's or a lathe's spline, and the spline.
std::pair<std::vector<Point2>, SplineKind> spline_points(const MapReader& object,
                                                         std::string_view expected) {
    const YamlSource& source = object.source();
    const MapEntry& entry = object.require("points");
    const auto items = read_sequence(source, entry.value, object.field("points"), expected);
    std::vector<Point2> points;
    points.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        points.push_back(
            read_point2(source, items[i], {object.what(), "points[" + std::to_string(i) + "]"}));
    }
    return {points, *spline_kind(object.choice("spline", kSplines, "spline", "splines", "linear"))};
}

}  // namespace

Shape parse_lathe(const MapReader& object, ShapeReader&) {
    const auto [points, kind] = spline_points(object, "a list of [r, y] points");
    auto curve = spline_curve(kind, points);
    if (const auto* problem = std::get_if<std::string>(&curve)) {
        throw object.source().error_at(object.require("points").value, "lathe points: " + *problem);
    }
    auto lathe = make_lathe(std::get<Outline>(curve));
    if (const auto* problem = std::get_if<std::string>(&lathe)) {
        throw object.source().error_at(object.node(), *problem);
    }
    return std::get<Lathe>(std::move(lathe));
}

Shape parse_prism(const MapReader& object, ShapeReader&) {
    const YamlSource& source = object.source();
    const MapEntry& entry = object.require("points");
    const auto [points, kind] = spline_points(object, "a list of [x, z] points");
    auto outlines = spline_outlines(kind, points);
    if (const auto* problem = std::get_if<std::string>(&outlines)) {
        throw source.error_at(entry.value, "prism points: " + *problem);
    }
    auto prism = make_prism(std::get<SplineOutlines>(outlines).outlines, object.number("bottom"),
                            object.number("top"), object.boolean("open", false));
    if (const auto* problem = std::get_if<std::string>(&prism)) {
        throw source.error_at(object.node(), *problem);
    }
    return std::get<Prism>(std::move(prism));
}

}  // namespace glint
