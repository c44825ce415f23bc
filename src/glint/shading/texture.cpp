// Evaluating a colour source at a surface point: constant, 2D or solid checker, or image lookup.
#include "glint/shading/texture.h"

#include <cmath>

namespace glint {

namespace {

// Parity of one coordinate's cell index; floor() keeps the pattern regular across zero.
// fmod(floor(x), 2) is exact for every float and stays defined where a cast to an integer would
// overflow (huge coordinates over tiny squares); NaN counts as even.
bool odd_index(float x, float size) {
    return std::abs(std::fmod(std::floor(double(x) / size), 2.0)) == 1.0;
}

bool odd_cell(float a, float b, float c, float size) {
    return (odd_index(a, size) ^ odd_index(b, size) ^ odd_index(c, size)) != 0;
}

struct Evaluate {
    const SurfacePoint& sp;

    Color operator()(const Color& c) const { return c; }
    Color operator()(const CheckerTexture& checker) const {
        const bool odd = checker.space == CheckerSpace::uv
                             ? odd_cell(sp.uv.x, sp.uv.y, 0, checker.size)
                             : odd_cell(sp.p.x, sp.p.y, sp.p.z, checker.size);
        return odd ? checker.odd : checker.even;
    }
    Color operator()(const ImageTexture& image) const { return sample(image, sp.uv); }
    Color operator()(const NoiseTexture& noise) const { return glint::evaluate(noise, sp.p); }
};

}  // namespace

Color evaluate(const Texture& texture, const SurfacePoint& sp) {
    return std::visit(Evaluate{sp}, texture);
}

}  // namespace glint
