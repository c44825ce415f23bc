// The classic material of the lecture notes: Phong's local model plus the weights of the
// reflected and refracted rays of Whitted's recursion.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/math/color.h"
#include "glint/shading/angular_reflection.h"
#include "glint/shading/interior_fade.h"
#include "glint/shading/medium.h"
#include "glint/shading/normal_pattern.h"
#include "glint/shading/spectrum.h"
#include "glint/shading/texture.h"

namespace glint {

// How the highlight is measured: Phong's (R.V)^n or Blinn's (H.N)^n.
enum class Highlight { blinn, phong };

// Solid noise that varies reflect, roughness and transmit_roughness over the surface (in place
// of the material's constants), and a bump map or a normal pattern that tilts the shading
// normal (the bump map first).
struct MaterialMaps {
    std::optional<NoiseScalar> reflect, roughness, transmit_roughness;
    std::optional<BumpMap> bump;
    std::optional<NormalPattern> normal_pattern;
    // Light the surface gives off in its own colour C (a layered texture's ambient blend), as
    // C times this, on top of the material's emission (POV-Ray's emission of a pigment that
    // varies). Such an object is seen and lights the scene by the rays that find it, but no
    // shadow ray aims at it.
    Color color_emission;
};

struct Material {
    std::string name;
    Texture color = Color{1, 1, 1};  // the surface colour; scales the ambient and diffuse terms
    float ka = 0.1f;                 // ambient coefficient
    float kd = 0.7f;                 // diffuse coefficient
    float ks = 0;                    // specular (highlight) coefficient
    float shininess = 20;            // highlight exponent n
    // POV-Ray's finish: the exponent b of the diffuse term's (N.L)^b (1: Lambert's cosine), and
    // how far the highlight takes the surface colour, from white (0) to the colour (1). The
    // local model of the Whitted family reads them.
    float brilliance = 1;
    float metallic = 0;
    Highlight highlight = Highlight::blinn;
    float reflect = 0;  // kr, weight of the mirror-reflected ray (at grazing incidence)
    // When kr varies with the angle of incidence: its value facing the viewer and how it runs
    // to `reflect` (angular_reflection.h). None for most materials.
    std::optional<AngularReflection> reflect_angular;
    // The mirror reflection's colour: kr of each channel is reflect times it (gold reflects
    // more red than blue). Channels in [0, 1].
    Color reflect_color{1, 1, 1};
    // How far the reflection takes the surface colour facing the viewer, 0 to 1; none at
    // grazing incidence (POV-Ray's metallic reflection).
    float reflect_metallic = 0;
    float transmit = 0;  // kt, weight of the refracted ray
    // How much of the transmitted light takes the surface colour C, as coloured glass filters
    // it: the refracted ray weighs kt ((1 - tint) + tint C). POV-Ray's filter.
    float tint = 0;
    // How light fades on its way through the object's inside (interior_fade.h).
    InteriorFade fade;
    // The participating media filling the object's inside (medium.h); none for most.
    std::vector<Medium> media;
    // Whether the object's inside, when it holds no media, holds those of the object around it
    // (POV-Ray's hollow): else it keeps them out.
    bool hollow = false;
    // Whether kt splits by Fresnel's equations into reflected (kt F) and refracted (kt (1 - F)).
    bool fresnel = false;
    float ior = 1;  // index of refraction inside (outside: the enclosing object's, or 1)
    // How the index varies with wavelength; with a model, ior is its value at the d line
    // (kReferenceWavelength), which rays that carry no wavelength use.
    Dispersion dispersion;
    // Spread of the reflected and of the refracted ray over a lobe, 0 (a mirror, clear glass)
    // to 1, for the integrators that sample lobes: blurred mirrors and frosted glass.
    float roughness = 0;
    float transmit_roughness = 0;
    Color emission;  // added to the surface's own light, unaffected by lights and shadows
    // Whether both sides of the surface emit, or only its front (the side its normal points
    // to), as an area light set into a ceiling does.
    bool emits_both_sides = true;
    // What varies over the surface, when anything does; null for most materials, so that a hit
    // on them asks one question.
    std::shared_ptr<const MaterialMaps> maps;
};

// Whether the surface gives off light anywhere: a constant emission, or one in its colour.
inline bool emits(const Material& m) {
    return !is_black(m.emission) || (m.maps && !is_black(m.maps->color_emission));
}

}  // namespace glint
