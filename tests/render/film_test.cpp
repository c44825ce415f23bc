// The film: filter-weighted averages with worked numbers, splats across pixel and tile borders,
// and sums that do not depend on the order or grouping samples arrive in.
#include "glint/render/film/film.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "glint/math/interval.h"

namespace glint {
namespace {

FilterSpec spec_of(FilterKind kind) {
    FilterSpec spec;
    spec.kind = kind;
    spec.radius = default_filter_radius(kind);
    return spec;
}

TEST(Film, BoxFilterAveragesEachPixelsOwnSamples) {
    Film film(2, 1, FilterSpec{});
    FilmTile tile = film.make_tile({0, 0, 2, 1});
    tile.add_sample({0.25f, 0.5f}, {1, 2, 3});
    tile.add_sample({0.75f, 0.25f}, {3, 2, 1});
    tile.add_sample({1.5f, 0.5f}, {0.5f, 0, 0});
    film.merge(tile);
    const Image image = film.resolve();
    EXPECT_EQ(image.at(0, 0), (Color{2, 2, 2}));
    EXPECT_EQ(image.at(1, 0), (Color{0.5f, 0, 0}));
}

TEST(Film, ASampleAddedThroughItsFootprintGivesTheSameSums) {
    // The output variables add each sample through one footprint to many films; each must hold
    // the sums the image's own path gives, bit for bit, for every filter.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0, 1);
    for (const FilterKind kind :
         {FilterKind::box, FilterKind::tent, FilterKind::gaussian, FilterKind::mitchell}) {
        for (const float radius : {0.5f, default_filter_radius(kind)}) {
            const FilterSpec spec{kind, radius};
            Film direct(9, 7, spec), through(9, 7, spec);
            const Tile region{2, 1, 7, 6};
            FilmTile a = direct.make_tile(region), b = through.make_tile(region);
            for (int i = 0; i < 200; ++i) {
                const Point2 p{2 + 5 * u(rng), 1 + 5 * u(rng)};
                const Color c{u(rng), 2 * u(rng), -u(rng)};
                a.add_sample(p, c);
                b.add_sample_through(b.footprint(p), c);
            }
            direct.merge(a);
            through.merge(b);
            const Image x = direct.resolve(), y = through.resolve();
            for (std::size_t i = 0; i < x.pixels.size(); ++i)
                ASSERT_EQ(x.pixels[i], y.pixels[i]) << int(kind) << " " << radius << " " << i;
        }
    }
}

TEST(Film, BoxFilterKeepsASampleOnTheTilesFarEdgeInTheTile) {
    // A jittered offset can round up to 1: the sample at x = 2 still belongs to pixel 1 of the
    // tile [0, 2), never to the next tile's pixel 2.
    Film film(3, 1, FilterSpec{});
    FilmTile left = film.make_tile({0, 0, 2, 1});
    FilmTile right = film.make_tile({2, 0, 3, 1});
    left.add_sample({2.0f, 0.5f}, Color::gray(4));
    right.add_sample({2.5f, 0.5f}, Color::gray(1));
    film.merge(right);
    film.merge(left);
    const Image image = film.resolve();
    EXPECT_EQ(image.at(1, 0), Color::gray(4));
    EXPECT_EQ(image.at(2, 0), Color::gray(1));
}

TEST(Film, BoxFilterAveragesInSampleOrderLikeAPlainSum) {
    // Whitted's images stay bit for bit what a float sum over the samples in order gives.
    Film film(1, 1, FilterSpec{});
    FilmTile tile = film.make_tile({0, 0, 1, 1});
    const Color samples[] = {{0.1f, 0.7f, 1e-3f}, {0.3f, 0.2f, 5.0f}, {0.77f, 0.01f, 0.5f}};
    Color sum;
    for (const Color& c : samples) {
        tile.add_sample({0.5f, 0.5f}, c);
        sum += c;
    }
    film.merge(tile);
    EXPECT_EQ(film.resolve().at(0, 0), sum / 3.0f);
}

TEST(Film, PixelsWithoutSamplesAreBlack) {
    Film film(3, 3, spec_of(FilterKind::gaussian));
    EXPECT_EQ(film.resolve().at(1, 1), Color{});
}

TEST(Film, APixelWhoseWeightsSumBelowZeroIsStillTheirWeightedMean) {
    // Mitchell's negative lobes, importance-sampled, weigh samples -1 or +1 (times a constant):
    // a pixel of few samples may sum to a negative weight. Its value is still the ratio of the
    // sums, which for one colour is that colour; only a pixel whose weights cancel is black.
    Film film(2, 1, spec_of(FilterKind::mitchell), /*importance_sampled=*/true);
    FilmTile tile = film.make_tile({0, 0, 2, 1});
    tile.add_to_pixel(0, 0, -1.0f, {0.5f, 0.25f, 2});
    tile.add_to_pixel(0, 0, -1.0f, {0.5f, 0.25f, 2});
    tile.add_to_pixel(0, 0, 1.0f, {0.5f, 0.25f, 2});
    tile.add_to_pixel(1, 0, -1.0f, {1, 1, 1});
    tile.add_to_pixel(1, 0, 1.0f, {3, 3, 3});
    film.merge(tile);
    const Image image = film.resolve();
    EXPECT_EQ(image.at(0, 0), (Color{0.5f, 0.25f, 2}));
    EXPECT_EQ(image.at(1, 0), Color{});
}

TEST(Film, TentFilterWeighsNeighboursSamplesByDistance) {
    // Tent of radius 1 over pixel centres 0.5 and 1.5: a sample of 1 at x = 0.75 weighs 0.75
    // for pixel 0 and 0.25 for pixel 1, one of 4 at x = 1.25 the other way round. Pixel 0:
    // (0.75 * 1 + 0.25 * 4) / 1 = 1.75; pixel 1: (0.25 * 1 + 0.75 * 4) / 1 = 3.25.
    Film film(2, 1, spec_of(FilterKind::tent));
    FilmTile tile = film.make_tile({0, 0, 2, 1});
    tile.add_sample({0.75f, 0.5f}, Color::gray(1));
    tile.add_sample({1.25f, 0.5f}, Color::gray(4));
    film.merge(tile);
    const Image image = film.resolve();
    EXPECT_FLOAT_EQ(image.at(0, 0).r, 1.75f);
    EXPECT_FLOAT_EQ(image.at(1, 0).r, 3.25f);
}

TEST(Film, SamplesReachPixelsOfTheNeighbouringTiles) {
    // A Gaussian of radius 1.5 around a sample near the right edge of a 2 x 2 tile reaches two
    // pixels into the next tile; the tile's region extends that far.
    Film film(8, 8, spec_of(FilterKind::gaussian));
    FilmTile tile = film.make_tile({0, 0, 2, 2});
    EXPECT_EQ(tile.region().x1, 4);
    EXPECT_EQ(tile.region().y1, 4);
    EXPECT_EQ(tile.region().x0, 0);  // clipped to the image
    tile.add_sample({1.9f, 1.9f}, Color::gray(1));
    film.merge(tile);
    const Image image = film.resolve();
    EXPECT_EQ(image.at(3, 3), Color{});  // its centre is 1.6 away on each axis: outside
    EXPECT_EQ(image.at(2, 2), Color::gray(1));
    EXPECT_EQ(image.at(0, 3), Color{});
}

TEST(Film, ImageDoesNotDependOnHowSamplesAreGroupedOrOrdered) {
    // The same samples split into tiles of two sizes and added in two orders give the same
    // image bit for bit: fixed-point sums are exact.
    std::mt19937 random(5);
    std::uniform_real_distribution<float> unit(0, 1);
    struct Sample {
        Point2 p;
        Color c;
    };
    std::vector<Sample> samples;
    for (int i = 0; i < 4000; ++i)
        samples.push_back({{unit(random) * 16, unit(random) * 12},
                           {unit(random) * 1e3f, unit(random) * 1e-3f, unit(random)}});
    const auto render = [&](int tile_size, bool reverse) {
        Film film(16, 12, spec_of(FilterKind::mitchell));
        std::vector<Sample> order = samples;
        if (reverse) std::reverse(order.begin(), order.end());
        for (int y = 0; y < 12; y += tile_size)
            for (int x = 0; x < 16; x += tile_size) {
                const Tile t{x, y, std::min(x + tile_size, 16), std::min(y + tile_size, 12)};
                FilmTile tile = film.make_tile(t);
                for (const Sample& s : order)
                    if (s.p.x >= t.x0 && s.p.x < t.x1 && s.p.y >= t.y0 && s.p.y < t.y1)
                        tile.add_sample(s.p, s.c);
                film.merge(tile);
            }
        return film.resolve();
    };
    const Image a = render(16, false);
    EXPECT_TRUE(a.pixels == render(5, true).pixels);
    EXPECT_TRUE(a.pixels == render(1, false).pixels);
}

TEST(Film, SmallAndLargeValuesKeepTheirPrecision) {
    Film film(1, 1, FilterSpec{});
    FilmTile tile = film.make_tile({0, 0, 1, 1});
    tile.add_sample({0.5f, 0.5f}, {1e-6f, 1e8f, 0.1f});
    film.merge(tile);
    const Color c = film.resolve().at(0, 0);
    EXPECT_NEAR(c.r, 1e-6, 1e-9);
    EXPECT_EQ(c.g, 1e8f);
    EXPECT_EQ(c.b, 0.1f);
}

TEST(Film, SamplesMustBeFiniteAndWithinTheFixedPointRange) {
    EXPECT_TRUE(is_valid_sample({1, -2, 1e9f}));
    EXPECT_FALSE(is_valid_sample({std::nanf(""), 0, 0}));
    EXPECT_FALSE(is_valid_sample({0, kInfinity, 0}));
    EXPECT_FALSE(is_valid_sample({0, 0, -2e9f}));
}

TEST(BadSamples, KeepTheFirstInScanlineOrder) {
    BadSamples a, b;
    a.add({5, 2, 0});
    b.add({1, 2, 3});
    b.add({9, 1, 0});
    a += b;
    EXPECT_EQ(a.count, 3u);
    EXPECT_EQ(a.first->x, 9);
    EXPECT_EQ(a.first->y, 1);
}

}  // namespace
}  // namespace glint
