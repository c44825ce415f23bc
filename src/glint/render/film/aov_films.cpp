#include "glint/render/film/aov_films.h"

namespace glint {

AovFilms::AovFilms(AovSet set, int width, int height, const FilterSpec& filter,
                   bool importance_sampled)
    : set_(set), width_(width), height_(height), importance_sampled_(importance_sampled) {
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    for (const Aov a : set.list()) {
        switch (aov_info(a).kind) {
            case AovKind::surface:
            case AovKind::sample_mean:
                films_.emplace_back(a, Film(width, height, filter, importance_sampled));
                break;
            case AovKind::id:
                (a == Aov::object ? objects_ : materials_).assign(pixels, -1);
                break;
            case AovKind::pixel:
                break;
        }
    }
}

AovTile AovFilms::make_tile(const Tile& tile) {
    AovTile t;
    t.films_ = this;
    t.tiles_.reserve(films_.size());
    for (const auto& [a, film] : films_) t.tiles_.emplace_back(a, film.make_tile(tile));
    return t;
}

void AovFilms::merge(const AovTile& tile) {
    for (std::size_t i = 0; i < films_.size(); ++i) films_[i].second.merge(tile.tiles_[i].second);
}

void AovTile::add(Point2 p, int x, int y, int sample, float weight, const AovSample& a) {
    const bool own_pixel = films_->importance_sampled_;
    // The filter's weights once for every film: they would cost more than the rest.
    const SampleFootprint footprint =
        tiles_.empty() || own_pixel ? SampleFootprint{} : tiles_.front().second.footprint(p);
    for (auto& [aov, tile] : tiles_) {
        // What the eye ray hit averages over the samples that hit something.
        if (aov_info(aov).kind == AovKind::surface && !a.hit) continue;
        const Color value = a.value(aov);
        if (!is_valid_sample(value)) continue;
        if (own_pixel)
            tile.add_to_pixel(x, y, weight, value);
        else
            tile.add_sample_through(footprint, value);
    }
    if (sample != 0) return;
    const std::size_t pixel = std::size_t(y) * std::size_t(films_->width_) + std::size_t(x);
    if (!films_->objects_.empty()) films_->objects_[pixel] = a.object;
    if (!films_->materials_.empty()) films_->materials_[pixel] = a.material;
}

std::vector<AovImage> AovFilms::resolve() const {
    std::vector<AovImage> out;
    std::size_t film = 0;
    for (const Aov a : set_.list()) {
        if (a == Aov::samples) continue;
        if (aov_info(a).kind != AovKind::id) {
            out.push_back({a, films_[film++].second.resolve()});
            continue;
        }
        Image image(width_, height_);
        const auto& ids = a == Aov::object ? objects_ : materials_;
        for (std::size_t i = 0; i < ids.size(); ++i) image.pixels[i] = Color::gray(float(ids[i]));
        out.push_back({a, std::move(image)});
    }
    return out;
}

}  // namespace glint
