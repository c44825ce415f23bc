// The films of a render's output variables (aov.h): a Film per variable, through the image's own
// filter, so that each layer is resolved as the image is and the image's parts add up to it; and
// the ids of each pixel's first sample, which a mean would mix.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "glint/image/image.h"
#include "glint/render/film/aov.h"
#include "glint/render/film/film.h"
#include "glint/render/tiles.h"
#include "glint/sampling/filter.h"

namespace glint {

// One variable resolved, scalars in every channel (uv in r and g).
struct AovImage {
    Aov aov;
    Image image;
};

class AovFilms;

// A tile's part of every film, filled by one render thread.
class AovTile {
public:
    // Adds the sample taken at film position p of pixel (x, y), its index `sample`, of filter
    // weight `weight` under filter importance sampling (1 otherwise).
    void add(Point2 p, int x, int y, int sample, float weight, const AovSample& a);

private:
    friend class AovFilms;
    AovFilms* films_ = nullptr;
    std::vector<std::pair<Aov, FilmTile>> tiles_;
};

class AovFilms {
public:
    AovFilms() = default;  // no variables
    // importance_sampled as for Film.
    AovFilms(AovSet set, int width, int height, const FilterSpec& filter,
             bool importance_sampled = false);

    const AovSet& set() const { return set_; }
    bool empty() const { return set_.empty(); }

    // Concurrent with merges of other tiles as Film::make_tile is; ids go straight to the film
    // (a pixel's first sample is in one tile only).
    AovTile make_tile(const Tile& tile);
    void merge(const AovTile& tile);

    // The variables in Aov order, but `samples`, which the render's state holds.
    std::vector<AovImage> resolve() const;

    // The films, in Aov order, and the ids of each pixel's first sample (empty unless asked
    // for): to add films up and to move a tile's pixels between processes.
    std::vector<std::pair<Aov, Film>>& films() { return films_; }
    const std::vector<std::pair<Aov, Film>>& films() const { return films_; }
    std::vector<std::int32_t>& objects() { return objects_; }
    const std::vector<std::int32_t>& objects() const { return objects_; }
    std::vector<std::int32_t>& materials() { return materials_; }
    const std::vector<std::int32_t>& materials() const { return materials_; }

private:
    friend class AovTile;
    AovSet set_;
    int width_ = 0, height_ = 0;
    bool importance_sampled_ = false;
    std::vector<std::pair<Aov, Film>> films_;
    std::vector<std::int32_t> objects_, materials_;  // -1: missed, or no sample yet
};

}  // namespace glint
