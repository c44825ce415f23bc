// The keys of the material map, its textures and its pattern maps (docs/scene-format.md,
// "materials").
#include "glint/scene/schema/schema_tables.h"
#include "glint/shading/noise.h"

namespace glint {

namespace {

const KeySchema kNoiseScale{
    "scale", "number", "1", "size of one feature (a vein, a ring, a noise cell) in scene units",
    "> 0",   kPositive};
const KeySchema kNoiseTurbulence{
    "turbulence",   "number",
    "1 (wood 0.2)", "marble and wood: how far turbulence moves the veins or rings, in features",
    ">= 0",         kNonNegative};
const KeySchema kNoiseOctaves{
    "octaves", "integer", "6", "noise octaves summed", "1..30", Range{1, kMaxOctaves}};
const KeySchema kPatternType{"type", "string", "required", "the pattern, as for the textures above",
                             "`fbm`, `granite`, `marble`, `turbulence`, `wood`"};

// The solid noise textures share their keys (and their table in the docs).
const std::vector<KeySchema> kNoiseTextureKeys{
    {"type", "string", "required",
     "`marble`: veins across x, 0.5 + 0.5 sin(2π(x + turbulence · turb(p))); `wood`: rings around "
     "the y axis; `granite`: speckles of high-frequency turbulence (values mostly 0.1–0.4, as "
     "POV-Ray's); `turbulence`: Σ\\|noise(2ⁱp)\\|/2ⁱ; `fbm`: 0.5 + 0.5 Σ noise(2ⁱp)/2ⁱ",
     ""},
    kNoiseScale,
    kNoiseTurbulence,
    kNoiseOctaves,
    {"colors", "list of colours",
     "per pattern (white marble with grey veins, light and dark wood, grey granite, black to "
     "white)",
     "the ramp's stops, the first at 0 and the last at 1", "at least 2"},
};

}  // namespace

std::vector<EntitySchema> material_schemas() {
    return {
        {EntityFamily::material,
         "material",
         {
             {"color", "color or texture", "1 (white)",
              "the surface colour; scales the ambient and diffuse terms", "channels >= 0"},
             {"ka", "number", "0.1", "ambient coefficient", ">= 0", kNonNegative},
             {"kd", "number", "0.7", "diffuse coefficient", ">= 0", kNonNegative},
             {"ks", "number", "0", "specular (highlight) coefficient", ">= 0", kNonNegative},
             {"shininess", "number", "20", "highlight exponent n", ">= 0", kNonNegative},
             {"brilliance", "number", "1",
              "exponent b of the diffuse term's (N·L)^b, POV-Ray's brilliance: above 1 the light "
              "falls off faster towards the shadow's edge, as on metal",
              ">= 0", kNonNegative},
             {"metallic", "number", "0",
              "how far the highlight takes the surface colour, from white (0) to the colour (1)",
              "[0, 1]", kUnitInterval},
             {"highlight", "string", "`blinn`",
              "how the highlight is measured: `blinn` is (H·N)^n, `phong` is (R·V)^n",
              "`blinn`, `phong`"},
             {"reflect", "number", "0", "kr, weight of the mirror-reflected ray", "[0, 1]",
              kUnitInterval},
             {"reflect_color", "color", "1 (white)",
              "the reflection's colour: each channel's kr is `reflect` times it (gold reflects "
              "more "
              "red than blue)",
              "channels in [0, 1]"},
             {"reflect_facing", "number", "`reflect` (0 with `reflect_fresnel`)",
              "kr where the viewer looks along the normal; `reflect` is then kr at grazing "
              "incidence, and kr runs between them with the angle ([reflection that varies with "
              "the angle](#reflection-that-varies-with-the-angle))",
              "[0, 1]", kUnitInterval},
             {"reflect_falloff", "number", "1",
              "kr = facing + (reflect − facing) (1 − cos θ)^falloff", "> 0", kPositive},
             {"reflect_fresnel", "bool", "false",
              "kr runs from `reflect_facing` to `reflect` by Fresnel's reflectance of a dielectric "
              "of the object's `ior` instead",
              ""},
             {"reflect_metallic", "number", "0",
              "how far the reflection takes the surface colour facing the viewer (none at grazing "
              "incidence), as metal's does; POV-Ray's metallic reflection",
              "[0, 1]", kUnitInterval},
             {"transmit", "number", "0", "kt, weight of the refracted ray", "[0, 1]",
              kUnitInterval},
             {"tint", "number", "0",
              "how much of the transmitted light takes the surface colour C, as coloured glass "
              "filters it: the refracted ray (and a transparent shadow) weighs kt ((1 − tint) + "
              "tint C); POV-Ray's filter",
              "[0, 1]", kUnitInterval},
             {"fade_distance", "number", "0 (none)",
              "light travelling d through the object's inside fades ([interior "
              "fade](#interior-fade)): to exp(−1), or with `fade_power` to half, at this distance",
              ">= 0", kNonNegative},
             {"fade_power", "number", "exponential",
              "p of the fade c + (1 − c) / (1 + (d / fade_distance)^p); unless given, or from 1000 "
              "on, Beer–Lambert's exp(−(1 − c) d / fade_distance)",
              ">= 0", kNonNegative},
             {"fade_color", "color", "0 (black)",
              "c, the colour that passes unfaded: its complement fades", "channels in [0, 1]"},
             {"medium_absorption", "color", "0 (none)",
              "what the object's inside absorbs per unit length ([participating "
              "media](#participating-media))",
              "channels >= 0"},
             {"medium_emission", "color", "0 (none)",
              "the light the object's inside gives off per unit length", "channels >= 0"},
             {"medium_scattering", "color", "0 (none)",
              "what the object's inside scatters per unit length of the light it is lit by",
              "channels >= 0"},
             {"medium_phase", "string", "`isotropic`",
              "how the scattered light spreads over the directions: evenly, by Rayleigh's law, "
              "Mie's hazy or murky approximations, or Henyey and Greenstein's function",
              "`isotropic`, `rayleigh`, `mie_hazy`, `mie_murky`, `henyey_greenstein`"},
             {"medium_eccentricity", "number", "0",
              "g of `henyey_greenstein`: > 0 scatters forwards, < 0 backwards", "(-1, 1)",
              Range{-1, 1, true, true}},
             {"medium_extinction", "number", "1",
              "how much of what it scatters the medium takes from the light crossing it", "[0, 1]",
              kUnitInterval},
             {"medium_samples", "integer", "10",
              "points a ray through the medium is evaluated at, one in each of as many equal "
              "intervals",
              "1..1000", Range{1, 1000}},
             {"hollow", "bool", "false",
              "whether the object's inside, when it holds no medium, holds that of the object "
              "around it (POV-Ray's hollow); else it keeps it out",
              ""},
             {"ior", "number", "1",
              "index of refraction inside the object; outside it is that of the object around it "
              "([nested media](#nested-media)), or 1 (vacuum)",
              "> 0", kPositive},
             {"fresnel", "bool", "false",
              "split `transmit` by Fresnel's equations for a dielectric: kt F reflects (added to "
              "`reflect`'s ray) and kt (1 − F) refracts, F the reflectance at the angle of "
              "incidence for the indices on both sides",
              ""},
             {"dispersion", "glass name or map", "none",
              "how `ior` varies with wavelength ([dispersion](#dispersion)): `n-bk7`, `n-sf11`, "
              "`fused-silica`, `{abbe: V}`, `{cauchy: [A, B]}` or `{sellmeier: [B1, B2, B3, C1, "
              "C2, C3]}`",
              "see there"},
             {"roughness", "number", "0",
              "with `distributed`: spreads the reflected ray over a glossy lobe, from 0 (a mirror) "
              "to 1 (the whole hemisphere) ([glossy reflection and "
              "translucency](#glossy-reflection-and-translucency)); `whitted` reflects as a mirror",
              "[0, 1]", kUnitInterval},
             {"transmit_roughness", "number", "`roughness`",
              "the same for the refracted ray: frosted glass", "[0, 1]", kUnitInterval},
             {"emission", "color", "0",
              "light the surface gives off itself, unaffected by lights and shadows; with "
              "`distributed`, the object also lights the scene ([objects that emit "
              "light](#objects-that-emit-light))",
              "channels >= 0"},
             {"emission_sides", "string", "`both`",
              "which sides of the surface emit: `both`, or `front`, the side its normal points to "
              "(a triangle's or polygon's counter-clockwise side, a sphere's outside), as a light "
              "set into a ceiling emits only into the room",
              "`both`, `front`"},
             {"bump", "pattern map", "none",
              "tilts the shading normal by Blinn's bump mapping, as if the surface were moved "
              "along its normal by a pattern ([textures](#textures))",
              "a map of a pattern's keys and `strength`"},
         }},
        {EntityFamily::texture,
         "checker",
         {
             {"type", "string", "required", "the texture type", "`checker`"},
             {"even", "color", "1 (white)", "colour of the squares whose index sum is even",
              "channels >= 0"},
             {"odd", "color", "0 (black)", "colour of the other squares", "channels >= 0"},
             {"size", "number", "1",
              "edge of one square: uv units for `uv`, scene units for `solid`", "> 0", kPositive},
             {"space", "string", "`solid`",
              "`solid` carves the pattern out of 3D space (a solid texture); `uv` paints it on the "
              "surface's uv coordinates",
              "`solid`, `uv`"},
         }},
        {EntityFamily::texture,
         "image",
         {
             {"type", "string", "required", "the texture type", "`image`"},
             {"file", "string", "required",
              "PNG, JPEG, HDR, TGA, BMP, OpenEXR (`.exr`) or PFM (`.pfm`), relative to the scene "
              "file; 8- and 16-bit images are sRGB-decoded to linear, HDR, EXR and PFM stay linear",
              "a readable image in the folders the scene may read ([general "
              "rules](#general-rules))"},
             {"scale", "color", "1", "multiplies every texel", "channels >= 0"},
             {"wrap", "string", "`repeat`", "what uv outside [0, 1] reads", "`repeat`, `clamp`"},
             {"filter", "string", "`trilinear`",
              "how texels are blended: over the footprint of the pixel that looks them up "
              "(`trilinear`, `ewa`), or at a point (`bilinear`, `nearest`)",
              "`trilinear`, `ewa`, `bilinear`, `nearest`"},
         }},
        {EntityFamily::texture, "fbm", kNoiseTextureKeys},
        {EntityFamily::texture, "granite", kNoiseTextureKeys},
        {EntityFamily::texture, "marble", kNoiseTextureKeys},
        {EntityFamily::texture, "turbulence", kNoiseTextureKeys},
        {EntityFamily::texture, "wood", kNoiseTextureKeys},
        {EntityFamily::pattern,
         "value",
         {
             kPatternType,
             kNoiseScale,
             kNoiseTurbulence,
             kNoiseOctaves,
             {"low", "number", "0", "the value where the pattern is 0", "within the key's range"},
             {"high", "number", "1", "the value where the pattern is 1", "within the key's range"},
         }},
        {EntityFamily::pattern,
         "bump",
         {
             kPatternType,
             kNoiseScale,
             kNoiseTurbulence,
             kNoiseOctaves,
             {"strength", "number", "0.05",
              "how far the surface seems moved at the pattern's 1, scene units; negative presses "
              "it in",
              ""},
         }},
    };
}

}  // namespace glint
