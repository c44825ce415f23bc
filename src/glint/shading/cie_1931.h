// The CIE 1931 2-degree standard observer: the colour matching functions x-bar, y-bar, z-bar
// that turn a spectrum into tristimulus values XYZ.
#pragma once

#include <array>

namespace glint {

// CIE XYZ tristimulus values (or the three matching functions at one wavelength).
struct Xyz {
    float x = 0, y = 0, z = 0;
};

// The tabulated range: 95 entries every 5 nm from 360 to 830 nm.
inline constexpr float kCie1931FirstWavelength = 360;  // nm
inline constexpr float kCie1931LastWavelength = 830;   // nm
inline constexpr float kCie1931Step = 5;               // nm
inline constexpr int kCie1931Count = 95;

// The table itself, entry i at 360 + 5 i nm (CIE 15:2004).
const std::array<Xyz, kCie1931Count>& cie_1931_table();

// x-bar, y-bar, z-bar at lambda_nm, interpolated linearly between the table's entries; zero
// outside [360, 830] nm (and for NaN). y-bar peaks at 1 at 555 nm.
Xyz cie_1931(float lambda_nm);

}  // namespace glint
