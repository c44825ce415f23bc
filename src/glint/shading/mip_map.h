// An image and its successive halvings down to one texel (Williams 1983): what a texture lookup
// filtered over a footprint reads, at the level whose texels are as wide as the footprint.
#pragma once

#include <vector>

#include "glint/image/image.h"

namespace glint {

class MipMap {
public:
    // Level 0 is the image itself (not empty); each next level is half as wide and high,
    // rounded up, each texel the mean of the 2x2 texels under it (the last row or column
    // repeated where a size is odd), down to 1x1.
    explicit MipMap(Image base);

    int levels() const { return int(levels_.size()); }
    const Image& level(int i) const { return levels_[std::size_t(i)]; }
    const Image& base() const { return levels_.front(); }

private:
    std::vector<Image> levels_;
};

}  // namespace glint
