// POV-Ray's blob onto glint's implicit surfaces: each component's field strength (1 - d^2/r^2)^2
// within its radius r of its centre (a sphere) or of its axis (a cylinder, whose ends are round),
// and the surface where the fields add up to the threshold. Written as an expression, the
// interval search of implicit surfaces finds it; components placed by their own transforms.
#include <cmath>

#include "glint/geometry/implicit_surface.h"
#include "glint/math/vector3d.h"
#include "glint/scene/pov/pov_item_reader.h"
#include "glint/scene/pov/pov_polynomial.h"

namespace glint {

namespace {

// An affine function of the scene point (x, y, z): c[0] x + c[1] y + c[2] z + c[3].
std::string affine_text(const std::array<double, 4>& c) {
    return "(" + expression_number(c[0]) + "*x+" + expression_number(c[1]) + "*y+" +
           expression_number(c[2]) + "*z+" + expression_number(c[3]) + ")";
}

// The coordinates of the scene point along the unit axes e of the component's space, from its
// point `origin`: e . (placement^-1 p - origin), one affine function an axis.
std::array<std::string, 3> frame_coordinates(const Transform& placement, const PovVector& origin,
                                             const std::array<Vector3d, 3>& axes) {
    const Matrix4& m = placement.inverse_matrix();
    std::array<std::string, 3> q;
    for (int k = 0; k < 3; ++k) {
        const double e[3] = {axes[k].x, axes[k].y, axes[k].z};
        std::array<double, 4> c{};
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 3; ++i) c[j] += e[i] * (m.m[i][j] - (j == 3 ? origin[i] : 0));
        q[k] = affine_text(c);
    }
    return q;
}

struct BlobComponent {
    bool cylinder = false;
    PovVector a{}, b{};  // the centre; a cylinder's ends
    double radius = 0, strength = 0;
    Transform transform;
};

}  // namespace

Shape PovItemReader::blob(const PovToken& keyword) {
    double threshold = 1;
    std::vector<BlobComponent> components;
    // sphere { <c>, r, [strength] s modifiers } and cylinder { <a>, <b>, r, [strength] s ... }.
    // A radius whose square is positive and finite: the field divides by it.
    const auto radius = [&] {
        const PovToken at = parser_.peek();
        const double r = parser_.finite_float("as the component's radius");
        if (!(r > 0 && r * r > 0 && std::isfinite(r * r)))
            throw parser_.error_at(at, "a blob component's radius must be > 0");
        return r;
    };
    const auto component = [&](const PovToken& kind) {
        parser_.expect("{", "after " + kind.text);
        BlobComponent c;
        c.cylinder = kind.is_word("cylinder");
        c.a = point("as the component's centre");
        parser_.accept(",");
        if (c.cylinder) {
            c.b = point("as the component's other end");
            parser_.accept(",");
        }
        c.radius = radius();
        parser_.accept(",");
        parser_.accept_word("strength");
        c.strength = parser_.finite_float("as the component's strength");
        for (PovToken t = parser_.next(); !t.is_symbol("}"); t = parser_.next()) {
            if (const auto step = transform_step(t)) {
                c.transform = *step * c.transform;
            } else if (t.is_word("texture") || t.is_word("pigment") || t.is_word("finish") ||
                       t.is_word("normal")) {
                parser_.skip_braced(t);
                read_past("a blob component's own texture", "the blob's texture paints it all");
            } else {
                throw unsupported(t, "in a blob component");
            }
        }
        components.push_back(c);
    };
    for (;;) {
        const PovToken& ahead = parser_.peek_item();
        if (ahead.is_word("threshold")) {
            parser_.next();
            const PovToken at = parser_.peek();
            threshold = parser_.finite_float("after threshold");
            if (!(threshold > 0)) throw parser_.error_at(at, "a blob's threshold must be > 0");
        } else if (ahead.is_word("sphere") || ahead.is_word("cylinder")) {
            component(parser_.next());
        } else if (ahead.is_word("component")) {
            // The old form: component strength, radius, <centre>.
            parser_.next();
            BlobComponent c;
            c.strength = parser_.finite_float("as the component's strength");
            parser_.accept(",");
            c.radius = radius();
            parser_.accept(",");
            c.a = point("as the component's centre");
            components.push_back(c);
        } else if (ahead.is_word("sturm") || ahead.is_word("hierarchy")) {
            parser_.next();
            optional_amount();
        } else {
            break;
        }
    }
    // f = threshold - the fields' sum: the blob is where f < 0.
    std::string source = expression_number(threshold);
    Bounds3 region;
    for (const BlobComponent& c : components) {
        const double r2 = c.radius * c.radius;
        // The squared distance to the centre or to the axis, in a frame whose first axis runs
        // along the cylinder's from its end a: each coordinate written once keeps the interval
        // search's enclosures tight.
        std::array<Vector3d, 3> axes{Vector3d{1, 0, 0}, Vector3d{0, 1, 0}, Vector3d{0, 0, 1}};
        double length = 0;
        Bounds3 own{{float(c.a[0] - c.radius), float(c.a[1] - c.radius), float(c.a[2] - c.radius)},
                    {float(c.a[0] + c.radius), float(c.a[1] + c.radius), float(c.a[2] + c.radius)}};
        if (c.cylinder) {
            const Vector3d axis{c.b[0] - c.a[0], c.b[1] - c.a[1], c.b[2] - c.a[2]};
            length = std::sqrt(dot(axis, axis));
            if (length > 0) {
                axes[0] = axis * (1 / length);
                const Vector3d helper =
                    std::abs(axes[0].x) < 0.9 ? Vector3d{1, 0, 0} : Vector3d{0, 1, 0};
                const Vector3d side = cross(axes[0], helper);
                axes[1] = side * (1 / std::sqrt(dot(side, side)));
                axes[2] = cross(axes[0], axes[1]);
                own = merge(own, Point3{float(c.b[0] - c.radius), float(c.b[1] - c.radius),
                                        float(c.b[2] - c.radius)});
                own = merge(own, Point3{float(c.b[0] + c.radius), float(c.b[1] + c.radius),
                                        float(c.b[2] + c.radius)});
            }
        }
        const auto q = frame_coordinates(c.transform, c.a, axes);
        // Along the axis, the distance beyond its ends: max(0, -u, u - length).
        const std::string along =
            length > 0 ? "max(0,max(-" + q[0] + "," + q[0] + "-" + expression_number(length) + "))"
                       : q[0];
        const std::string d2 = "(" + along + "^2+" + q[1] + "^2+" + q[2] + "^2)";
        source += "-" + expression_number(c.strength) + "*max(0,1-" + d2 + "/" +
                  expression_number(r2) + ")^2";
        // Only where some field is positive can the sum reach the threshold.
        if (c.strength > 0) region = merge(region, c.transform(own));
    }
    if (region.is_empty())
        throw parser_.error_at(keyword, "a blob needs a component of positive strength");
    auto compiled = compile_expression(source, {});
    if (auto* error = std::get_if<ExpressionError>(&compiled))
        throw parser_.error_at(keyword, "blob: " + error->message);
    ImplicitSurface surface;
    surface.f = std::make_shared<const Expression>(std::move(std::get<Expression>(compiled)));
    surface.region = loosened(region);
    return surface;
}

}  // namespace glint
