// Parsers of the round shapes: disk, cylinder, cone, torus, and the quadric clipped to a box.
#include "glint/scene/yaml/yaml_shape_parsers.h"

namespace glint {

Shape parse_disk(const MapReader& object, ShapeReader&) {
    Disk disk;
    disk.center = object.point("center");
    disk.normal = Normal3(object.direction("normal", Vector3{0, 1, 0}));
    disk.radius = object.number("radius");
    disk.inner_radius = object.number("inner_radius");
    return checked(object, disk);
}

Shape parse_cylinder(const MapReader& object, ShapeReader&) {
    Cylinder cylinder;
    cylinder.base = object.point("base");
    cylinder.top = object.point("top");
    cylinder.radius = object.number("radius");
    cylinder.capped = object.boolean("capped", true);
    return checked(object, cylinder);
}

Shape parse_cone(const MapReader& object, ShapeReader&) {
    Cone cone;
    cone.base = object.point("base");
    cone.base_radius = object.number("base_radius");
    cone.apex = object.point("apex");
    cone.apex_radius = object.number("apex_radius");
    cone.capped = object.boolean("capped", true);
    return checked(object, cone);
}

Shape parse_torus(const MapReader& object, ShapeReader&) {
    Torus torus;
    torus.center = object.point("center", Point3{0, 0, 0});
    torus.axis = Normal3(object.direction("axis", Vector3{0, 1, 0}));
    torus.major_radius = object.number("major_radius");
    torus.minor_radius = object.number("minor_radius");
    return checked(object, torus);
}

Shape parse_quadric(const MapReader& object, ShapeReader&) {
    const YamlSource& source = object.source();
    Quadric quadric;
    const MapEntry& entry = object.require("coefficients");
    const auto items = read_sequence(source, entry.value, object.field("coefficients"),
                                     "a list of 10 numbers [A, B, C, D, E, F, G, H, I, J]", 10);
    for (std::size_t i = 0; i < 10; ++i) {
        quadric.coefficients[i] = read_number(
            source, items[i], {object.what(), "coefficients[" + std::to_string(i) + "]"});
    }
    quadric.clip = {object.point("min"), object.point("max")};
    return checked(object, quadric);
}

}  // namespace glint
