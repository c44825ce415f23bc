#include "glint/geometry/shape.h"

namespace glint {

namespace {
struct NameOf {
    std::string_view operator()(const Sphere&) const { return "sphere"; }
    std::string_view operator()(const Plane&) const { return "plane"; }
    std::string_view operator()(const Triangle&) const { return "triangle"; }
    std::string_view operator()(const Box&) const { return "box"; }
};
}  // namespace

std::string_view shape_name(const Shape& shape) { return std::visit(NameOf{}, shape); }

}  // namespace glint
