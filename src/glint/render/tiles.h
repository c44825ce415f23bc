// The image cut into square tiles: the unit of parallel work.
#pragma once

#include <algorithm>
#include <vector>

namespace glint {

struct Tile {
    int x0, y0, x1, y1;  // pixels [x0, x1) x [y0, y1)
};

// Tiles in scanline order; those on the right and bottom edges may be smaller.
inline std::vector<Tile> make_tiles(int width, int height, int tile_size) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += tile_size)
        for (int x = 0; x < width; x += tile_size)
            tiles.push_back(
                {x, y, std::min(x + tile_size, width), std::min(y + tile_size, height)});
    return tiles;
}

}  // namespace glint
