// POV-Ray's sphere_sweep { linear_spline | b_spline | cubic_spline n, <c>, r, ... tolerance t }
// onto glint's own solids: the merge of its chain of spheres and tangent cones
// (geometry/sphere_sweep.h), a solid as POV-Ray's is.
#include "glint/geometry/sphere_sweep.h"
#include "glint/scene/pov/pov_item_reader.h"

namespace glint {

void PovItemReader::sphere_sweep(const PovToken& keyword, PovObject& object) {
    const PovToken kind = parser_.next();
    SweepSpline spline = SweepSpline::linear;
    if (kind.is_word("b_spline")) {
        spline = SweepSpline::b_spline;
    } else if (kind.is_word("cubic_spline")) {
        spline = SweepSpline::cubic;
    } else if (!kind.is_word("linear_spline")) {
        throw parser_.error_at(kind,
                               "expected linear_spline, b_spline or cubic_spline in "
                               "sphere_sweep, got " +
                                   describe(kind));
    }
    const int count = parser_.whole_number("as the sphere_sweep's number of spheres", 2, 1'000'000);
    std::vector<SweptSphere> spheres;
    for (int i = 0; i < count; ++i) {
        parser_.accept(",");
        const Point3 center = to_point(point("as a sphere_sweep centre"));
        parser_.accept(",");
        const PovToken at = parser_.peek();
        const float radius = number("as a sphere_sweep radius");
        if (!(radius > 0))
            throw parser_.error_at(
                at, "sphere_sweep radius must be > 0, got " + format_pov_number(radius));
        spheres.push_back({center, radius});
    }
    // POV-Ray's depth tolerance for its root solver: glint meets each piece exactly.
    if (parser_.peek_item().is_word("tolerance")) {
        parser_.next();
        parser_.finite_float("as the sphere_sweep's tolerance");
    }
    auto pieces = sweep_pieces(spline, spheres);
    if (const auto* problem = std::get_if<std::string>(&pieces))
        throw parser_.error_at(keyword, *problem);
    object.csg = PovObject::Csg::merge;
    const auto add = [&](Shape shape) {
        PovObject piece;
        piece.shape = std::move(shape);
        piece.at = keyword.at;
        object.children.push_back(std::make_shared<const PovObject>(std::move(piece)));
    };
    for (const Sphere& s : std::get<SweepPieces>(pieces).spheres) add(s);
    for (const Cone& c : std::get<SweepPieces>(pieces).cones) add(c);
}

}  // namespace glint
