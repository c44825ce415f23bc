#include "glint/shading/texture.h"

#include <cmath>

namespace glint {

namespace {

// Parity of the cell index; floor() keeps the pattern regular across zero.
bool odd_cell(float a, float b, float c, float size) {
    const auto cell = static_cast<long long>(std::floor(a / size)) +
                      static_cast<long long>(std::floor(b / size)) +
                      static_cast<long long>(std::floor(c / size));
    return (cell & 1) != 0;
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
};

}  // namespace

Color evaluate(const Texture& texture, const SurfacePoint& sp) {
    return std::visit(Evaluate{sp}, texture);
}

}  // namespace glint
