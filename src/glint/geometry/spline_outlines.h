// POV-Ray's four splines through a list of 2D points, as the closed outlines of a prism:
//   linear     straight edges from point to point;
//   quadratic  from point i to i + 1 with the slope of the line from i - 1 to i + 1;
//   cubic      Catmull-Rom: from i to i + 1 with the slopes (p[i+1] - p[i-1]) / 2 and
//              (p[i+2] - p[i]) / 2;
//   bezier     each four points a Bezier curve, the first and fourth on it.
// An outline closes where a point repeats the outline's first point on the curve (for the
// linear and Bezier splines, the first point given; for the quadratic and cubic ones, the
// second, as the first only sets a slope); the next point starts the next outline.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "glint/geometry/prism.h"

namespace glint {

enum class SplineKind { linear, quadratic, cubic, bezier };

// "linear", "quadratic", "cubic" or "bezier"; nothing for another name.
std::optional<SplineKind> spline_kind(std::string_view name);

struct SplineOutlines {
    std::vector<Outline> outlines;
    // Outlines whose last point did not return to their first, closed by a straight edge.
    int closed_by_line = 0;
};

// The outlines, each curve flattened to within 1e-4 of the points' extent. An error (naming the
// point count) when there are too few points for the spline.
std::variant<SplineOutlines, std::string> spline_outlines(SplineKind kind,
                                                          std::span<const Point2> points);

// The spline through the points as one open curve, as POV-Ray's lathe takes it: every segment
// in turn (for the quadratic and cubic splines, the first and, for cubic, the last point only
// set slopes; the Bezier spline takes groups of four). An error when the count does not fit.
std::variant<Outline, std::string> spline_curve(SplineKind kind, std::span<const Point2> points);

// POV-Ray's surface of revolution (sor) as a lathe's curve: between the second point and the
// next-to-last, r^2 is a cubic in y on each segment, matching r^2 at both ends and, at each,
// the slope of r^2 across the neighbouring points (the first and last points only set slopes).
// The curve is cut into 32 pieces a segment, keeping its normals; unless open, flat caps close
// it at the bottom and the top (down to the axis), making a solid. An error when there are
// fewer than 4 points or the heights do not rise.
std::variant<Outline, std::string> sor_curve(std::span<const Point2> points, bool open);

}  // namespace glint
