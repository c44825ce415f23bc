// FreeType reads the font: the character map, each glyph's outline in font units (unscaled,
// unhinted), its metrics and the kerning pairs; the layout is POV-Ray's.
#include "glint/scene/font_outlines.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <array>
#include <memory>

namespace glint {

namespace {

// The code points of UTF-8 text; a byte that starts no valid sequence is taken as Latin-1.
std::vector<char32_t> code_points(std::string_view text) {
    std::vector<char32_t> out;
    for (std::size_t i = 0; i < text.size();) {
        const auto byte = static_cast<unsigned char>(text[i]);
        const int length = byte < 0x80           ? 1
                           : (byte >> 5) == 0x6  ? 2
                           : (byte >> 4) == 0xe  ? 3
                           : (byte >> 3) == 0x1e ? 4
                                                 : 0;
        bool valid = length > 0 && i + std::size_t(length) <= text.size();
        char32_t c = length == 1   ? byte
                     : length == 2 ? byte & 0x1f
                     : length == 3 ? byte & 0x0f
                                   : byte & 0x07;
        for (int k = 1; valid && k < length; ++k) {
            const auto next = static_cast<unsigned char>(text[i + std::size_t(k)]);
            valid = (next >> 6) == 0x2;
            c = (c << 6) | (next & 0x3f);
        }
        if (!valid) {
            out.push_back(byte);
            ++i;
        } else {
            out.push_back(c);
            i += std::size_t(length);
        }
    }
    return out;
}

std::string utf8(char32_t c) {
    std::string s;
    if (c < 0x80) {
        s += char(c);
    } else if (c < 0x800) {
        s += char(0xc0 | (c >> 6));
        s += char(0x80 | (c & 0x3f));
    } else if (c < 0x10000) {
        s += char(0xe0 | (c >> 12));
        s += char(0x80 | ((c >> 6) & 0x3f));
        s += char(0x80 | (c & 0x3f));
    } else {
        s += char(0xf0 | (c >> 18));
        s += char(0x80 | ((c >> 12) & 0x3f));
        s += char(0x80 | ((c >> 6) & 0x3f));
        s += char(0x80 | (c & 0x3f));
    }
    return s;
}

// Collects a glyph's contours from FT_Outline_Decompose, scaled to ems and moved by (dx, dy).
struct OutlineSink {
    double scale = 1, dx = 0, dy = 0;
    std::vector<Outline> outlines;
    Point2 pen;

    Point2 place(const FT_Vector* v) const {
        return {float(double(v->x) * scale + dx), float(double(v->y) * scale + dy)};
    }
};

OutlineSink& sink_of(void* user) { return *static_cast<OutlineSink*>(user); }

int move_to(const FT_Vector* to, void* user) {
    OutlineSink& s = sink_of(user);
    s.outlines.emplace_back();
    s.pen = s.place(to);
    return 0;
}

int line_to(const FT_Vector* to, void* user) {
    OutlineSink& s = sink_of(user);
    const Point2 p = s.place(to);
    append_line(s.outlines.back(), s.pen, p);
    s.pen = p;
    return 0;
}

// A quadratic Bezier p0 p1 p2 in power form: (p0 - 2 p1 + p2) s^2 + 2 (p1 - p0) s + p0.
int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
    OutlineSink& s = sink_of(user);
    const Point2 p0 = s.pen, p1 = s.place(control), p2 = s.place(to);
    append_curve(s.outlines.back(),
                 {{0, 0},
                  {p0.x - 2 * p1.x + p2.x, p0.y - 2 * p1.y + p2.y},
                  {2 * (p1.x - p0.x), 2 * (p1.y - p0.y)},
                  p0},
                 1e-4);
    s.pen = p2;
    return 0;
}

int cubic_to(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    OutlineSink& s = sink_of(user);
    const Point2 p0 = s.pen, p1 = s.place(c1), p2 = s.place(c2), p3 = s.place(to);
    const auto power = [](float a, float b, float c, float d) {
        return std::array<float, 4>{-a + 3 * b - 3 * c + d, 3 * a - 6 * b + 3 * c, 3 * (b - a), a};
    };
    const auto x = power(p0.x, p1.x, p2.x, p3.x), y = power(p0.y, p1.y, p2.y, p3.y);
    append_curve(s.outlines.back(), {{x[0], y[0]}, {x[1], y[1]}, {x[2], y[2]}, {x[3], y[3]}}, 1e-4);
    s.pen = p3;
    return 0;
}

struct LibraryDone {
    void operator()(FT_Library library) const { FT_Done_FreeType(library); }
};
struct FaceDone {
    void operator()(FT_Face face) const { FT_Done_Face(face); }
};

}  // namespace

