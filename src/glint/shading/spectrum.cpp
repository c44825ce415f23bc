// Wavelengths to linear sRGB through the CIE 1931 observer, and indices of refraction that vary
// with wavelength (Cauchy, Sellmeier).
#include "glint/shading/spectrum.h"

#include <cmath>
#include <sstream>

#include "glint/geometry/number_text.h"

namespace glint {

Color xyz_to_linear_srgb(Xyz xyz) {
    // IEC 61966-2-1:1999, the matrix from XYZ (D65) to linear sRGB.
    return {3.2406f * xyz.x - 1.5372f * xyz.y - 0.4986f * xyz.z,
            -0.9689f * xyz.x + 1.8758f * xyz.y + 0.0415f * xyz.z,
            0.0557f * xyz.x - 0.2040f * xyz.y + 1.0570f * xyz.z};
}

namespace {
// 1 / the integral of xyz_to_linear_srgb(cie_1931(lambda)) over [360, 830] nm, per channel.
// The interpolated table is piecewise linear, so the trapezoid rule on its entries is its exact
// integral, and the matrix being linear, the integral of the sRGB response is the matrix times
// the integral of XYZ. Summed in double: the sums are of 95 terms spanning six decades.
Color weight_scale() {
    const auto& table = cie_1931_table();
    double x = 0, y = 0, z = 0;
    for (int i = 0; i < kCie1931Count; ++i) {
        const double w = (i == 0 || i == kCie1931Count - 1) ? 0.5 : 1.0;
        x += w * table[i].x;
        y += w * table[i].y;
        z += w * table[i].z;
    }
    const double step = kCie1931Step;
    const Color integral = xyz_to_linear_srgb({float(x * step), float(y * step), float(z * step)});
    return {1 / integral.r, 1 / integral.g, 1 / integral.b};
}
}  // namespace

Color wavelength_to_rgb_weight(float lambda_nm) {
    static const Color scale = weight_scale();
    return xyz_to_linear_srgb(cie_1931(lambda_nm)) * scale;
}

namespace {
float cauchy_index(const Dispersion& d, float lambda_um) {
    return d.c[0] + d.c[1] / (lambda_um * lambda_um);
}

// n^2 of the Sellmeier formula. A term with B_i = 0 is absent, even at its pole.
float sellmeier_index_squared(const Dispersion& d, float lambda_um) {
    const float l2 = lambda_um * lambda_um;
    float n2 = 1;
    for (int i = 0; i < 3; ++i) {
        if (d.c[i] != 0) n2 += d.c[i] * l2 / (l2 - d.c[i + 3]);
    }
    return n2;
}
}  // namespace

float refractive_index(const Dispersion& d, float ior, float lambda_nm) {
    const float lambda_um = lambda_nm * 1e-3f;
    switch (d.model) {
        case DispersionModel::none:
            return ior;
        case DispersionModel::cauchy:
            return cauchy_index(d, lambda_um);
        case DispersionModel::sellmeier:
            return std::sqrt(sellmeier_index_squared(d, lambda_um));
    }
    return ior;
}

Dispersion cauchy_from_abbe(float n_d, float abbe) {
    // n_F - n_C = (n_d - 1) / V = B (1 / lambda_F^2 - 1 / lambda_C^2), then A from n_d.
    constexpr double kD = 0.58756, kF = 0.48613, kC = 0.65627;  // um
    const double b = (double(n_d) - 1) / abbe / (1 / (kF * kF) - 1 / (kC * kC));
    const double a = n_d - b / (kD * kD);
    Dispersion d{DispersionModel::cauchy, {}};
    d.c[0] = float(a);
    d.c[1] = float(b);
    return d;
}

std::string describe_problem(const Dispersion& d, float ior) {
    std::ostringstream out;
    if (d.model == DispersionModel::none) {
        if (!std::isfinite(ior) || !(ior > 0)) {
            out << "index of refraction must be finite and > 0, got " << number_text(ior);
        }
        return out.str();
    }
    const char* name = d.model == DispersionModel::cauchy ? "cauchy" : "sellmeier";
    const int count = d.model == DispersionModel::cauchy ? 2 : 6;
    for (int i = 0; i < count; ++i) {
        if (!std::isfinite(d.c[i])) {
            out << name << " coefficients must be finite, got " << number_text(d.c[i]);
            return out.str();
        }
    }
    if (d.model == DispersionModel::sellmeier) {
        // Near a pole n^2 runs off to +-infinity, between grid points as much as on them.
        for (int i = 0; i < 3; ++i) {
            const float c = d.c[i + 3];
            const float pole_nm = std::sqrt(c) * 1000;
            if (d.c[i] != 0 && pole_nm >= kMinWavelength && pole_nm <= kMaxWavelength) {
                out << "sellmeier coefficient C" << i + 1 << " = " << number_text(c)
                    << " um^2 puts a pole at " << std::lround(pole_nm) << " nm, inside "
                    << kMinWavelength << "-" << kMaxWavelength << " nm";
                return out.str();
            }
        }
    }
    // A Cauchy index is monotonic in lambda, so the grid's ends bound it; without a pole in the
    // range a Sellmeier one is smooth, and 1 nm steps see where it is not positive.
    for (int lambda = int(kMinWavelength); lambda <= int(kMaxWavelength); ++lambda) {
        const float n = refractive_index(d, ior, float(lambda));
        if (std::isnan(n)) {
            out << name << " coefficients give no real index of refraction at " << lambda << " nm";
            return out.str();
        }
        if (!std::isfinite(n) || !(n > 0)) {
            out << name << " coefficients give an index of refraction of " << number_text(n)
                << " at " << lambda << " nm; it must be finite and > 0";
            return out.str();
        }
    }
    return out.str();
}

}  // namespace glint
