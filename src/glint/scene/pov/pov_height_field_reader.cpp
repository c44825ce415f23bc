// POV-Ray's height_field: an image's grey levels (a palette image's indices) as heights over the
// unit square, onto glint's triangle mesh. Two triangles a cell split as POV-Ray splits them, and
// with `smooth` the normals POV-Ray averages at each point of the grid.
#include <cmath>

#include "glint/image/srgb.h"
#include "glint/scene/pov/pov_item_reader.h"

namespace glint {

namespace {

// POV-Ray reads heights from the file's values, not from linear light: the image's grey level
// encoded again, 0 to 1.
float height_of(Color linear) {
    const float grey = 0.299f * linear_to_srgb(linear.r) + 0.587f * linear_to_srgb(linear.g) +
                       0.114f * linear_to_srgb(linear.b);
    return std::clamp(grey, 0.0f, 1.0f);
}

}  // namespace

Shape PovItemReader::height_field(const PovToken& keyword) {
    std::optional<PaletteImage> palette;
    const Image image = image_file(keyword, &palette);
    if (image.width < 2 || image.height < 2)
        throw parser_.error_at(keyword, "a height_field's image must be at least 2 x 2 pixels");
    bool smooth = false;
    float water = 0;
    for (;;) {
        const PovToken& ahead = parser_.peek_item();
        if (ahead.is_word("smooth")) {
            parser_.next();
            smooth = true;
        } else if (ahead.is_word("water_level")) {
            parser_.next();
            const PovToken at = parser_.peek();
            water = number("after water_level");
            if (!(water >= 0 && water <= 1))
                throw parser_.error_at(at, "water_level must be in [0, 1]");
        } else if (ahead.is_word("hierarchy") || ahead.is_word("premultiplied")) {
            parser_.next();
            optional_amount();
        } else if (ahead.is_word("gamma")) {
            parser_.next();
            parser_.finite_float("after gamma");
            read_past("gamma in a height_field", "heights are the file's grey levels");
        } else {
            break;
        }
    }
    // Point (x, z) of the grid, z = 0 at the image's bottom row, over the unit square.
    const int w = image.width, h = image.height;
    // A palette image's heights are its indices, as POV-Ray reads them (index 255 is 255/256).
    std::vector<float> heights(std::size_t(w) * std::size_t(h));
    for (int z = 0; z < h; ++z)
        for (int x = 0; x < w; ++x) {
            const std::size_t pixel = std::size_t(h - 1 - z) * std::size_t(w) + std::size_t(x);
            heights[std::size_t(z) * std::size_t(w) + std::size_t(x)] =
                palette ? float(palette->indices[pixel]) / 256 : height_of(image.pixels[pixel]);
        }
    const auto height = [&](int x, int z) {
        return heights[std::size_t(z) * std::size_t(w) + std::size_t(x)];
    };
    MeshData arrays;
    for (int z = 0; z < h; ++z)
        for (int x = 0; x < w; ++x)
            arrays.positions.push_back(
                {float(x) / float(w - 1), height(x, z), float(z) / float(h - 1)});
    const auto index = [w](int x, int z) { return std::uint32_t(z * w + x); };
    for (int z = 0; z + 1 < h; ++z)
        for (int x = 0; x + 1 < w; ++x) {
            // The cell's diagonal runs from (x + 1, z) to (x, z + 1); wound to face up.
            const std::array<std::uint32_t, 3> low{index(x, z), index(x, z + 1), index(x + 1, z)};
            const std::array<std::uint32_t, 3> high{index(x + 1, z + 1), index(x + 1, z),
                                                    index(x, z + 1)};
            for (const auto& t : {low, high}) {
                const bool drowned = arrays.positions[t[0]].y < water &&
                                     arrays.positions[t[1]].y < water &&
                                     arrays.positions[t[2]].y < water;
                if (!drowned) arrays.triangles.push_back(t);
            }
        }
    if (smooth) {
        // As POV-Ray: the four triangles' normals round each point, found in the grid's own
        // units (a pixel across, 65535 up), each turned up and normalised, their sum normalised,
        // then carried into the unit square.
        const auto grid = [&](int x, int z) {
            return Vector3{float(x), 65535 * height(x, z), float(z)};
        };
        for (int z = 0; z < h; ++z)
            for (int x = 0; x < w; ++x) {
                Vector3 sum;
                const int around[4][4] = {
                    {1, 0, 0, 1}, {0, 1, -1, 0}, {-1, 0, 0, -1}, {0, -1, 1, 0}};
                for (const auto& a : around) {
                    const int x1 = x + a[0], z1 = z + a[1], x2 = x + a[2], z2 = z + a[3];
                    if (x1 < 0 || x2 < 0 || z1 < 0 || z2 < 0 || x1 >= w || x2 >= w || z1 >= h ||
                        z2 >= h)
                        continue;
                    Vector3 n = cross(grid(x2, z2) - grid(x, z), grid(x1, z1) - grid(x, z));
                    if (n.y < 0) n = -n;
                    if (length(n) > 0) sum += normalize(n);
                }
                const Vector3 unit{sum.x * float(w - 1), sum.y * 65535, sum.z * float(h - 1)};
                arrays.normals.push_back(Normal3(length(unit) > 0 ? unit : Vector3{0, 1, 0}));
            }
    }
    MeshBuild built = build_mesh(std::move(arrays));
    if (!built.mesh) throw parser_.error_at(keyword, "height_field: " + built.error);
    return TriangleMesh{built.mesh};
}

}  // namespace glint
