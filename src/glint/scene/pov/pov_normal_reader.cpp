// POV-Ray's normal { }: its own patterns (bumps, dents, wrinkles, ripples, waves) and the slope of
// any pigment pattern or of a pigment's grey (pigment_pattern), with its amount, modifiers and
// transforms, read onto glint's normal patterns (shading/normal_pattern.h).
#include <string_view>

#include "glint/scene/pov/pov_item_reader.h"

namespace glint {

namespace {

std::optional<NormalPatternKind> normal_kind(std::string_view w) {
    if (w == "bumps") return NormalPatternKind::bumps;
    if (w == "dents") return NormalPatternKind::dents;
    if (w == "wrinkles") return NormalPatternKind::wrinkles;
    if (w == "ripples") return NormalPatternKind::ripples;
    if (w == "waves") return NormalPatternKind::waves;
    return std::nullopt;
}

// POV-Ray's other patterns, which glint does not tilt normals by yet.
bool unread_normal_pattern(std::string_view w) {
    static constexpr std::string_view kUnread[] = {
        "aoi",      "average",  "bump_map",      "cells",  "cubic",  "density_file",
        "facets",   "function", "image_pattern", "julia",  "magnet", "object",
        "pavement", "quilted",  "slope",         "square", "tiling", "triangular"};
    for (const std::string_view u : kUnread)
        if (u == w) return true;
    return false;
}

}  // namespace

PovNormal PovItemReader::normal(const std::optional<PovNormal>& base) {
    parser_.expect("{", "after normal");
    PovNormal n = base.value_or(PovNormal{});
    PovPigment pattern_of;  // the pattern and its modifiers, read as a pigment's
    pattern_of.spec = n.pattern.pattern;
    if (auto d = take_declared<PovNormal>()) {
        n = *d;
        pattern_of.spec = n.pattern.pattern;
    } else if (const PovToken& first = parser_.peek_item();
               first.kind == PovTokenKind::identifier) {
        if (const auto kind = normal_kind(first.text)) {
            parser_.next();
            n = PovNormal{};
            n.pattern.kind = *kind;
            pattern_of = PovPigment{};
        } else if (first.is_word("pigment_pattern")) {
            // The slope of a pigment's grey.
            parser_.next();
            n = PovNormal{};
            n.pattern.kind = NormalPatternKind::slope;
            n.pigment = std::make_shared<const PovPigment>(pigment({}));
            pattern_of = PovPigment{};
        } else if (is_pigment_pattern(first.text)) {
            const PovToken name = parser_.next();
            n = PovNormal{};
            if (parser_.peek_item().is_word("normal")) {
                // checker normal { } normal { }: a normal for each of the pattern's parts.
                n.unsupported = name.text + " of normals";
                parser_.skip_to_closing_brace(name);
                return n;
            }
            pattern_of = pattern(name);
            n.pattern.kind = NormalPatternKind::slope;
            // A function glint cannot compute: the surface stays smooth.
            if (pattern_of.kind == PovPigment::Kind::unsupported)
                n.unsupported = name.text + " using " + pattern_of.uses;
        } else if (unread_normal_pattern(first.text)) {
            // A pattern glint does not tilt normals by yet: the surface stays smooth.
            const PovToken name = parser_.next();
            n = PovNormal{};
            n.unsupported = name.text;
            parser_.skip_to_closing_brace(name);
            return n;
        }
    }
    parser_.accept(",");  // gradient y, 0.5
    if (const auto amount = amount_if_given()) n.pattern.amount = float(*amount);
    for (;;) {
        const PovToken token = parser_.next();
        if (token.is_symbol("}")) break;
        if (const auto step = transform_step(token)) {
            n.transform = *step * n.transform;
        } else if (token.is_word("bump_size")) {
            n.pattern.amount = number("after bump_size");
        } else if (token.is_word("accuracy")) {
            const PovToken at = parser_.peek();
            n.pattern.accuracy = number("after accuracy");
            if (!(n.pattern.accuracy > 0)) throw parser_.error_at(at, "accuracy must be > 0");
        } else if (token.is_word("no_bump_scale")) {
            read_past("no_bump_scale", "a normal's bumps keep their depth when it is scaled");
        } else if (token.is_word("slope_map") || token.is_word("normal_map") ||
                   token.is_word("warp")) {
            parser_.skip_braced(token);
            read_past(token.text + " in a normal", "the normal pattern is used without it");
        } else if (token.kind != PovTokenKind::identifier || !pattern_modifier(token, pattern_of)) {
            throw unsupported(token, "in a normal");
        }
    }
    n.pattern.pattern = pattern_of.spec;
    return n;
}

}  // namespace glint
