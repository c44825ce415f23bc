// The keys of each light (docs/scene-format.md, "lights").
#include "glint/scene/scene_limits.h"
#include "glint/scene/schema/schema_tables.h"

namespace glint {

namespace {

const KeySchema kPosition{"position", "point", "required", "where the light is", ""};
const KeySchema kColor{"color", "color", "1 (white)", "the light's colour", "channels >= 0"};
const KeySchema kIntensity{"intensity", "number", "1", "multiplies `color`", ">= 0", kNonNegative};
const KeySchema kAttenuation{
    "attenuation", "`[constant, linear, quadratic]`", "`[1, 0, 0]` (none)",
    "intensity at distance d is `color / (constant + linear·d + quadratic·d²)`",
    "each >= 0, not all zero"};
const KeySchema kShadowRays{
    "shadow_rays",
    "integer",
    "`image.shadow_rays`",
    "shadow rays each sample sends to the light; stratified together with the other samples'",
    "1..4096",
    Range{1, kMaxShadowRays}};
const KeySchema kVisible{"visible", "bool", "true",
                         "the light's face is an object that the camera and mirrors see, glowing "
                         "in `color × intensity`; it casts no shadow",
                         ""};
const KeySchema kShadows{"shadows", "bool", "true",
                         "whether objects shadow the light; `false` lights every surface facing "
                         "it, as POV-Ray's `shadowless` fill lights (the Whitted family and path "
                         "tracing's light samples; particles from the light still stop at objects)",
                         ""};
const KeySchema kInMedia{"in_media", "bool", "true",
                         "whether the light scatters in participating media ([participating "
                         "media](#participating-media)); POV-Ray's `media_interaction`",
                         ""};
const KeySchema kMotion{"motion", "list of keyframes", "none",
                        "moves the light from frame to frame: see [animation](#animation)", ""};
const KeySchema kAreaAttenuation{"attenuation", "`[constant, linear, quadratic]`",
                                 "`[1, 0, 0]` (none)",
                                 "intensity at distance d is `color / (constant + linear·d + "
                                 "quadratic·d²)`, d the distance to the point drawn",
                                 "each >= 0, not all zero"};

// An area light: its shape's keys, then those every area light takes.
EntitySchema area_light(std::string_view name, std::vector<KeySchema> keys) {
    keys.insert(keys.end(), {kShadowRays, kVisible, kColor, kIntensity, kAreaAttenuation, kShadows,
                             kInMedia, kMotion});
    return {EntityFamily::light, name, std::move(keys)};
}

}  // namespace

std::vector<EntitySchema> light_schemas() {
    return {
        {EntityFamily::light,
         "point",
         {
             kPosition,
             kColor,
             kIntensity,
             kAttenuation,
             kShadows,
             kInMedia,
             kMotion,
         }},
        {EntityFamily::light,
         "directional",
         {
             {"direction", "vector", "required",
              "the way the light travels (e.g. `[0, -1, 0]` shines down); normalised", "non-zero"},
             kColor,
             kIntensity,
             kShadows,
             kInMedia,
             kMotion,
         }},
        {EntityFamily::light,
         "spot",
         {
             kPosition,
             {"direction", "vector", "`at` or `direction` required",
              "the cone's axis, the way it points; normalised", "non-zero"},
             {"at", "point", "`at` or `direction` required", "a point the cone's axis aims at",
              "not `position`"},
             {"cone_angle", "number", "30", "half-angle of the lit cone, degrees: dark beyond",
              "(0, 90]", Range{0, 90, true, false}},
             {"falloff", "number", "5 (at most `cone_angle`)",
              "width of the soft rim inside the cone, degrees: full intensity within `cone_angle − "
              "falloff`, a smoothstep in cos(angle) across the rim",
              "[0, `cone_angle`]", Range{0, 90}},
             {"tightness", "number", "0",
              "how the intensity gathers towards the axis: cos(angle)^tightness across the cone "
              "(POV-Ray's); 0 is even",
              ">= 0", kNonNegative},
             kColor,
             kIntensity,
             kAttenuation,
             kShadows,
             kInMedia,
             kMotion,
         }},
        area_light("sphere",
                   {
                       {"center", "point", "required", "the sphere's centre", ""},
                       {"radius", "number", "required", "the sphere's radius", "> 0", kPositive},
                   }),
        area_light("disk",
                   {
                       {"center", "point", "required", "the disk's centre", ""},
                       {"normal", "vector", "`[0, -1, 0]`",
                        "the disk's normal (it shines to both sides); normalised", "non-zero"},
                       {"radius", "number", "required", "the disk's radius", "> 0", kPositive},
                   }),
        area_light("rectangle",
                   {
                       {"center", "point", "required", "the rectangle's centre", ""},
                       {"u", "vector", "required", "its first side, full length", "non-zero"},
                       {"v", "vector", "required",
                        "its second side, full length (perpendicular to `u` for a rectangle, "
                        "else a parallelogram)",
                        "non-zero, not parallel to `u`"},
                   }),
    };
}

}  // namespace glint