std::variant<TextOutlines, std::string> text_outlines(std::string_view font,
                                                      std::string_view font_name,
                                                      std::string_view text, Vector3 offset) {
    const std::string name(font_name);
    FT_Library raw_library = nullptr;
    if (FT_Init_FreeType(&raw_library) != 0) return "cannot start FreeType to read " + name;
    const std::unique_ptr<FT_LibraryRec_, LibraryDone> library(raw_library);
    FT_Face raw_face = nullptr;
    if (FT_New_Memory_Face(library.get(), reinterpret_cast<const FT_Byte*>(font.data()),
                           FT_Long(font.size()), 0, &raw_face) != 0)
        return name + " is not a font FreeType reads (TrueType, OpenType)";
    const std::unique_ptr<FT_FaceRec_, FaceDone> face(raw_face);
    if (!FT_IS_SCALABLE(face.get()) || face->units_per_EM == 0)
        return name + " has no outlines: it is a bitmap font";
    // Unicode first, then the Macintosh Roman map of old fonts, as POV-Ray looks for them.
    if (FT_Select_Charmap(face.get(), FT_ENCODING_UNICODE) != 0)
        FT_Select_Charmap(face.get(), FT_ENCODING_APPLE_ROMAN);

    const double em = 1.0 / face->units_per_EM;
    const FT_Outline_Funcs funcs{move_to, line_to, conic_to, cubic_to, 0, 0};
    TextOutlines result;
    double pen = 0, rise = 0;
    FT_UInt previous = 0;
    bool first = true;
    for (const char32_t c : code_points(text)) {
        const FT_UInt index = FT_Get_Char_Index(face.get(), c);
        if (index == 0) result.missing.push_back(utf8(c));
        if (FT_Load_Glyph(face.get(), index,
                          FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0 ||
            face->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
            return name + ": cannot read the glyph of " + utf8(c);
        FT_Outline& outline = face->glyph->outline;
        FT_BBox box{};
        FT_Outline_Get_CBox(&outline, &box);
        const double advance = double(face->glyph->metrics.horiAdvance);
        const double bearing = double(face->glyph->metrics.horiBearingX);
        // POV-Ray: the first letter's left edge at 0; each next one at the pen plus its left
        // side bearing and the pair's kerning, its box's left edge taken off.
        double x = 0;
        if (first) {
            x = -double(box.xMin) * em;
            pen = (advance - bearing) * em;
        } else {
            FT_Vector kern{0, 0};
            if (FT_HAS_KERNING(face.get()))
                FT_Get_Kerning(face.get(), previous, index, FT_KERNING_UNSCALED, &kern);
            const double k = std::max(double(kern.x), -double(face->units_per_EM));
            x = pen + (bearing - double(box.xMin) + k) * em;
            pen += (advance + k) * em;
        }
        OutlineSink sink{em, x, rise, {}, {}};
        if (outline.n_contours > 0 && FT_Outline_Decompose(&outline, &funcs, &sink) != 0)
            return name + ": cannot read the outline of " + utf8(c);
        std::erase_if(sink.outlines, [](const Outline& o) { return o.empty(); });
        if (!sink.outlines.empty()) result.glyphs.push_back(std::move(sink.outlines));
        pen += offset.x;
        rise += offset.y;
        previous = index;
        first = false;
    }
    return result;
}

}  // namespace glint
