// POV-Ray's image_map: the image file (found and read as #include finds files, through the
// sandbox), its projection, once, interpolation and filter/transmit all, onto glint's projected
// images (shading/projected_image.h) or, with uv_mapping, its images on the surface's uv.
#include <span>
#include <string_view>

#include "glint/image/image_error.h"
#include "glint/image/texture_file.h"
#include "glint/scene/pov/pov_item_reader.h"
#include "glint/scene/quote.h"

namespace glint {

namespace {

// POV-Ray's image file types, and the extension it adds to a name without one.
std::optional<std::string_view> extension_of(std::string_view type) {
    struct Named {
        std::string_view type, extension;
    };
    static constexpr Named kTypes[] = {{"png", ".png"}, {"jpeg", ".jpg"}, {"tga", ".tga"},
                                       {"ppm", ".ppm"}, {"pgm", ".pgm"},  {"gif", ".gif"},
                                       {"hdr", ".hdr"}, {"exr", ".exr"},  {"tiff", ".tif"},
                                       {"iff", ".iff"}, {"sys", ".png"}};
    for (const Named& t : kTypes)
        if (t.type == type) return t.extension;
    return std::nullopt;
}

}  // namespace

Image PovItemReader::image_file(const PovToken& keyword, std::optional<PaletteImage>* palette) {
    std::string extension;
    if (const PovToken& type = parser_.peek_item(); type.kind == PovTokenKind::identifier) {
        if (type.is_word("function"))
            throw parser_.error_at(type, "an image made by a function is not supported yet",
                                   {kSeeCompatibility});
        if (const auto e = extension_of(type.text)) {
            extension = *e;
            parser_.next();
        }
    }
    const PovToken name_token = parser_.peek();
    std::string name = parser_.string_expression("as the " + keyword.text + "'s file");
    if (std::filesystem::path(name).extension().empty()) name += extension;
    const auto [path, bytes] = parser_.read_file(keyword, name_token, name, "image");
    const ReadSandbox* sandbox = parser_.options().sandbox;
    try {
        const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
        if (palette) *palette = read_png_palette(std::span(data, bytes.size()), path);
        return decode_texture_image(std::span(data, bytes.size()), path,
                                    sandbox ? sandbox->limits.image_pixels : kMaxImagePixels);
    } catch (const ImageError& e) {
        throw parser_.error_at(name_token,
                               "cannot read the image " + quote(name) + ": " + e.detail);
    }
}

PovPigment PovItemReader::image_map(const PovToken& keyword) {
    parser_.expect("{", "after image_map");
    auto image = std::make_shared<ProjectedImage>();
    image->image.image = std::make_shared<const MipMap>(image_file(keyword));
    // POV-Ray reads the nearest pixel unless asked to interpolate.
    image->image.filter = TextureFilter::nearest;
    PovPigment p;
    p.kind = PovPigment::Kind::image;
    for (;;) {
        const PovToken token = parser_.next();
        if (token.is_symbol("}")) break;
        if (token.is_word("map_type")) {
            const PovToken at = parser_.peek();
            const int type = parser_.whole_number("after map_type", 0, 7);
            if (type > 2)
                throw parser_.error_at(at,
                                       "map_type " + std::to_string(type) +
                                           " is not supported yet: glint projects images "
                                           "planar (0), spherical (1) and cylindrical (2)",
                                       {kSeeCompatibility});
            image->projection = type == 0   ? ImageProjection::planar
                                : type == 1 ? ImageProjection::spherical
                                            : ImageProjection::cylindrical;
        } else if (token.is_word("once")) {
            image->once = true;
        } else if (token.is_word("interpolate")) {
            const PovToken at = parser_.peek();
            const int kind = parser_.whole_number("after interpolate", 0, 4);
            if (kind == 1) throw parser_.error_at(at, "interpolate must be 2, 3 or 4");
            // Bilinear for all three: POV-Ray's bicubic (3) and normalised distance (4) blend
            // the same neighbours with other weights.
            if (kind >= 2) image->image.filter = TextureFilter::bilinear;
        } else if (token.is_word("filter") || token.is_word("transmit")) {
            const bool all = parser_.accept_word("all");
            if (!all) {
                parser_.finite_float("as the palette index");
                parser_.accept(",");
            }
            const double amount = parser_.finite_float("after " + token.text);
            if (all)
                p.color[token.is_word("filter") ? 3 : 4] = amount;
            else
                read_past(token.text + " of one palette entry in an image_map",
                          "glint reads images as colours, without their palette");
        } else if (token.is_word("use_color") || token.is_word("use_colour") ||
                   token.is_word("use_index") || token.is_word("use_alpha") ||
                   token.is_word("premultiplied")) {
            if (token.is_word("premultiplied")) optional_amount();
        } else if (token.is_word("gamma")) {
            parser_.finite_float("after gamma");
            read_past("gamma in an image_map", "glint decodes an image by its own file's encoding");
        } else {
            throw unsupported(token, "in an image_map");
        }
    }
    if (image->once) image->image.wrap = TextureWrap::clamp;
    p.image = std::move(image);
    return p;
}

}  // namespace glint
