// Typed reading of single YAML values. The parsing of scalars is ours rather than yaml-cpp's
// as<T>(), so that every failure has a precise message and nothing else throws.
#include "glint/scene/yaml/yaml_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>

#include "glint/scene/suggest.h"

namespace glint {

namespace {

// Scalars quoted in messages are cut short so that a pasted blob cannot flood the terminal.

bool is_plain(const YAML::Node& node) { return node.Tag() == "?"; }

enum class NumberStatus { ok, not_a_number, not_finite, out_of_range };

struct ParsedNumber {
    NumberStatus status;
    double value = 0;
};

// YAML 1.2 core-schema floats and decimal integers. std::from_chars would also take "inf" and
// "nan", which YAML spells ".inf" and ".nan", so the first character is checked first.
ParsedNumber parse_number(std::string_view s) {
    std::string_view body = s;
    const bool negative = !body.empty() && body[0] == '-';
    if (!body.empty() && (body[0] == '+' || body[0] == '-')) body.remove_prefix(1);
    if (body == ".inf" || body == ".Inf" || body == ".INF") return {NumberStatus::not_finite};
    if (s == ".nan" || s == ".NaN" || s == ".NAN") return {NumberStatus::not_finite};
    if (body.empty() || !(std::isdigit(static_cast<unsigned char>(body[0])) || body[0] == '.')) {
        return {NumberStatus::not_a_number};
    }
    double value = 0;
    const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), value);
    if (end != body.data() + body.size()) return {NumberStatus::not_a_number};
    if (ec == std::errc::result_out_of_range) return {NumberStatus::out_of_range};
    if (ec != std::errc()) return {NumberStatus::not_a_number};
    return {NumberStatus::ok, negative ? -value : value};
}

bool looks_like_number(const YAML::Node& node) {
    return node.IsScalar() && is_plain(node) &&
           parse_number(node.Scalar()).status != NumberStatus::not_a_number;
}

// An empty value has no token of its own; its key is the best place to point at.
const YAML::Node& blame(const YAML::Node& node, const Field& field) {
    if (node.IsNull() && !field.key_node.Mark().is_null()) return field.key_node;
    return node;
}

std::string subject(const Field& field) {
    return field.what.empty() ? field.key : field.what + " " + field.key;
}

}  // namespace

SceneError type_error(const YamlSource& source, const YAML::Node& node, const Field& field,
                      std::string_view expected) {
    std::vector<std::string> notes;
    if (node.IsScalar() && node.Tag() == "!" &&
        parse_number(node.Scalar()).status == NumberStatus::ok) {
        notes.push_back("quoted values are strings; write the number without quotes");
    }
    return source.error_at(blame(node, field),
                           "expected " + std::string(expected) + " for " + quote(field.key) +
                               ", got " + describe(node),
                           std::move(notes));
}

// --- Ranges and text ---

