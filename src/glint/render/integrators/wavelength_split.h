// Dispersion's split of a ray that carries every wavelength (wavelength 0): at a surface that
// disperses and transmits, what refracts takes one wavelength, drawn from the visible range, and
// counts by that wavelength's colour over the density it was drawn with. Every integrator splits
// rays so; the distributed ones draw from the sample's wavelength dimension, particles from their
// next number.
#pragma once

#include "glint/math/color.h"
#include "glint/sampling/warp.h"
#include "glint/shading/material.h"
#include "glint/shading/spectrum.h"

namespace glint {

struct WavelengthSplit {
    float wavelength = 0;   // the ray's own, or the one drawn
    Color weight{1, 1, 1};  // what the refracted part counts by: 1, or the drawn colour / pdf
    bool drawn = false;
    float u = 0;  // the number it was drawn from, when drawn
};

// The split of a ray of `wavelength` meeting m; draw_u() gives the number to draw with, and is
// called only when the ray splits, so that nothing else draws a number.
template <class DrawU>
WavelengthSplit split_wavelength(const Material& m, float wavelength, DrawU draw_u) {
    WavelengthSplit split;
    split.wavelength = wavelength;
    if (m.dispersion.model == DispersionModel::none || !(m.transmit > 0) || wavelength != 0)
        return split;
    split.drawn = true;
    split.u = draw_u();
    split.wavelength = sample_visible_wavelength(split.u);
    split.weight =
        wavelength_to_rgb_weight(split.wavelength) / visible_wavelength_pdf(split.wavelength);
    return split;
}

}  // namespace glint
