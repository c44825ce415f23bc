// A mesh of a million triangles, as the meshes issue asks, through the whole path a user's file
// takes: a binary PLY written to a temporary folder, the model loader (validator, Assimp, BVH),
// a scene that frames it, and a small render. Its speed is the acceleration structures' concern;
// here it must load and render at all, within memory and a few seconds.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "glint/render/render.h"
#include "glint/scene/mesh/model_scene.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

// A wavy height field of n x n quads (2 n^2 triangles) over [-1, 1]^2 in x and y, facing +z
// (where the framing camera looks from), as binary little-endian PLY: float x y z per vertex, a
// uchar count and three int indices per face.
void write_height_field_ply(const fs::path& file, int n) {
    std::ofstream out(file, std::ios::binary);
    const int side = n + 1;
    const std::uint64_t vertices = std::uint64_t(side) * side;
    const std::uint64_t faces = 2 * std::uint64_t(n) * n;
    out << "ply\nformat binary_little_endian 1.0\ncomment glint big mesh test\n"
        << "element vertex " << vertices << "\nproperty float x\nproperty float y\n"
        << "property float z\nelement face " << faces
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    std::vector<char> buffer;
    const auto put = [&](const auto& value) {
        const char* bytes = reinterpret_cast<const char*>(&value);
        buffer.insert(buffer.end(), bytes, bytes + sizeof value);
    };
    for (int i = 0; i < side; ++i) {
        for (int k = 0; k < side; ++k) {
            const float x = -1 + 2.0f * float(k) / float(n), y = -1 + 2.0f * float(i) / float(n);
            put(x);
            put(y);
            put(0.1f * std::sin(6 * x) * std::cos(5 * y));
        }
    }
    const auto triangle = [&](std::int32_t a, std::int32_t b, std::int32_t c) {
        put(std::uint8_t(3));
        put(a), put(b), put(c);
    };
    for (int i = 0; i < n; ++i) {
        for (int k = 0; k < n; ++k) {
            const std::int32_t v = i * side + k;
            triangle(v, v + 1, v + side);  // counter-clockwise seen from +z
            triangle(v + 1, v + side + 1, v + side);
        }
    }
    out.write(buffer.data(), std::streamsize(buffer.size()));
    ASSERT_TRUE(out.good()) << "cannot write " << file;
}

// A folder of its own under the system's temporary one, removed however the test ends.
struct TemporaryFolder {
    fs::path path = fs::temp_directory_path() / ("glint-big-mesh-" + std::to_string(::getpid()));
    TemporaryFolder() { fs::create_directories(path); }
    ~TemporaryFolder() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
};

TEST(BigMesh, AMillionTrianglePlyLoadsAndRenders) {
    const TemporaryFolder dir;
    const fs::path file = dir.path / "height_field.ply";
    constexpr int kQuads = 708;  // 2 x 708^2 = 1,002,528 triangles
    write_height_field_ply(file, kQuads);

    const auto start = std::chrono::steady_clock::now();
    Scene scene = load_model_scene(file);
    std::uint64_t triangles = 0;
    for (const SceneObject& object : scene.objects) {
        if (const auto* mesh = std::get_if<TriangleMesh>(&object.shape))
            triangles += mesh->data->triangles.size();
    }
    EXPECT_EQ(triangles, 2u * kQuads * kQuads);
    scene.settings.width = 32;
    scene.settings.height = 24;
    const RenderResult result = render(World(scene), {});
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    ASSERT_EQ(result.image.width, 32);
    EXPECT_EQ(result.bad_samples.count, 0u);
    // Not empty: the framed height field (a square in the sphere the camera frames) covers a
    // fifth of the image or more, and is lit.
    EXPECT_GT(result.rays.primary_hits, result.rays[RayKind::primary] / 5);
    float brightest = 0;
    for (const Color& c : result.image.pixels) brightest = std::max({brightest, c.r, c.g, c.b});
    EXPECT_GT(brightest, 0.05f);
    // Recorded, not asserted: timing belongs to the benchmarks (DESIGN.md, principle 3).
    RecordProperty("seconds", std::to_string(seconds));
}

}  // namespace
}  // namespace glint
