// What a POV-Ray scene's declarable items are as they are read, in POV-Ray's own terms (its
// finish, pigment, texture and interior, and objects with their transforms), before
// pov_scene.cpp maps them onto glint's materials, shapes and lights.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "glint/camera/camera_spec.h"
#include "glint/geometry/shape.h"
#include "glint/math/transform.h"
#include "glint/scene/pov/pov_files.h"
#include "glint/scene/pov/pov_value.h"
#include "glint/shading/interior_fade.h"
#include "glint/shading/medium.h"
#include "glint/shading/normal_pattern.h"
#include "glint/shading/pattern.h"
#include "glint/shading/projected_image.h"

namespace glint {

// POV-Ray's finish, with its defaults.
struct PovFinish {
    double ambient = 0.1;
    double diffuse = 0.6;
    double brilliance = 1;
    double phong = 0, phong_size = 40;
    double specular = 0, roughness = 0.05;
    double reflection = 0;  // the maximum, at grazing incidence: its colour's greatest channel
    Color reflection_color{1, 1, 1};  // the colour's channels over the greatest
    // reflection { min max falloff F fresnel metallic M }: the minimum, facing the viewer
    // (the maximum unless given; 0 with fresnel and one value).
    std::optional<double> reflection_min;
    double reflection_falloff = 1;
    bool fresnel = false;
    double reflection_metallic = 0;
    double emission = 0;  // the pigment's colour given off, unlit
    double metallic = 0;  // the highlight's tint by the pigment
};

// One entry of a color_map: the colour (r, g, b, filter, transmit) from the value `at` on.
struct PovPigment;
struct PovColorStop {
    double at = 0;
    PovVector color = PovVector::of(0, 5);
    std::shared_ptr<const PovPigment> pigment;  // a pigment_map's entry: the pigment, not color
};

struct PovColorMap {
    std::vector<PovColorStop> stops;  // sorted by `at`, at least one
};

// A solid colour (r, g, b, filter, transmit), or a pattern through a colour map (a checker's
// two colours are the map at 0 and 1), or an image_map; or a pattern glint does not read yet,
// read past so that only an object that uses it stops the scene.
struct PovPigment {
    enum class Kind { color, pattern, image, unsupported } kind = Kind::color;
    std::string pattern;  // unsupported: its name
    std::string uses;     // unsupported function: what in it glint does not compute yet
    PovPosition at;       // unsupported: where it was written
    PovVector color = PovVector::of(0, 5);  // POV-Ray's default pigment is black
    PatternSpec spec;                       // pattern: glint's own
    PovColorMap map;                        // pattern: its colours
    Transform transform;                    // where the pattern lies, relative to the object
    // image: the image and its projection (its transform unset: `transform` places it), or the
    // image on the surface's uv (uv_mapping); `color` holds its filter and transmit all.
    std::shared_ptr<const ProjectedImage> image;
    bool uv_mapping = false;
    bool average = false;  // pattern: POV-Ray's average of its pigment_map's entries
};

// sky_sphere: pigments layered from the first up, seen in each direction as at the point of the
// unit sphere there, moved by the transform; scaled by emission.
struct PovSkySphere {
    std::vector<PovPigment> pigments;
    Transform transform;
    PovVector emission = PovVector::of(1, 5);
};

// fog: constant (fog_type 1) or ground fog (fog_type 2), as written.
struct PovFog {
    int type = 1;
    double distance = 0;
    PovVector color = PovVector::of(0, 5);
    double offset = 0, alt = 0;  // fog_offset, fog_alt
    PovVector up{{0, 1, 0}};
    PovVector turbulence{{0, 0, 0}};
    double turbulence_depth = 0.5;  // turb_depth
    PovPosition at;
};

// normal { }: a normal pattern placed by its transform (relative to the object, as a
// pigment's); or one glint does not read yet (`unsupported` names it), which leaves the surface
// smooth.
struct PovNormal {
    NormalPattern pattern;  // its to_pattern is set when the object is placed
    // pigment_pattern: the pigment whose grey is the slope's height (pattern.pigment is made
    // from it when the object is placed).
    std::shared_ptr<const PovPigment> pigment;
    Transform transform;
    std::string unsupported;
};

// A texture, and the layers over it (`texture { } texture { }`): each of those a texture of
// its own, with none above it.
struct PovTexture {
    PovPigment pigment;
    PovFinish finish;
    std::optional<PovNormal> normal;
    std::vector<PovTexture> above;  // bottom first

    // The layer on top, which pigment, finish and normal written after the layers change.
    PovTexture& top() { return above.empty() ? *this : above.back(); }
    const PovTexture& top() const { return above.empty() ? *this : above.back(); }