std::string format_number(double value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string format_number(float value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string describe(const YAML::Node& node) {
    switch (node.Type()) {
        case YAML::NodeType::Sequence:
            return "a sequence";
        case YAML::NodeType::Map:
            return "a map";
        case YAML::NodeType::Scalar:
            if (looks_like_number(node) && node.Scalar().size() <= kMaxQuoted) return node.Scalar();
            return quote(node.Scalar());
        default:
            return "nothing";
    }
}

std::string join(std::span<const std::string_view> names) {
    std::string out;
    for (const std::string_view name : names) {
        if (!out.empty()) out += ", ";
        out += name;
    }
    return out;
}

// --- Single values ---

float read_number(const YamlSource& source, const YAML::Node& node, const Field& field,
                  Range range) {
    if (!node.IsScalar() || !is_plain(node)) throw type_error(source, node, field, "a number");
    const ParsedNumber parsed = parse_number(node.Scalar());
    switch (parsed.status) {
        case NumberStatus::not_a_number:
            throw type_error(source, node, field, "a number");
        case NumberStatus::not_finite:
            throw type_error(source, node, field, "a finite number");
        case NumberStatus::out_of_range:
        case NumberStatus::ok:
            break;
    }
    // Values are stored as floats; one that a float cannot hold is as wrong as infinity.
    constexpr double kFloatMax = std::numeric_limits<float>::max();
    if (parsed.status == NumberStatus::out_of_range || std::abs(parsed.value) > kFloatMax) {
        throw source.error_at(node, subject(field) +
                                        " must be between -3.4e38 and 3.4e38 (a float), got " +
                                        describe(node));
    }
    const auto value = static_cast<float>(parsed.value);
    if (!range.contains(value)) {
        throw source.error_at(
            node, subject(field) + " must be " + range.describe() + ", got " + describe(node));
    }
    return value;
}

std::int64_t read_integer(const YamlSource& source, const YAML::Node& node, const Field& field,
                          IntRange range) {
    if (!node.IsScalar() || !is_plain(node)) throw type_error(source, node, field, "an integer");
    std::string_view text = node.Scalar();
    if (!text.empty() && text[0] == '+') text.remove_prefix(1);
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    const bool whole = !text.empty() && end == text.data() + text.size();
    if (!whole || (ec != std::errc() && ec != std::errc::result_out_of_range)) {
        throw type_error(source, node, field, "an integer");
    }
    if (ec == std::errc::result_out_of_range || value < range.min || value > range.max) {
        throw source.error_at(node, subject(field) + " must be in " + std::to_string(range.min) +
                                        ".." + std::to_string(range.max) + ", got " +
                                        describe(node));
    }
    return value;
}

bool read_bool(const YamlSource& source, const YAML::Node& node, const Field& field) {
    if (node.IsScalar() && is_plain(node)) {
        std::string lower = node.Scalar();
        for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (lower == "true" || lower == "yes" || lower == "on") return true;
        if (lower == "false" || lower == "no" || lower == "off") return false;
    }
    throw type_error(source, node, field, "true or false");
}

std::string read_string(const YamlSource& source, const YAML::Node& node, const Field& field) {
    if (!node.IsScalar()) throw type_error(source, node, field, "a string");
    return node.Scalar();
}

std::vector<YAML::Node> read_sequence(const YamlSource& source, const YAML::Node& node,
                                      const Field& field, std::string_view expected,
                                      std::size_t count) {
    if (!node.IsSequence()) throw type_error(source, node, field, expected);
    std::vector<YAML::Node> items;
    for (auto it = node.begin(); it != node.end(); ++it) items.push_back(*it);
    if (count > 0 && items.size() != count) {
        throw source.error_at(node, "expected " + std::string(expected) + " for " +
                                        quote(field.key) + ", got a sequence of " +
                                        std::to_string(items.size()));
    }
    return items;
}

namespace {
std::array<float, 3> read_triple(const YamlSource& source, const YAML::Node& node,
                                 const Field& field, std::string_view expected) {
    const auto items = read_sequence(source, node, field, expected, 3);
    std::array<float, 3> values{};
    for (std::size_t i = 0; i < 3; ++i) {
        values[i] =
            read_number(source, items[i], {field.what, field.key + "[" + std::to_string(i) + "]"});
    }
    return values;
}
}  // namespace

Point3 read_point(const YamlSource& source, const YAML::Node& node, const Field& field) {
    const auto v = read_triple(source, node, field, "a point [x, y, z]");
    return {v[0], v[1], v[2]};
}

Vector3 read_vector(const YamlSource& source, const YAML::Node& node, const Field& field) {
    const auto v = read_triple(source, node, field, "a vector [x, y, z]");
    return {v[0], v[1], v[2]};
}

Point2 read_point2(const YamlSource& source, const YAML::Node& node, const Field& field) {
    const auto items = read_sequence(source, node, field, "a pair [u, v]", 2);
    return {read_number(source, items[0], {field.what, field.key + "[0]"}),
            read_number(source, items[1], {field.what, field.key + "[1]"})};
}

Color read_color(const YamlSource& source, const YAML::Node& node, const Field& field) {
    constexpr std::string_view kExpected = "a color ([r, g, b] or a number)";
    const auto channel = [&](const YAML::Node& item, const Field& f) {
        const float v = read_number(source, item, f);
        if (v < 0) {
            throw source.error_at(item,
                                  subject(field) + " channels must be >= 0, got " + describe(item));
        }
        return v;
    };
    if (node.IsScalar() && looks_like_number(node)) return Color::gray(channel(node, field));
    if (!node.IsSequence()) throw type_error(source, node, field, kExpected);
    const auto items = read_sequence(source, node, field, kExpected, 3);
    Color c;
    c.r = channel(items[0], {field.what, field.key + "[0]"});
    c.g = channel(items[1], {field.what, field.key + "[1]"});
    c.b = channel(items[2], {field.what, field.key + "[2]"});
    return c;
}

SceneError unknown_name(const YamlSource& source, const YAML::Node& at, std::string_view kind,
                        std::string_view plural, std::string_view name,
                        std::span<const std::string_view> names) {
    return source.error_at(
        at, "unknown " + std::string(kind) + " " + quote(name),
        {std::string(plural) + " are: " + join(names) + did_you_mean(name, names)});
}

std::optional<Vector3> unit_vector(Vector3 v) {
    const double x = v.x, y = v.y, z = v.z;
    const double length = std::sqrt(x * x + y * y + z * z);
    if (!(length > 0) || !std::isfinite(length)) return std::nullopt;
    return Vector3(float(x / length), float(y / length), float(z / length));
}

std::string format_vector(Vector3 v) {
    std::string out = "[";  // built up with += : GCC 12 misreports "[" + string (-Wrestrict)
    out += format_number(v.x);
    out += ", ";
    out += format_number(v.y);
    out += ", ";
    out += format_number(v.z);
    out += "]";
    return out;
}

}  // namespace glint
