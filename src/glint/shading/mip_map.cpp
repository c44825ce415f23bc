// Building the pyramid by 2x2 box filtering.
#include "glint/shading/mip_map.h"

#include <algorithm>
#include <utility>

namespace glint {

namespace {

Image halved(const Image& in) {
    Image out((in.width + 1) / 2, (in.height + 1) / 2);
    for (int y = 0; y < out.height; ++y) {
        const int y0 = 2 * y, y1 = std::min(2 * y + 1, in.height - 1);
        for (int x = 0; x < out.width; ++x) {
            const int x0 = 2 * x, x1 = std::min(2 * x + 1, in.width - 1);
            out.at(x, y) = (in.at(x0, y0) + in.at(x1, y0) + in.at(x0, y1) + in.at(x1, y1)) * 0.25f;
        }
    }
    return out;
}

}  // namespace

MipMap::MipMap(Image base) {
    levels_.push_back(std::move(base));
    while (levels_.back().width > 1 || levels_.back().height > 1)
        levels_.push_back(halved(levels_.back()));
}

}  // namespace glint