    // The texture moved by `step`, after what moved it before: its pigments and normals with it.
    void move(const Transform& step) {
        pigment.transform = step * pigment.transform;
        if (normal) normal->transform = step * normal->transform;
        for (PovTexture& layer : above) layer.move(step);
    }
};

// media { } as written: glint's medium (its densities left empty) and the density pigments,
// in the object's space as its texture's pigments are.
struct PovMedium {
    Medium medium;
    std::vector<PovPigment> densities;
};

struct PovInterior {
    double ior = 1;
    double dispersion = 1;  // the index's ratio from the red end of the spectrum to the violet
    int dispersion_samples = 7;
    // fade_distance, fade_power and fade_color, as glint's fade (0 distance: none; POV-Ray's
    // power 0 unless given).
    InteriorFade fade{0, 0, {}};
    std::vector<PovMedium> media;

    bool has_densities() const {
        for (const PovMedium& m : media)
            if (!m.densities.empty()) return true;
        return false;
    }
    // Moves the media's densities, as an object's transforms move its interior.
    void move(const Transform& step) {
        for (PovMedium& m : media)
            for (PovPigment& d : m.densities) d.transform = step * d.transform;
    }
};

// material { texture interior }: what it gives; null where it gives nothing.
struct PovMaterial {
    std::shared_ptr<const PovTexture> texture;
    std::shared_ptr<const PovInterior> interior;
};

// POV-Ray's camera as written: its vectors before look_at aims them (pov_scene.cpp does).
struct PovCamera {
    PovPosition at;  // the camera keyword, for errors found when it is placed
    bool orthographic = false;
    // fisheye, ultra_wide_angle, panoramic, cylinder (of kind 1 to 4) or spherical; nothing
    // for perspective and orthographic.
    std::optional<Projection> wide;
    int cylinder_kind = 1;
    std::optional<double> vertical_angle;  // spherical: the second number after angle
    PovVector location{};
    PovVector direction{{0, 0, 1}}, up{{0, 1, 0}}, sky{{0, 1, 0}}, right{{1.33, 0, 0}};
    std::optional<PovVector> look_at, focal_point;
    std::optional<double> angle, aperture;
    std::optional<int> blur_samples;
    bool sized = false;   // up or right given: an orthographic camera's view is their size
    Transform transform;  // rotate, translate, ... after the vectors
};

struct PovObject;

// POV-Ray's light_source as written, before pov_scene.cpp maps it onto one of glint's lights.
struct PovLight {
    PovPosition at;
    PovVector position{};
    PovVector color{};
    enum class Kind { point, spot, parallel } kind = Kind::point;
    PovVector point_at{};
    double radius = 30, falloff = 45, tightness = 0;
    std::optional<PovVector> area_u, area_v;  // area_light's axes
    int n1 = 1, n2 = 1;                       // and its counts
    bool circular = false;
    std::optional<double> fade_distance;
    double fade_power = 0;
    bool shadowless = false;
    bool media_interaction = true;                // scatters in media
    std::shared_ptr<const PovObject> looks_like;  // drawn at the light, casting no shadow
    Transform transform;
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
    bool inverse = false;  // inside and outside swapped: what a CSG keeps of it turns over
    // clipped_by: an intersection of objects in this object's own space (so that its later
    // transforms move them with it); its surface is kept inside them only.
    std::shared_ptr<const PovObject> clipped_by;
    // bounded_by, read the same way: only a hint to POV-Ray, but the region of a polynomial
    // surface (quartic, poly), which is unbounded.
    std::shared_ptr<const PovObject> bounded_by;
    // "quartic", "poly", ...: a polynomial surface, whose region (its shape's box) is set from
    // its bounded_by or clipped_by objects; without them it cannot be placed.
    std::string polynomial;
    std::shared_ptr<const PovUnread> unread;  // an object glint does not read yet: its name, place
    std::shared_ptr<const PovLight> light;    // a light_source, placed as objects are
    PovPosition at;                           // where it was written
};

// A POV-Ray function { }: glint expression text over its parameters, written $0, $1, ... (x, y
// and z unless it names its own), which a call replaces by its arguments
// (pov_function_reader.cpp). A function glint cannot compute yet (an internal one such as
// f_noise3d, a pattern's or a pigment's) names what stops it in `unsupported`: declaring it is
// fine, using it in an isosurface an error.
struct PovFunction {
    int arity = 3;
    std::string text;
    std::string unsupported;
    PovPosition at;
};

// The function's text with each argument, in parentheses, in place of its parameter.
std::string call_text(const PovFunction& function, const std::vector<std::string>& arguments);

// A map (color_map, pigment_map, ...) that glint does not read yet: kept to stop the scene only
// where it is used.
struct PovUnread {
    std::string what;
    PovPosition at;
};

using PovItem = std::variant<PovObject, PovTexture, PovPigment, PovFinish, PovInterior, Transform,
                             PovUnread, PovCamera, PovColorMap, PovSkySphere, PovMaterial,
                             PovNormal, PovFunction, PovMedium>;

// A declared item as an identifier's value holds it.
struct PovItemRef {
    PovItem item;
};

}  // namespace glint
