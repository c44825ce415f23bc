// Spectral rendering for dispersion: one wavelength per sample, its weight in linear sRGB through
// the CIE 1931 observer, and how a material's index of refraction varies with wavelength.
#pragma once

#include <array>
#include <string>

#include "glint/math/color.h"
#include "glint/shading/cie_1931.h"

namespace glint {

// The range wavelengths are drawn from: where the CIE 1931 table is defined.
inline constexpr float kMinWavelength = kCie1931FirstWavelength;  // nm
inline constexpr float kMaxWavelength = kCie1931LastWavelength;   // nm

// The wavelength at which an index of refraction is quoted (n_d, the helium d line), and the one
// a ray without a wavelength uses.
inline constexpr float kReferenceWavelength = 587.56f;  // nm

// CIE XYZ to linear sRGB (IEC 61966-2-1, D65 white): D65 white (0.9505, 1, 1.089) maps to
// (1, 1, 1). Colours outside the sRGB gamut get negative channels.
Color xyz_to_linear_srgb(Xyz xyz);

// The linear sRGB response of light of a single wavelength, each channel scaled so that its
// integral over [360, 830] nm is exactly 1: an equal-energy spectrum maps to white (1, 1, 1).
// (Per channel scaling balances the equal-energy white to sRGB's white, in RGB.)
// Contract: for lambda drawn with pdf p(lambda), E[weight(lambda) / p(lambda)] = (1, 1, 1), so
// an RGB colour multiplied channel by channel by weight / pdf is unchanged on average.
// Channels can be negative: most spectral colours lie outside the sRGB gamut (500 nm has a
// negative red). Zero outside [360, 830] nm.
Color wavelength_to_rgb_weight(float lambda_nm);

enum class DispersionModel { none, cauchy, sellmeier };

// How a material's index of refraction depends on wavelength. The coefficients c mean:
//   cauchy:    n = A + B / lambda^2, c = {A, B} with B in um^2 (Cauchy 1836);
//   sellmeier: n^2 = 1 + sum_i B_i lambda^2 / (lambda^2 - C_i), c = {B1, B2, B3, C1, C2, C3}
//              with C_i in um^2 (Sellmeier 1871; the form of glass makers' catalogues).
// lambda is in micrometres in both formulas.
struct Dispersion {
    DispersionModel model = DispersionModel::none;
    std::array<float, 6> c{};
};

// The index of refraction at lambda_nm: ior for the none model (which ignores lambda), else the
// model's formula (which ignores ior). Meaningful where describe_problem(d, ior) is empty;
// otherwise it can be NaN (a Sellmeier n^2 < 0) or not positive.
float refractive_index(const Dispersion& d, float ior, float lambda_nm);

// The two-term Cauchy formula through n_d at the d line (587.56 nm) with Abbe number
// V = (n_d - 1) / (n_F - n_C), F = 486.13 nm, C = 656.27 nm: how glass is usually quoted.
// abbe > 0; the larger, the less dispersion (infinity gives a constant n_d).
Dispersion cauchy_from_abbe(float n_d, float abbe);

// Empty when the index is finite and > 0 everywhere on [360, 830] nm (checked every 1 nm, and
// no Sellmeier pole sqrt(C_i) inside the range), else what is wrong, e.g. "sellmeier
// coefficients give no real index of refraction at 412 nm". An index between 0 and 1 is
// allowed: some materials have one.
std::string describe_problem(const Dispersion& d, float ior);

}  // namespace glint
