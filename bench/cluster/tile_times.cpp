// The seconds each piece of a render takes on one thread, for the cluster's scale model
// (model.py): every tile of the scene through its first pass, one at a time.
//   tile_times SCENE WIDTH HEIGHT SPP_A_PASS > times.json
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "glint/render/render.h"
#include "glint/render/tiles.h"
#include "glint/scene/load_scene.h"

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: tile_times SCENE WIDTH HEIGHT SPP_A_PASS\n");
        return 2;
    }
    glint::Scene scene = glint::load_scene(argv[1]);
    scene.settings.width = std::atoi(argv[2]);
    scene.settings.height = std::atoi(argv[3]);
    scene.settings.samples_per_pixel = std::atoi(argv[4]);
    const glint::World world(std::move(scene));
    glint::RenderOptions options;
    options.threads = 1;
    options.pass_size = world.settings().samples_per_pixel;  // one pass
    glint::RenderState state = glint::initial_state(world.settings(), options);
    const auto tiles =
        glint::make_tiles(world.settings().width, world.settings().height, options.tile_size);
    std::printf("{\"scene\": \"%s\", \"width\": %d, \"height\": %d, \"spp\": %d, \"seconds\": [",
                argv[1], world.settings().width, world.settings().height,
                world.settings().samples_per_pixel);
    for (std::size_t t = 0; t < tiles.size(); ++t) {
        const glint::WorkPiece piece{0, int(t)};
        const auto start = std::chrono::steady_clock::now();
        glint::render_pieces(world, options, state, {&piece, 1});
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("%s%.6g", t ? ", " : "", s);
    }
    std::printf("]}\n");
    return 0;
}
