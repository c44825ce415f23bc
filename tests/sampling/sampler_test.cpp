// The sampler's patterns: pure functions of their coordinates, stratified as each kind promises
// (grid cells, the fine grid's rows and columns, elementary intervals), for any sample count.
#include "glint/sampling/sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "glint/sampling/random.h"
#include "glint/sampling/warp.h"

namespace glint {
namespace {

std::vector<Point2> pattern(const Sampler& s, std::uint64_t pixel, std::uint32_t count,
                            std::uint32_t dimension) {
    std::vector<Point2> points;
    for (std::uint32_t i = 0; i < count; ++i)
        points.push_back(s.get_2d(pixel, i, count, dimension));
    return points;
}

void expect_in_unit_square(const std::vector<Point2>& points) {
    for (const Point2& p : points) {
        ASSERT_GE(p.x, 0);
        ASSERT_LT(p.x, 1);
        ASSERT_GE(p.y, 0);
        ASSERT_LT(p.y, 1);
    }
}

// Whether each of the columns x rows cells holds at most one point (exactly one when there are
// as many points as cells).
bool one_per_cell(const std::vector<Point2>& points, int columns, int rows) {
    std::set<int> cells;
    for (const Point2& p : points) cells.insert(int(p.y * rows) * columns + int(p.x * columns));
    return cells.size() == points.size();
}

TEST(Sampler, OneRegularSampleSitsAtThePixelCentre) {
    const Sampler sampler(SamplerKind::regular, 1, 0);
    EXPECT_EQ(sampler.get_2d(0, 0, 1, kPixelDimension), (Point2{0.5f, 0.5f}));
    EXPECT_EQ(sampler.get_2d(5, 0, 1, kLensDimension), (Point2{0.5f, 0.5f}));
    EXPECT_EQ(sampler.get_1d(5, 0, 1, kTimeDimension), 0.5f);
}

TEST(Sampler, RegularPixelPositionsAreGridCentresInScanlineOrder) {
    const Sampler sampler(SamplerKind::regular, 9, 0);
    EXPECT_EQ(sampler.get_2d(3, 0, 9, kPixelDimension), (Point2{1 / 6.0f, 1 / 6.0f}));
    EXPECT_EQ(sampler.get_2d(3, 4, 9, kPixelDimension), (Point2{0.5f, 0.5f}));
    EXPECT_EQ(sampler.get_2d(3, 5, 9, kPixelDimension), (Point2{5 / 6.0f, 0.5f}));
    EXPECT_EQ(sampler.get_2d(3, 8, 9, kPixelDimension), (Point2{5 / 6.0f, 5 / 6.0f}));
}

TEST(Sampler, RegularOtherDimensionsVisitTheSameCentresInAnotherOrder) {
    const Sampler sampler(SamplerKind::regular, 16, 7);
    std::vector<Point2> pixel = pattern(sampler, 2, 16, kPixelDimension);
    std::vector<Point2> lens = pattern(sampler, 2, 16, kLensDimension);
    EXPECT_NE(pixel, lens);
    const auto order = [](Point2 a, Point2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; };
    std::sort(pixel.begin(), pixel.end(), order);
    std::sort(lens.begin(), lens.end(), order);
    EXPECT_EQ(pixel, lens);
}

TEST(Sampler, RegularNeedsASquareCountTheOthersAny) {
    EXPECT_TRUE(is_valid_sample_count(SamplerKind::regular, 1));
    EXPECT_TRUE(is_valid_sample_count(SamplerKind::regular, 16));
    EXPECT_FALSE(is_valid_sample_count(SamplerKind::regular, 2));
    EXPECT_FALSE(is_valid_sample_count(SamplerKind::regular, 0));
    for (const SamplerKind kind : {SamplerKind::jittered, SamplerKind::sobol}) {
        EXPECT_TRUE(is_valid_sample_count(kind, 5));
        EXPECT_TRUE(is_valid_sample_count(kind, 1));
        EXPECT_FALSE(is_valid_sample_count(kind, 0));
    }
}

TEST(Sampler, ValuesArePureFunctionsOfPixelSampleDimensionAndSeed) {
    for (const SamplerKind kind : {SamplerKind::jittered, SamplerKind::sobol}) {
        const Sampler a(kind, 16, 42), b(kind, 16, 42), other_seed(kind, 16, 43);
        EXPECT_EQ(a.get_2d(9, 3, 16, 5), b.get_2d(9, 3, 16, 5));
        EXPECT_EQ(a.get_1d(9, 3, 16, 5), b.get_1d(9, 3, 16, 5));
        EXPECT_NE(a.get_2d(9, 3, 16, 5), other_seed.get_2d(9, 3, 16, 5));
        EXPECT_NE(a.get_2d(9, 3, 16, 5), a.get_2d(10, 3, 16, 5));  // another pixel
        EXPECT_NE(a.get_2d(9, 3, 16, 5), a.get_2d(9, 3, 16, 6));   // another dimension
    }
}

TEST(Sampler, JitteredPointsFillEveryCellOfTheGridForAnyCount) {
    const Sampler sampler(SamplerKind::jittered, 1, 3);
    // Square and non-square counts: the grid is count's two factors closest to its root.
    for (const auto& [count, columns, rows] :
         {std::tuple{16, 4, 4}, std::tuple{5, 5, 1}, std::tuple{10, 5, 2}, std::tuple{60, 10, 6},
          std::tuple{32, 8, 4}, std::tuple{1, 1, 1}}) {
        for (std::uint64_t pixel = 0; pixel < 20; ++pixel) {
            const auto points = pattern(sampler, pixel, count, 7);
            expect_in_unit_square(points);
            EXPECT_TRUE(one_per_cell(points, columns, rows)) << count << " points";
        }
    }
}

TEST(Sampler, EveryPatternIsUniformForAnyCount) {
    // Averaged over pixels, the share of a pattern's points in a region is the region's area:
    // here the strips y >= 0.9 and x >= 0.9, which the last row or column of a partly filled
    // grid would under-sample.
    for (const SamplerKind kind : {SamplerKind::jittered, SamplerKind::sobol}) {
        const Sampler sampler(kind, 1, 2);
        for (const std::uint32_t count : {5u, 7u, 10u, 18u, 32u, 33u}) {
            double top = 0, right = 0;
            const int pixels = 4000;
            for (std::uint64_t pixel = 0; pixel < pixels; ++pixel)
                for (const Point2& p : pattern(sampler, pixel, count, 6)) {
                    top += p.y >= 0.9f;
                    right += p.x >= 0.9f;
                }
            // Binomial standard error of the share: sqrt(0.09 / (pixels count)) <= 0.0021.
            EXPECT_NEAR(top / (pixels * count), 0.1, 0.008) << count << " points";
            EXPECT_NEAR(right / (pixels * count), 0.1, 0.008) << count << " points";
        }
    }
}

TEST(Sampler, JitteredSquarePatternsAreNRooksOnTheFineGrid) {
    // Correlated multi-jittering: n^2 points leave one in each of the n^2 columns and rows.
    const Sampler sampler(SamplerKind::jittered, 1, 11);
    for (std::uint64_t pixel = 0; pixel < 20; ++pixel) {
        const auto points = pattern(sampler, pixel, 36, 4);
        EXPECT_TRUE(one_per_cell(points, 36, 1));
        EXPECT_TRUE(one_per_cell(points, 1, 36));
    }
}

TEST(Sampler, JitteredOneDimensionalPointsFillEveryStratum) {
    const Sampler sampler(SamplerKind::jittered, 1, 5);
    for (const std::uint32_t count : {1u, 7u, 64u}) {
        std::set<int> strata;
        for (std::uint32_t i = 0; i < count; ++i) {
            const float u = sampler.get_1d(4, i, count, 9);
            ASSERT_GE(u, 0);
            ASSERT_LT(u, 1);
            strata.insert(int(u * float(count)));
        }
        EXPECT_EQ(strata.size(), count);
    }
}

TEST(Sampler, SobolPrefixesArePowerOfTwoNetsInEveryShape) {
    // A (0, m, 2)-net: each of the 2^m elementary intervals 2^-a x 2^-(m-a) holds one point, for
    // the first 2^m samples and for the next 2^m as well (any aligned block).
    const Sampler sampler(SamplerKind::sobol, 1, 9);
    for (const int m : {2, 4, 6}) {
        const std::uint32_t n = 1u << m;
        for (const std::uint32_t start : {0u, n}) {
            std::vector<Point2> points;
            for (std::uint32_t i = start; i < start + n; ++i)
                points.push_back(sampler.get_2d(77, i, n, 6));
            expect_in_unit_square(points);
            for (int a = 0; a <= m; ++a)
                EXPECT_TRUE(one_per_cell(points, 1 << a, 1 << (m - a)))
                    << "2^" << m << " points from " << start << ", intervals 2^-" << a;
        }
    }
}

TEST(Sampler, SobolDimensionsAndPixelsAreDecorrelated) {
    // Scrambled per dimension and pixel: the same index gives unrelated points, and the mean of
    // x * y over pairs of dimensions is that of independent uniforms (1/4).
    const Sampler sampler(SamplerKind::sobol, 64, 1);
    double sum = 0;
    const int n = 4096;
    for (int i = 0; i < n; ++i) {
        const Point2 a = sampler.get_2d(std::uint64_t(i / 64), i % 64, 64, 4);
        const Point2 b = sampler.get_2d(std::uint64_t(i / 64), i % 64, 64, 5);
        sum += double(a.x) * double(b.x);
    }
    EXPECT_NEAR(sum / n, 0.25, 0.01);
}

TEST(Sampler, SobolCameraDimensionsAreEachANetAndScrambledApart) {
    // The pixel's samples in the camera's dimensions: every coordinate of 2^m samples holds one
    // point in each interval 2^-m, in any pixel; and two coordinates are as unrelated as
    // independent uniforms (the mean of their product over many pixels is 1/4).
    const std::uint32_t n = 64;
    const Sampler sampler(SamplerKind::sobol, int(n), 4);
    const auto coordinate = [&](int c, std::uint64_t pixel, std::uint32_t i) {
        if (c == 4) return sampler.get_1d(pixel, i, n, kTimeDimension);
        if (c == 5) return sampler.get_1d(pixel, i, n, kWavelengthDimension);
        const Point2 p = sampler.get_2d(pixel, i, n, c < 2 ? kPixelDimension : kLensDimension);
        return c % 2 ? p.y : p.x;
    };
    for (std::uint64_t pixel = 0; pixel < 10; ++pixel)
        for (int c = 0; c < 6; ++c) {
            std::set<int> strata;
            for (std::uint32_t i = 0; i < n; ++i) {
                const float u = coordinate(c, pixel, i);
                ASSERT_GE(u, 0);
                ASSERT_LT(u, 1);
                strata.insert(int(u * float(n)));
            }
            EXPECT_EQ(strata.size(), n) << "coordinate " << c;
        }
    const int pixels = 100;
    for (int a = 0; a < 6; ++a)
        for (int b = a + 1; b < 6; ++b) {
            double sum = 0;
            for (std::uint64_t pixel = 0; pixel < pixels; ++pixel)
                for (std::uint32_t i = 0; i < n; ++i)
                    sum += double(coordinate(a, pixel, i)) * double(coordinate(b, pixel, i));
            EXPECT_NEAR(sum / (pixels * n), 0.25, 0.01) << "coordinates " << a << ", " << b;
        }
}

TEST(Sampler, SobolStratifiesThePixelAndTheLensTogether) {
    // Depth of field: out of focus, a sample sees the point its pixel position and its lens
    // position reach together, spread over the circle of confusion (here R pixels wide). Drawn
    // as one sequence, a pixel's 16 or 64 samples estimate what it sees (an out-of-focus round
    // object; an edge) with a much smaller mean squared error than when the lens's points are
    // shuffled apart from the pixel's (a padded dimension, here dimension 9).
    struct Seen {
        const char* name;
        bool (*covered)(Point2 film);
        float radius;
    };
    const Seen cases[] = {
        {"a round object, R = 1",
         [](Point2 f) { return (f.x - 0.3f) * (f.x - 0.3f) + (f.y - 0.2f) * (f.y - 0.2f) < 0.5f; },
         1},
        {"an edge, R = 3", [](Point2 f) { return f.x < 0.8f; }, 3},
    };
    for (const Seen& seen : cases) {
        const auto sees = [&](Point2 p, Point2 l) {
            const Point2 d = sample_uniform_disk(l);
            return seen.covered({p.x + seen.radius * d.x, p.y + seen.radius * d.y});
        };
        // What the pixel sees, from a million points of Roberts' 4D Kronecker sequence (steps
        // the powers of 1 / phi_4, x^5 = x + 1).
        double exact = 0;
        const int many = 1 << 20;
        const double alpha[] = {0.8566748839, 0.7338918058, 0.6287067210, 0.5385972572};
        for (int i = 0; i < many; ++i) {
            double u[4];
            for (int c = 0; c < 4; ++c) u[c] = std::fmod(0.5 + i * alpha[c], 1.0);
            exact += sees({float(u[0]), float(u[1])}, {float(u[2]), float(u[3])});
        }
        exact /= many;
        for (const std::uint32_t n : {16u, 64u}) {
            const Sampler sampler(SamplerKind::sobol, int(n), 1);
            double joint = 0, padded = 0;
            const int pixels = 2000;
            for (std::uint64_t pixel = 0; pixel < pixels; ++pixel) {
                double with_lens = 0, with_other = 0;
                for (std::uint32_t i = 0; i < n; ++i) {
                    const Point2 p = sampler.get_2d(pixel, i, n, kPixelDimension);
                    with_lens += sees(p, sampler.get_2d(pixel, i, n, kLensDimension));
                    with_other += sees(p, sampler.get_2d(pixel, i, n, 9));
                }
                joint += (with_lens / n - exact) * (with_lens / n - exact);
                padded += (with_other / n - exact) * (with_other / n - exact);
            }
            EXPECT_LT(joint, 0.75 * padded)
                << seen.name << ", " << n << " samples: " << joint / pixels << " against "
                << padded / pixels;
        }
    }
}

TEST(SampleStream, SubSamplesAreStratifiedAcrossThePixelsSamplesTogether) {
    // 16 samples with 4 shadow rays each: 64 points of one dimension, one in each cell of 8 x 8.
    for (const SamplerKind kind : {SamplerKind::jittered, SamplerKind::regular}) {
        const Sampler sampler(kind, 16, 2);
        std::vector<Point2> points;
        for (std::uint32_t s = 0; s < 16; ++s) {
            SampleStream stream(sampler, 12, s);
            const std::uint32_t dimension = stream.next_dimension();
            for (std::uint32_t j = 0; j < 4; ++j) points.push_back(stream.get_2d(dimension, j, 4));
        }
        EXPECT_TRUE(one_per_cell(points, 8, 8));
    }
}

TEST(SampleStream, HandsOutFreshDimensionsAfterTheReservedOnes) {
    const Sampler sampler(SamplerKind::jittered, 4, 0);
    SampleStream stream(sampler, 0, 1);
    EXPECT_EQ(stream.next_dimension(), kFirstFreeDimension);
    EXPECT_EQ(stream.next_dimension(), kFirstFreeDimension + 1);
    EXPECT_EQ(stream.next_2d(), sampler.get_2d(0, 1, 4, kFirstFreeDimension + 2));
}

TEST(SampleStream, KeptPixelKeysGiveTheSameNumbers) {
    // A pixel's kept keys only save work: every sample draws what it draws without them, in
    // the kept dimensions and beyond, 2D and 1D, for every kind.
    for (const SamplerKind kind :
         {SamplerKind::jittered, SamplerKind::regular, SamplerKind::sobol}) {
        const Sampler sampler(kind, 9, 5);
        PixelPatterns pixel(sampler, 1234);
        for (std::uint32_t s = 0; s < 9; ++s) {
            SampleStream kept(pixel, s);
            const SampleStream fresh(sampler, 1234, s);
            for (const std::uint32_t d : {0u, 1u, 2u, 7u, 31u, 32u, 40u}) {
                EXPECT_EQ(kept.get_2d(d), fresh.get_2d(d)) << int(kind) << " " << s << " " << d;
                EXPECT_EQ(kept.get_2d(d, 2, 3), fresh.get_2d(d, 2, 3));
                EXPECT_EQ(kept.get_1d(d), fresh.get_1d(d));
            }
        }
    }
}

TEST(Sampler, NamesRoundTrip) {
    for (const std::string_view name : sampler_names()) EXPECT_TRUE(sampler_from_name(name));
    EXPECT_EQ(sampler_from_name("sobol"), SamplerKind::sobol);
    EXPECT_FALSE(sampler_from_name("halton"));
}

TEST(Random, PureFunctionOfItsCoordinatesAndUniform) {
    EXPECT_EQ(random_float(7, 3, 1, 42), random_float(7, 3, 1, 42));
    EXPECT_NE(random_float(7, 3, 1, 42), random_float(7, 3, 2, 42));
    EXPECT_NE(random_float(7, 3, 1, 42), random_float(7, 3, 1, 43));
    double sum = 0;
    int buckets[10] = {};
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const float u = random_float(i, 0, 0, 1);
        ASSERT_GE(u, 0);
        ASSERT_LT(u, 1);
        sum += u;
        ++buckets[int(u * 10)];
    }
    EXPECT_NEAR(sum / n, 0.5, 0.005);
    for (int b : buckets) EXPECT_NEAR(b, n / 10, 400);  // about 4 standard deviations
}

}  // namespace
}  // namespace glint
