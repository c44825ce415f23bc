// What a POV-Ray scene's declarable items are as they are read, in POV-Ray's own terms (its
// finish, pigment, texture and interior, and objects with their transforms), before
// pov_scene.cpp maps them onto glint's materials, shapes and lights.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "glint/geometry/shape.h"
#include "glint/math/transform.h"
#include "glint/scene/pov/pov_files.h"
#include "glint/scene/pov/pov_value.h"

namespace glint {

// POV-Ray's finish, with its defaults.
struct PovFinish {
    double ambient = 0.1;
    double diffuse = 0.6;
    double brilliance = 1;
    double phong = 0, phong_size = 40;
    double specular = 0, roughness = 0.05;
    double reflection = 0;
    double emission = 0;   // the pigment's colour given off, unlit
    bool fresnel = false;  // reflection { ... fresnel }
    bool metallic = false;
};

// A solid colour (r, g, b, filter, transmit), or a checker of two; or a pattern glint does not
// read yet, read past so that only an object that uses it stops the scene.
struct PovPigment {
    enum class Kind { color, checker, unsupported } kind = Kind::color;
    std::string pattern;                    // unsupported: its name
    PovPosition at;                         // unsupported: where it was written
    PovVector color = PovVector::of(0, 5);  // POV-Ray's default pigment is black
    PovVector other = PovVector::of(0, 5);  // checker: the second colour
    Transform transform;                    // where the pattern lies, relative to the object
};

struct PovTexture {
    PovPigment pigment;
    PovFinish finish;
};

struct PovInterior {
    double ior = 1;
    double dispersion = 1;
};

// An object: a shape in its own space or a CSG of objects, placed by its transform, with what
// it says of its look (children without a texture take their parent's).
struct PovUnread;

struct PovObject {
    std::optional<Shape> shape;  // a shape; else a CSG of children (or an object not read yet)
    enum class Csg { group, merge, intersection, difference } csg = Csg::group;
    std::vector<std::shared_ptr<const PovObject>> children;
    Transform transform;                         // object to parent
    std::shared_ptr<const PovTexture> texture;   // null: the parent's, or `fallback`
    std::shared_ptr<const PovTexture> fallback;  // #default's texture when it was read
    std::shared_ptr<const PovInterior> interior;
    bool no_shadow = false;
    bool hollow = false;
    std::shared_ptr<const PovUnread> unread;  // an object glint does not read yet: its name, place
};

// A map (color_map, pigment_map, ...) that glint does not read yet: kept to stop the scene only
// where it is used.
struct PovUnread {
    std::string what;
    PovPosition at;
};

using PovItem =
    std::variant<PovObject, PovTexture, PovPigment, PovFinish, PovInterior, Transform, PovUnread>;

// A declared item as an identifier's value holds it.
struct PovItemRef {
    PovItem item;
};

}  // namespace glint
