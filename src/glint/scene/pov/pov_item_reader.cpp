// POV-Ray's objects and their modifiers, textures, pigments, finishes and interiors. As in
// POV-Ray, the commas between an item's values may be left out: `box { <0, 0, 0> <1, 1, 1> }`.
#include "glint/scene/pov/pov_item_reader.h"

#include <algorithm>
#include <cmath>

#include "glint/geometry/expression.h"
#include "glint/geometry/polygon.h"
#include "glint/math/interval.h"
#include "glint/scene/pov/pov_polynomial.h"
#include "glint/scene/quote.h"

namespace glint {

namespace {

// The surfaces of a polynomial, unbounded but for their bounded_by or clipped_by objects.
bool is_polynomial(const std::string& keyword) {
    return keyword == "quadric" || keyword == "cubic" || keyword == "quartic" || keyword == "poly";
}

bool is_shape(const std::string& keyword) {
    return keyword == "sphere" || keyword == "box" || keyword == "plane" || keyword == "cylinder" ||
           keyword == "cone" || keyword == "torus" || keyword == "disc" || keyword == "triangle" ||
           keyword == "smooth_triangle" || keyword == "polygon" || keyword == "mesh" ||
           keyword == "mesh2" || keyword == "height_field" || keyword == "superellipsoid" ||
           keyword == "blob" || keyword == "prism" || keyword == "lathe" || keyword == "sor" ||
           keyword == "text" || keyword == "julia_fractal" || keyword == "isosurface" ||
           keyword == "sphere_sweep" || is_polynomial(keyword);
}

// POV-Ray's objects that glint does not read yet: read past, so that only using one stops the
// scene (include files declare many).
bool is_unread_object(const std::string& keyword) {
    static const std::string_view kUnread[] = {"bicubic_patch", "lemon", "ovus", "parametric",
                                               "polynomial"};
    return std::find(std::begin(kUnread), std::end(kUnread), keyword) != std::end(kUnread);
}

// Whether the pigment lets nothing through anywhere: no filter or transmit in any colour.
bool opaque(const PovPigment& p) {
    if (p.kind == PovPigment::Kind::unsupported) return false;
    const auto clear = [](const PovVector& c) { return c[3] == 0 && c[4] == 0; };
    if (p.kind != PovPigment::Kind::pattern) return clear(p.color);
    return std::all_of(p.map.stops.begin(), p.map.stops.end(), [&](const PovColorStop& s) {
        return s.pigment ? opaque(*s.pigment) : clear(s.color);
    });
}

// The texture without the layers that an opaque one above them hides.
PovTexture without_hidden(PovTexture t) {
    for (std::size_t i = t.above.size(); i-- > 0;) {
        if (!opaque(t.above[i].pigment)) continue;
        PovTexture top = std::move(t.above[i]);
        top.above.assign(std::make_move_iterator(t.above.begin() + std::ptrdiff_t(i) + 1),
                         std::make_move_iterator(t.above.end()));
        return top;
    }
    return t;
}

bool is_csg(const std::string& keyword) {
    return keyword == "union" || keyword == "merge" || keyword == "intersection" ||
           keyword == "difference";
}

template <typename S>
Shape checked_shape(const PovParser& parser, const PovToken& at, S shape) {
    if (const std::string problem = describe_problem(shape); !problem.empty())
        throw parser.error_at(at, problem);
    return shape;
}

}  // namespace

Point3 to_point(const PovVector& v) { return {float(v[0]), float(v[1]), float(v[2])}; }
Vector3 to_vector(const PovVector& v) { return {float(v[0]), float(v[1]), float(v[2])}; }

PovItemReader::PovItemReader(PovParser& parser, std::vector<std::string>& warnings)
    : parser_(parser), warnings_(warnings) {}

PovTexture PovItemReader::laid_over(PovTexture below, PovTexture layer, const PovToken& at) {
    // Each layer costs every hit on the object: a texture laid over itself in a loop must not
    // grow without end.
    if (below.above.size() + layer.above.size() + 2 > kMaxTextureLayers)
        throw parser_.error_at(
            at, "a texture has more than " + std::to_string(kMaxTextureLayers) + " layers");
    std::vector<PovTexture> upper = std::move(layer.above);
    layer.above.clear();
    below.above.push_back(std::move(layer));
    for (PovTexture& l : upper) below.above.push_back(std::move(l));
    return without_hidden(std::move(below));
}

bool PovItemReader::starts_object(const std::string& keyword) {
    return is_shape(keyword) || is_csg(keyword) || is_unread_object(keyword) ||
           keyword == "object" || keyword == "light_source";
}

SceneError PovItemReader::unsupported(const PovToken& token, std::string_view where) {
    return parser_.error_at(token,
                            describe(token) + " is not supported " + std::string(where) + " yet",
                            {kSeeCompatibility});
}

double PovItemReader::optional_amount() { return amount_if_given().value_or(1); }

bool PovItemReader::number_next() {
    const PovToken& ahead = parser_.peek_item();
    bool given = ahead.kind == PovTokenKind::number || ahead.is_symbol("(") ||
                 ahead.is_symbol("-") || ahead.is_symbol("+");
    if (ahead.kind == PovTokenKind::identifier) {
        static const std::string_view kWords[] = {"on", "off", "true", "false", "yes", "no"};
        const PovValue* declared = parser_.symbols().find(ahead.text);
        given = std::find(std::begin(kWords), std::end(kWords), ahead.text) != std::end(kWords) ||
                (declared && std::holds_alternative<double>(*declared));
    }
    return given;
}

std::optional<double> PovItemReader::amount_if_given() {
    if (!number_next()) return std::nullopt;
    return parser_.finite_float("after the keyword");
}

void PovItemReader::read_past(const std::string& what, const std::string& instead) {
    if (!read_past_.insert(what).second) return;
    warnings_.push_back(what + " is read past: " + instead);
}

void PovItemReader::read_default(const PovToken& directive) {
    parser_.expect("{", "after #default");
    PovTexture t = *default_texture_;
    for (PovToken token = parser_.next(); !token.is_symbol("}"); token = parser_.next()) {
        if (token.is_word("texture"))
            t = texture(t);
        else if (token.is_word("pigment"))
            t.pigment = pigment(t.pigment);
        else if (token.is_word("finish"))
            t.finish = finish(t.finish);
        else if (token.is_word("normal"))
            t.normal = normal(t.normal);
        else if (token.kind == PovTokenKind::end)
            throw parser_.error_at(directive, "#default { is not closed by }");
        else
            throw unsupported(token, "in #default");
    }
    default_texture_ = std::make_shared<const PovTexture>(t);
}

std::optional<PovItem> PovItemReader::read(const PovToken& keyword) {
    const std::string& w = keyword.text;
    // #default, or the same block written as a statement: default { ... }.
    if (w == "default") {
        read_default(keyword);
        return PovUnread{"#default", keyword.at};
    }
    if (w == "color_map" || w == "colour_map") return color_map(keyword);
    if (w == "material") return material({});
    if (w == "pigment_map" || w == "normal_map" || w == "texture_map" || w == "slope_map" ||
        w == "density_map" || w == "material_map") {
        parser_.skip_braced(keyword);
        return PovUnread{w, keyword.at};
    }
    if (w == "normal") return normal(default_texture_->normal);
    if (w == "function") return function(keyword);
    if (starts_object(w)) return object(keyword);
    if (w == "camera") return camera(keyword);
    if (w == "sky_sphere") return sky_sphere(keyword);
    if (w == "texture") {
        PovTexture layered = texture(*default_texture_);
        // Layers over it (`texture { } texture { }`). A lookahead past a complete value: a
        // directive after it must not run before the value is declared.
        while (parser_.peek().is_word("texture")) {
            const PovToken next = parser_.next();
            layered = laid_over(std::move(layered), texture(*default_texture_), next);
        }
        return layered;
    }
    if (w == "pigment") return pigment(default_texture_->pigment);
    if (w == "finish") return finish(default_texture_->finish);
    if (w == "interior") return interior({});
    if (w == "media") return media(keyword);
    if (w == "density") return density();
    if (w == "transform") {
        parser_.expect("{", "after transform");
        Transform t;
        for (PovToken step = parser_.next(); !step.is_symbol("}"); step = parser_.next()) {
            if (step.is_word("inverse")) {
                t = t.inverse();
                continue;
            }
            if (const auto named = declared<Transform>(step)) {  // transform { Declared }
                t = *named * t;
                continue;
            }
            const auto s = transform_step(step);
            if (!s)
                throw parser_.error_at(
                    step, "expected a transform in transform { }, got " + describe(step));
            t = *s * t;
        }
        return t;
    }
    return std::nullopt;
}

std::optional<Transform> PovItemReader::transform_step(const PovToken& keyword) {
    const std::string& w = keyword.text;
    if (w == "translate")
        return Transform::translate(to_vector(parser_.finite_vector("after translate")));
    if (w == "rotate") {
        // About x, then y, then z, in degrees (as POV-Ray's rotate).
        const PovVector a = parser_.finite_vector("after rotate");
        return Transform::rotate({0, 0, 1}, float(a[2])) *
               Transform::rotate({0, 1, 0}, float(a[1])) *
               Transform::rotate({1, 0, 0}, float(a[0]));
    }
    if (w == "scale") {
        const PovVector s = parser_.finite_vector("after scale");
        // As floats: a factor too small for one is zero too.
        if (float(s[0]) == 0 || float(s[1]) == 0 || float(s[2]) == 0)
            throw parser_.error_at(
                keyword, "scale by zero flattens the object: every factor must be non-zero");
        return Transform::scale(float(s[0]), float(s[1]), float(s[2]));
    }
    if (w == "matrix") {
        // <a, b, c,  d, e, f,  g, h, i,  j, k, l>: rows of a 4x3 matrix that points multiply
        // from the left, the last row the translation.
        const std::vector<double> v = parser_.finite_list("of matrix", 12);
        Matrix4 m = Matrix4::identity();
        for (int c = 0; c < 3; ++c) {
            for (int r = 0; r < 3; ++r) m.m[std::size_t(r)][std::size_t(c)] = float(v[3 * c + r]);
            m.m[std::size_t(c)][3] = float(v[9 + c]);
        }
        const auto t = Transform::from_matrix(m);
        if (!t) throw parser_.error_at(keyword, "matrix has no inverse: it flattens the object");
        return *t;
    }
    if (w == "transform") {
        if (parser_.peek_item().is_symbol("{")) return std::get<Transform>(*read(keyword));
        const PovToken name = parser_.next();
        if (auto t = declared<Transform>(name)) return t;
        throw parser_.error_at(
            name, "expected a declared transform after transform, got " + describe(name));
    }
    return std::nullopt;
}

PovObject PovItemReader::object(const PovToken& keyword) {
    const PovParser::Nested nested(parser_, keyword);
    if (is_unread_object(keyword.text)) {
        parser_.skip_braced(keyword);
        PovObject unread;
        unread.unread = std::make_shared<const PovUnread>(PovUnread{keyword.text, keyword.at});
        return unread;
    }
    if (keyword.text == "light_source") {
        PovObject light;
        light.light = std::make_shared<const PovLight>(light_source(keyword));
        return light;
    }
    parser_.expect("{", "after " + keyword.text);
    PovObject object;
    if (keyword.text == "object") {
        if (auto base = take_declared<PovObject>()) {
            object = *base;
        } else {
            const PovToken name = parser_.next();
            if (!(name.kind == PovTokenKind::identifier && starts_object(name.text) &&
                  !parser_.symbols().find(name.text)))
                throw parser_.error_at(name,
                                       "expected an object or a declared one in object { }, "
                                       "got " +
                                           describe(name));
            object = this->object(name);  // object { sphere { ... } ... }
        }
    } else if (is_csg(keyword.text)) {
        csg(keyword, object);
    } else if (keyword.text == "mesh") {
        object.shape = mesh(keyword);
    } else if (keyword.text == "mesh2") {
        mesh2(keyword, object);
    } else if (keyword.text == "text") {
        text(keyword, object);
    } else if (keyword.text == "sphere_sweep") {
        sphere_sweep(keyword, object);
    } else {
        object.shape = shape(keyword);
        if (is_polynomial(keyword.text)) object.polynomial = keyword.text;
    }
    modifiers(object);
    if (!object.polynomial.empty()) set_polynomial_region(keyword, object);
    object.fallback = default_texture_;
    object.at = keyword.at;
    // An inverse plane is the other half-space: the plane turned over.
    if (auto* plane =
            object.inverse && object.shape ? std::get_if<Plane>(&*object.shape) : nullptr) {
        plane->normal = -plane->normal;
        object.inverse = false;
    }
    return object;
}

Shape PovItemReader::shape(const PovToken& keyword) {
    const std::string& w = keyword.text;
    if (w == "sphere") {
        const Point3 center = to_point(point("as the sphere's centre"));
        parser_.accept(",");
        const PovToken at = parser_.peek();
        const float radius = number("as the sphere's radius");
        if (!(radius > 0))
            throw parser_.error_at(at,
                                   "sphere radius must be > 0, got " + format_pov_number(radius));
        return Sphere{center, radius};
    }
    if (w == "box") {
        const Point3 a = to_point(point("as the box's corner"));
        parser_.accept(",");
        const Point3 b = to_point(point("as the box's corner"));
        return Box{{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)},
                   {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
    }
    if (w == "plane") {
        const Vector3 n = to_vector(point("as the plane's normal"));
        parser_.accept(",");
        const float d = number("as the plane's distance");
        if (!(length(n) > 0)) throw parser_.error_at(keyword, "plane normal must not be zero");
        const Vector3 unit = normalize(n);
        return Plane{to_point(unit * d), Normal3(unit)};
    }
    if (w == "cylinder" || w == "cone") {
        Point3 a = to_point(point("as the end's centre"));
        parser_.accept(",");
        float ra = 0;
        if (w == "cone") {
            ra = number("as the end's radius");
            parser_.accept(",");
        }
        Point3 b = to_point(point("as the other end's centre"));
        parser_.accept(",");
        float rb = number("as the radius");
        bool open = false;
        // `open` belongs to the shape: it comes before the modifiers.
        if (parser_.peek_item().is_word("open")) {
            parser_.next();
            open = true;
        }
        if (w == "cylinder") return checked_shape(parser_, keyword, Cylinder{a, b, rb, !open});
        if (ra < rb) {
            std::swap(a, b);
            std::swap(ra, rb);
        }
        return checked_shape(parser_, keyword, Cone{a, ra, b, rb, !open});
    }
    if (w == "quadric") {
        // <A, B, C>, <D, E, F>, <G, H, I>, J: A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x +
        // H y + I z + J, as glint's quadric; its clip box comes with its bounded_by.
        Quadric q;
        q.clip = Bounds3{};  // none yet
        for (int i = 0; i < 3; ++i) {
            const PovVector v = parser_.finite_vector("as the quadric's coefficients");
            for (int k = 0; k < 3; ++k) q.coefficients[std::size_t(3 * i + k)] = float(v[k]);
            parser_.accept(",");
        }
        q.coefficients[9] = number("as the quadric's constant");
        return q;
    }
    if (w == "cubic" || w == "quartic" || w == "poly") {
        int order = w == "cubic" ? 3 : 4;
        if (w == "poly") {
            order = parser_.whole_number("as the polynomial's order", 2, 7);
            parser_.accept(",");
        }
        const std::vector<double> c = parser_.finite_list(
            "as the " + w + "'s coefficients", std::size_t(polynomial_term_count(order)));
        auto compiled = compile_expression(polynomial_text(order, c), {});
        if (auto* error = std::get_if<ExpressionError>(&compiled))
            throw parser_.error_at(keyword, w + ": " + error->message);
        ImplicitSurface surface;
        surface.f = std::make_shared<const Expression>(std::move(std::get<Expression>(compiled)));
        surface.region = Bounds3{};  // none yet: it comes with its bounded_by
        return surface;
    }
    if (w == "superellipsoid") return superellipsoid(keyword);
    if (w == "isosurface") return isosurface(keyword);
    if (w == "blob") return blob(keyword);
    if (w == "torus") {
        const float major = number("as the torus's major radius");
        parser_.accept(",");
        const float minor = number("as the torus's minor radius");
        return checked_shape(parser_, keyword, Torus{{0, 0, 0}, Normal3{0, 1, 0}, major, minor});
    }
    if (w == "disc") {
        const Point3 center = to_point(point("as the disc's centre"));
        parser_.accept(",");
        const Vector3 n = to_vector(point("as the disc's normal"));
        parser_.accept(",");
        const float radius = number("as the disc's radius");
        float hole = 0;
        if (parser_.accept(",")) hole = number("as the disc's hole radius");
        if (!(length(n) > 0)) throw parser_.error_at(keyword, "disc normal must not be zero");
        return checked_shape(parser_, keyword, Disk{center, Normal3(normalize(n)), radius, hole});
    }
    if (w == "triangle") {
        MeshCorners corners;
        triangle(keyword, corners);
        return Triangle{{corners.positions[0], corners.positions[1], corners.positions[2]}};
    }
    if (w == "smooth_triangle") {
        // A mesh of one triangle carries the vertex normals.
        MeshCorners corners;
        triangle(keyword, corners);
        MeshBuild built = build_mesh(mesh_arrays(corners));
        if (!built.mesh) throw parser_.error_at(keyword, "smooth_triangle: " + built.error);
        return TriangleMesh{built.mesh};
    }
    if (w == "polygon") {
        const int count = parser_.whole_number("as the polygon's number of points", 3, 1'000'000);
        std::vector<Point3> points;
        for (int i = 0; i < count; ++i) {
            parser_.accept(",");
            const PovVector p = parser_.finite_vector("as a polygon point", 2);
            points.push_back({float(p[0]), float(p[1]), float(p.size > 2 ? p[2] : 0)});
        }
        // POV-Ray closes each outline by repeating its first point, and the last one without
        // it; points inside an odd number of outlines are inside (holes, islands).
        std::vector<std::vector<Point3>> outlines;
        for (std::size_t start = 0, i = 1; start < points.size(); ++i) {
            if (i < points.size() && points[i] != points[start]) continue;
            if (i - start < 3)
                throw parser_.error_at(keyword, "polygon: outline " +
                                                    std::to_string(outlines.size() + 1) +
                                                    " has fewer than 3 points");
            outlines.emplace_back(points.begin() + std::ptrdiff_t(start),
                                  points.begin() + std::ptrdiff_t(i));
            start = i + 1;
            i = start;
        }
        points = bridged_outline(outlines);
        auto made = make_polygon(points);
        if (auto* error = std::get_if<std::string>(&made)) throw parser_.error_at(keyword, *error);
        return std::get<Polygon>(std::move(made));
    }
    if (w == "prism") return prism(keyword);
    if (w == "lathe") return lathe(keyword);
    if (w == "sor") return sor(keyword);
    if (w == "julia_fractal") return julia_fractal(keyword);
    if (w == "height_field") return height_field(keyword);
    throw unsupported(keyword, "as an object");
}

void PovItemReader::triangle(const PovToken& keyword, MeshCorners& corners) {
    const bool smooth = keyword.text == "smooth_triangle";
    for (int i = 0; i < 3; ++i) {
        if (i > 0) parser_.accept(",");
        corners.positions.push_back(to_point(point("as a corner")));
        std::optional<Normal3> normal;
        if (smooth) {
            parser_.accept(",");
            normal = Normal3(to_vector(point("as the corner's normal")));
        }
        corners.normals.push_back(normal);
    }
}

MeshData PovItemReader::mesh_arrays(const MeshCorners& corners) {
    MeshData arrays;
    arrays.positions.assign(corners.positions.begin(), corners.positions.end());
    const bool smooth = std::any_of(corners.normals.begin(), corners.normals.end(),
                                    [](const auto& n) { return n.has_value(); });
    for (std::uint32_t t = 0; 3 * t < corners.positions.size(); ++t) {
        arrays.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
        if (!smooth) continue;
        // A flat triangle among smooth ones takes its face's normal at its corners.
        const Point3 a = arrays.positions[3 * t], b = arrays.positions[3 * t + 1],
                     c = arrays.positions[3 * t + 2];
        const Normal3 face(cross(b - a, c - a));
        for (int k = 0; k < 3; ++k)
            arrays.normals.push_back(corners.normals[3 * t + k].value_or(face));
    }
    return arrays;
}

Shape PovItemReader::mesh(const PovToken& keyword) {
    MeshCorners corners;
    while (parser_.peek_item().is_word("triangle") ||
           parser_.peek_item().is_word("smooth_triangle")) {
        const PovToken kind = parser_.next();
        parser_.expect("{", "after " + kind.text);
        triangle(kind, corners);
        const PovToken close = parser_.next();
        if (!close.is_symbol("}")) throw unsupported(close, "in a mesh's triangle");
    }
    MeshBuild built = build_mesh(mesh_arrays(corners));
    if (!built.mesh) throw parser_.error_at(keyword, "mesh: " + built.error);
    return TriangleMesh{built.mesh};
}

void PovItemReader::csg(const PovToken& keyword, PovObject& object) {
    const std::string& w = keyword.text;
    object.csg = w == "union"          ? PovObject::Csg::group
                 : w == "merge"        ? PovObject::Csg::merge
                 : w == "intersection" ? PovObject::Csg::intersection
                                       : PovObject::Csg::difference;
    while (starts_object(parser_.peek_item().text) &&
           parser_.peek_item().kind == PovTokenKind::identifier) {
        const PovToken child = parser_.next();
        object.children.push_back(std::make_shared<const PovObject>(this->object(child)));
    }
    if (object.children.empty()) throw parser_.error_at(keyword, w + " needs objects inside it");
}

std::shared_ptr<const PovObject> PovItemReader::object_list(const PovToken& keyword,
                                                            const PovObject& object,
                                                            std::shared_ptr<const PovObject> so_far,
                                                            bool* names_other) {
    parser_.expect("{", "after " + keyword.text);
    const std::string other = keyword.text == "clipped_by" ? "bounded_by" : "clipped_by";
    if (parser_.peek().is_word(other)) {
        parser_.next();
        parser_.expect("}", "after " + other);
        *names_other = true;
        return so_far;
    }
    // Several blocks of one kind add up: all their objects count.
    PovObject clip = so_far ? *so_far : PovObject{};
    clip.csg = PovObject::Csg::intersection;
    clip.at = keyword.at;
    // The objects are written in the object's parent space, as it stands after the transforms
    // read so far.
    const Transform to_object = object.transform.inverse();
    while (starts_object(parser_.peek_item().text) &&
           parser_.peek_item().kind == PovTokenKind::identifier) {
        const PovToken child = parser_.next();
        PovObject o = this->object(child);
        o.transform = to_object * o.transform;
        clip.children.push_back(std::make_shared<const PovObject>(std::move(o)));
    }
    const PovToken close = parser_.next();
    if (!close.is_symbol("}")) throw unsupported(close, "in " + keyword.text);
    if (clip.children.empty())
        throw parser_.error_at(keyword, keyword.text + " needs objects inside it");
    return std::make_shared<const PovObject>(std::move(clip));
}

Bounds3 PovItemReader::extent(const PovObject& object) {
    Bounds3 b;
    if (object.shape) {
        b = own_extent(*object.shape);
    } else if (object.csg == PovObject::Csg::intersection) {
        b = {{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}};
        for (const auto& child : object.children) {
            b = overlap(b, extent(*child));
        }
    } else if (object.csg == PovObject::Csg::difference && !object.children.empty()) {
        b = extent(*object.children.front());
    } else {
        for (const auto& child : object.children) b = merge(b, extent(*child));
    }
    if (object.clipped_by) {
        b = overlap(b, extent(*object.clipped_by));
    }
    return object.transform(b);
}

Bounds3 own_extent(const Shape& shape) {
    constexpr Bounds3 everywhere{{-kInfinity, -kInfinity, -kInfinity},
                                 {kInfinity, kInfinity, kInfinity}};
    // A plane along an axis is the half-space below it.
    if (const auto* plane = std::get_if<Plane>(&shape)) {
        const Vector3 n = to_vector(plane->normal);
        Bounds3 half = everywhere;
        for (int axis = 0; axis < 3; ++axis) {
            if (std::abs(n[axis]) != 1) continue;
            const float at = plane->point[axis];
            if (n[axis] > 0) (axis == 0 ? half.max.x : axis == 1 ? half.max.y : half.max.z) = at;
            if (n[axis] < 0) (axis == 0 ? half.min.x : axis == 1 ? half.min.y : half.min.z) = at;
        }
        return half;
    }
    const Bounds3 b = bounds(shape);
    if (!b.is_empty()) return b;
    // A polynomial not bounded yet: a quadric's inside where it is bounded along some axes.
    if (const auto* quadric = std::get_if<Quadric>(&shape))
        return inside_extent(quadric->coefficients);
    if (std::holds_alternative<ImplicitSurface>(shape)) return everywhere;
    return b;
}

Bounds3 far_bounded(Bounds3 region) {
    constexpr float far = kFarQuadric;
    region.min = max(region.min, Point3{-far, -far, -far});
    region.max = min(region.max, Point3{far, far, far});
    return region;
}

Bounds3 loosened(Bounds3 region) {
    if (region.is_empty() || !region.is_finite()) return region;
    const Vector3 size = region.diagonal();
    const Vector3 pad{1e-4f * std::max(1.0f, size.x), 1e-4f * std::max(1.0f, size.y),
                      1e-4f * std::max(1.0f, size.z)};
    return {region.min - pad, region.max + pad};
}

void PovItemReader::set_polynomial_region(const PovToken& keyword, PovObject& object) {
    const PovObject* bound = object.bounded_by ? object.bounded_by.get() : object.clipped_by.get();
    if (!bound) return;
    // The objects' common box, in the object's own space; a quadric's cut far out where they
    // leave it unbounded.
    Bounds3 region = extent(*bound);
    if (std::holds_alternative<Quadric>(*object.shape)) region = far_bounded(region);
    const Vector3 size = region.diagonal();
    if (region.is_empty() || !region.is_finite() || !(size.x > 0 && size.y > 0 && size.z > 0))
        throw parser_.error_at(keyword, "the " + object.polynomial +
                                            "'s bounded_by or clipped_by objects must enclose a "
                                            "finite box for glint to search the surface in");
    bound_polynomial(*object.shape, region);
}

void bound_polynomial(Shape& shape, const Bounds3& region) {
    if (auto* quadric = std::get_if<Quadric>(&shape)) {
        quadric->clip = region;
    } else if (auto* surface = std::get_if<ImplicitSurface>(&shape)) {
        surface->region = region;
        surface->tolerance = 1e-4f * max_component(region.diagonal());
    }
}

void PovItemReader::modifiers(PovObject& object) {
    bool clip_by_bounds = false, bound_by_clip = false;  // `clipped_by { bounded_by }` and back
    for (;;) {
        const PovToken token = parser_.next();
        if (token.is_symbol("}")) {
            if (clip_by_bounds) object.clipped_by = object.bounded_by;
            if (bound_by_clip) object.bounded_by = object.clipped_by;
            return;
        }
        if (token.kind != PovTokenKind::identifier) {
            throw parser_.error_at(token, "expected a modifier or '}', got " + describe(token));
        }
        const std::string& w = token.text;
        if (const auto step = transform_step(token)) {
            object.transform = *step * object.transform;
            // A texture given before moves with the object, as do the media of an interior.
            if (object.texture) {
                PovTexture moved = *object.texture;
                moved.move(*step);
                object.texture = std::make_shared<const PovTexture>(moved);
            }
            if (object.interior && object.interior->has_densities()) {
                PovInterior moved = *object.interior;
                moved.move(*step);
                object.interior = std::make_shared<const PovInterior>(std::move(moved));
            }
        } else if (w == "texture") {
            // A texture written after another is a layer over it, as in POV-Ray.
            PovTexture t = texture(*default_texture_);
            if (object.texture) t = laid_over(*object.texture, std::move(t), token);
            object.texture = std::make_shared<const PovTexture>(std::move(t));
        } else if (w == "pigment") {
            PovTexture t = object.texture ? *object.texture : *default_texture_;
            t.top().pigment = pigment(t.top().pigment);
            object.texture = std::make_shared<const PovTexture>(without_hidden(std::move(t)));
        } else if (w == "finish") {
            PovTexture t = object.texture ? *object.texture : *default_texture_;
            t.top().finish = finish(t.top().finish);
            object.texture = std::make_shared<const PovTexture>(t);
        } else if (w == "interior") {
            object.interior = std::make_shared<const PovInterior>(
                interior(object.interior ? *object.interior : PovInterior{}));
        } else if (w == "material") {
            const PovMaterial m = material({object.texture, object.interior});
            object.texture = m.texture;
            object.interior = m.interior;
        } else if (w == "normal") {
            PovTexture t = object.texture ? *object.texture : *default_texture_;
            t.top().normal = normal(t.top().normal);
            object.texture = std::make_shared<const PovTexture>(t);
        } else if (w == "no_shadow") {
            object.no_shadow = true;
        } else if (w == "hollow") {
            object.hollow = optional_amount() != 0;
        } else if (w == "inverse") {
            object.inverse = !object.inverse;
        } else if (w == "clipped_by") {
            object.clipped_by = object_list(token, object, object.clipped_by, &clip_by_bounds);
        } else if (w == "bounded_by") {
            object.bounded_by = object_list(token, object, object.bounded_by, &bound_by_clip);
        } else if (w == "sturm") {
            // POV-Ray's choice of root solver: glint's search needs none.
        } else if (w == "photons" || w == "radiosity") {
            parser_.skip_braced(token);
            read_past(w + " { } in an object",
                      w == "photons" ? "the Whitted and distributed integrators trace no photons"
                                     : "glint renders without radiosity");
        } else if (w == "no_image" || w == "no_reflection" || w == "no_radiosity" ||
                   w == "double_illuminate") {
            optional_amount();
            read_past(w, w == "double_illuminate" ? "a surface is lit from the side the light is on"
                                                  : "the object is seen by every ray");
        } else {
            throw unsupported(token, "as an object modifier");
        }
    }
}

PovTexture PovItemReader::texture(const PovTexture& base) {
    parser_.expect("{", "after texture");
    PovTexture t = base;
    if (auto d = take_declared<PovTexture>()) {
        t = *d;
    }
    // What is written after a declared layered texture changes its top layer, as in POV-Ray.
    bool uv_mapping = false;  // the texture's pigment laid over the surface's uv
    for (;;) {
        const PovToken token = parser_.next();
        if (token.is_symbol("}")) {
            PovPigment& p = t.top().pigment;
            if (uv_mapping &&
                (p.kind == PovPigment::Kind::pattern || p.kind == PovPigment::Kind::image))
                p.uv_mapping = true;
            return without_hidden(std::move(t));
        }
        if (token.is_word("uv_mapping"))
            uv_mapping = true;
        else if (token.is_word("pigment"))
            t.top().pigment = pigment(t.top().pigment);
        else if (token.is_word("finish"))
            t.top().finish = finish(t.top().finish);
        else if (token.is_word("normal"))
            t.top().normal = normal(t.top().normal);
        else if (token.is_word("checker"))
            checker_texture(token, t.top());
        else if (const auto step = transform_step(token))
            t.move(*step);
        else
            throw unsupported(token, "in a texture");
    }
}

void PovItemReader::checker_texture(const PovToken& keyword, PovTexture& t) {
    PovTexture squares[2];
    for (PovTexture& square : squares) {
        parser_.accept(",");
        const PovToken next = parser_.next();
        if (!next.is_word("texture"))
            throw parser_.error_at(
                next, "expected a texture for the checker's squares, got " + describe(next));
        square = texture(*default_texture_);
        if (square.pigment.kind != PovPigment::Kind::color)
            throw parser_.error_at(keyword,
                                   "a checker of patterned textures is not supported yet: its "
                                   "squares' pigments must be colours",
                                   {kSeeCompatibility});
    }
    // glint's material has one finish: the first square's.
    PovPigment& p = t.pigment;
    p = PovPigment{};
    p.kind = PovPigment::Kind::pattern;
    p.spec.kind = PatternKind::checker;
    p.spec.wave = default_wave(PatternKind::checker);
    p.map.stops = {{0, squares[0].pigment.color}, {1, squares[1].pigment.color}};
    t.finish = squares[0].finish;
    if (!warned_checker_finish_)
        warnings_.push_back(
            "texture { checker texture texture }: both squares take the first's "
            "finish");
    warned_checker_finish_ = true;
}

PovFinish PovItemReader::finish(const PovFinish& base) {
    parser_.expect("{", "after finish");
    PovFinish f = base;
    if (auto d = take_declared<PovFinish>()) {
        f = *d;
    }
    // A colour where POV-Ray allows one counts as its brightest channel.
    const auto amount = [&](std::string_view what) {
        const PovVector v = parser_.color_expression(what);
        return std::max({v[0], v[1], v[2]});
    };
    // A reflection's colour: its greatest channel as the amount, the others relative to it.
    const auto reflection_amount = [&](std::string_view what) {
        const PovVector v = parser_.color_expression(what);
        const double most = std::max({v[0], v[1], v[2]});
        f.reflection_color =
            most > 0 ? Color{float(std::max(v[0], 0.0) / most), float(std::max(v[1], 0.0) / most),
                             float(std::max(v[2], 0.0) / most)}
                     : Color{1, 1, 1};
        return most;
    };
    for (;;) {
        const PovToken token = parser_.next();
        const std::string& w = token.text;
        if (token.is_symbol("}")) return f;
        if (w == "ambient")
            f.ambient = amount("after ambient");
        else if (w == "diffuse") {
            f.diffuse = parser_.finite_float("after diffuse");
            // POV-Ray 3.7's light through the back of a thin surface: `diffuse 0.7, 0.2`.
            if (parser_.accept(",")) {
                parser_.finite_float("as the diffuse light from behind");
                read_past("diffuse light from behind (diffuse A, B)",
                          "surfaces are lit from the side the light is on");
            }
        } else if (w == "brilliance")
            f.brilliance = parser_.finite_float("after brilliance");
        else if (w == "phong")
            f.phong = parser_.finite_float("after phong");
        else if (w == "phong_size")
            f.phong_size = parser_.finite_float("after phong_size");
        else if (w == "specular")
            f.specular = parser_.finite_float("after specular");
        else if (w == "roughness")
            f.roughness = parser_.finite_float("after roughness");
        else if (w == "metallic")
            f.metallic = optional_amount();
        else if (w == "crand")
            parser_.finite_float("after crand");
        else if (w == "conserve_energy")
            optional_amount();  // read; glint's reflection adds to the diffuse as POV-Ray's without
                                // it
        else if (w == "emission")
            f.emission = amount("after emission");
        else if (w == "reflection") {
            if (parser_.accept("{")) {
                // reflection { [min,] max [fresnel] [metallic] [falloff F] [exponent E] }
                f.reflection = reflection_amount("in reflection");
                f.reflection_min.reset();
                f.fresnel = false;
                f.reflection_falloff = 1;
                f.reflection_metallic = 0;
                // The maximum after the minimum, with or without a comma between.
                bool two = false;
                if (parser_.accept(",") || number_next()) {
                    f.reflection_min = f.reflection;
                    f.reflection = reflection_amount("in reflection");
                    two = true;
                }
                for (PovToken r = parser_.next(); !r.is_symbol("}"); r = parser_.next()) {
                    if (r.is_word("fresnel")) {
                        f.fresnel = optional_amount() != 0;
                        // One value with fresnel is the maximum, from 0 facing the viewer.
                        if (f.fresnel && !two) f.reflection_min = 0;
                    } else if (r.is_word("metallic")) {
                        f.reflection_metallic = std::clamp(optional_amount(), 0.0, 1.0);
                    } else if (r.is_word("falloff")) {
                        const PovToken at = parser_.peek();
                        f.reflection_falloff = parser_.finite_float("after falloff");
                        if (!(f.reflection_falloff > 0))
                            throw parser_.error_at(at, "reflection's falloff must be > 0");
                    } else if (r.is_word("exponent")) {
                        parser_.finite_float("in reflection");
                    } else {
                        throw unsupported(r, "in reflection { }");
                    }
                }
            } else {
                f.reflection = reflection_amount("after reflection");
                f.reflection_min.reset();
                f.fresnel = false;
            }
        } else {
            throw unsupported(token, "in a finish");
        }
    }
}

PovMaterial PovItemReader::material(const PovMaterial& base) {
    parser_.expect("{", "after material");
    PovMaterial m = base;
    if (auto d = take_declared<PovMaterial>()) {
        if (d->texture) m.texture = d->texture;
        if (d->interior) m.interior = d->interior;
    }
    for (;;) {
        const PovToken token = parser_.next();
        if (token.is_symbol("}")) return m;
        if (token.is_word("texture")) {
            PovTexture t = texture(*default_texture_);
            if (m.texture) t = laid_over(*m.texture, std::move(t), token);
            m.texture = std::make_shared<const PovTexture>(std::move(t));
        } else if (token.is_word("interior")) {
            m.interior = std::make_shared<const PovInterior>(
                interior(m.interior ? *m.interior : PovInterior{}));
        } else if (const auto step = transform_step(token)) {
            if (m.texture) {
                PovTexture moved = *m.texture;
                moved.move(*step);
                m.texture = std::make_shared<const PovTexture>(moved);
            }
        } else {
            throw unsupported(token, "in a material");
        }
    }
}

PovInterior PovItemReader::interior(const PovInterior& base) {
    parser_.expect("{", "after interior");
    PovInterior in = base;
    if (auto d = take_declared<PovInterior>()) {
        in = *d;
    }
    for (;;) {
        const PovToken token = parser_.next();
        if (token.is_symbol("}")) return in;
        if (token.is_word("ior"))
            in.ior = parser_.finite_float("after ior");
        else if (token.is_word("dispersion")) {
            const PovToken at = parser_.peek();
            in.dispersion = parser_.finite_float("after dispersion");
            if (!(in.dispersion > 0.5 && in.dispersion < 2))
                throw parser_.error_at(
                    at, "dispersion must be in (0.5, 2), got " + format_pov_number(in.dispersion),
                    {"1 is none; POV-Ray suggests 1.01 to 1.1"});
        } else if (token.is_word("dispersion_samples"))
            in.dispersion_samples = parser_.whole_number("after dispersion_samples", 2, 1 << 10);
        else if (token.is_word("fade_distance") || token.is_word("fade_power")) {
            const PovToken at = parser_.peek();
            const auto value = float(parser_.finite_float("after " + token.text));
            (token.text == "fade_distance" ? in.fade.distance : in.fade.power) = value;
            if (const std::string problem = describe_problem(in.fade); !problem.empty())
                throw parser_.error_at(at, problem);
        } else if (token.is_word("fade_color") || token.is_word("fade_colour")) {
            const PovToken at = parser_.peek();
            const PovVector c = parser_.color_expression("after " + token.text);
            in.fade.color = Color{float(c[0]), float(c[1]), float(c[2])};
            if (const std::string problem = describe_problem(in.fade); !problem.empty())
                throw parser_.error_at(at, problem);
        } else if (token.is_word("caustics"))
            parser_.finite_float("in an interior");  // read; faked caustics are not drawn
        else if (token.is_word("media")) {
            if (in.media.size() == kMaxMedia)
                throw parser_.error_at(
                    token, "an interior holds at most " + std::to_string(kMaxMedia) + " media");
            in.media.push_back(media(token));
        } else
            throw unsupported(token, "in an interior");
    }
}

}  // namespace glint
