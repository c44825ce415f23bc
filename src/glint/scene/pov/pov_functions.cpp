// POV-Ray's built-in constants and functions (float, vector and string), with POV-Ray's own
// definitions: log is base 10, int truncates, str() formats as printf's %f, rand() is its
// linear congruential stream.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>

#include "glint/scene/pov/pov_parser.h"
#include "glint/scene/quote.h"

namespace glint {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

PovVector vector3(double x, double y, double z) {
    PovVector v;
    v[0] = x;
    v[1] = y;
    v[2] = z;
    return v;
}

// Rotation of p about the unit axis by `degrees`, right-handed in POV-Ray's axes (as its
// vaxis_rotate: x turns to y about z).
PovVector axis_rotate(const PovVector& p, PovVector axis, double degrees) {
    const double length = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    for (int i = 0; i < 3; ++i) axis[i] /= length;
    const double c = std::cos(degrees * kDegree), s = std::sin(degrees * kDegree);
    const double dot = axis[0] * p[0] + axis[1] * p[1] + axis[2] * p[2];
    const PovVector cross =
        vector3(axis[1] * p[2] - axis[2] * p[1], axis[2] * p[0] - axis[0] * p[2],
                axis[0] * p[1] - axis[1] * p[0]);
    PovVector r = vector3(0, 0, 0);
    for (int i = 0; i < 3; ++i) r[i] = p[i] * c + cross[i] * s + axis[i] * dot * (1 - c);
    return r;
}

// printf's %*.*f as POV-Ray's str(): a negative width pads with zeros, a negative precision
// takes %f's default of 6.
// A float argument as an int within [lo, hi] (POV-Ray truncates; huge values saturate).
int clamped(double value, int lo, int hi) {
    if (!(value >= lo)) return lo;
    return value > hi ? hi : int(value);
}

std::string format_float(double value, int width, int precision) {
    char buffer[512];
    const bool zeros = width < 0;
    width = std::min(std::abs(width), 200);
    precision = precision < 0 ? 6 : std::min(precision, 100);
    std::snprintf(buffer, sizeof buffer, zeros ? "%0*.*f" : "%*.*f", width, precision, value);
    return buffer;
}

}  // namespace

std::vector<PovValue> PovParser::arguments(const PovToken& name, std::size_t min, std::size_t max) {
    expect("(", "after " + quote(name.text));
    std::vector<PovValue> values;
    if (!peek().is_symbol(")")) {
        do values.push_back(expression());
        while (accept(","));
    }
    expect(")", "after " + quote(name.text) + "'s arguments");
    if (values.size() < min || values.size() > max) {
        const std::string count =
            min == max ? std::to_string(min) : std::to_string(min) + " to " + std::to_string(max);
        throw error_at(name, quote(name.text) + " takes " + count + " arguments, got " +
                                 std::to_string(values.size()));
    }
    return values;
}

std::optional<double> PovParser::render_float(std::string_view w) const {
    if (w == "clock") return options_.clock;
    if (w == "image_width") return double(options_.image_width);
    if (w == "image_height") return double(options_.image_height);
    if (w == "clock_delta") return 1.0;
    if (w == "clock_on") return 0.0;
    if (w == "initial_clock" || w == "final_clock") return options_.clock;
    if (w == "frame_number" || w == "initial_frame" || w == "final_frame") return 0.0;
    return std::nullopt;
}

std::optional<PovValue> PovParser::builtin(const PovToken& name) {
    const std::string& w = name.text;
    // Constants.
    if (w == "pi") return std::numbers::pi;
    if (w == "true" || w == "yes" || w == "on") return 1.0;
    if (w == "false" || w == "no" || w == "off") return 0.0;
    if (w == "x") return vector3(1, 0, 0);
    if (w == "y") return vector3(0, 1, 0);
    if (w == "z") return vector3(0, 0, 1);
    if (w == "t") {
        PovVector v = PovVector::of(0, 4);
        v[3] = 1;
        return v;
    }
    if (w == "u" || w == "v") {
        PovVector v = PovVector::of(0, 2);
        v[w == "u" ? 0 : 1] = 1;
        return v;
    }
    if (const std::optional<double> value = render_float(w)) return *value;
    if (w == "version") {
        if (const PovValue* declared = symbols_.find("version")) return *declared;
        return 3.7;
    }

    const auto f = [&](const PovValue& value) { return float_of(value, name, "in " + w); };
    const auto vec = [&](const PovValue& value) { return vector_of(value, name, "in " + w, 3); };
    const auto str = [&](const PovValue& value) { return string_of(value, name, "in " + w); };

    // Functions of one float.
    using Unary = double (*)(double);
    static const std::pair<const char*, Unary> kUnary[] = {
        {"abs", [](double a) { return std::abs(a); }},
        {"acos", [](double a) { return std::acos(a); }},
        {"acosh", [](double a) { return std::acosh(a); }},
        {"asin", [](double a) { return std::asin(a); }},
        {"asinh", [](double a) { return std::asinh(a); }},
        {"atan", [](double a) { return std::atan(a); }},
        {"atanh", [](double a) { return std::atanh(a); }},
        {"ceil", [](double a) { return std::ceil(a); }},
        {"cos", [](double a) { return std::cos(a); }},
        {"cosh", [](double a) { return std::cosh(a); }},
        {"degrees", [](double a) { return a / kDegree; }},
        {"exp", [](double a) { return std::exp(a); }},
        {"floor", [](double a) { return std::floor(a); }},
        {"int", [](double a) { return std::trunc(a); }},
        {"ln", [](double a) { return std::log(a); }},
        {"log", [](double a) { return std::log10(a); }},
        {"radians", [](double a) { return a * kDegree; }},
        {"sin", [](double a) { return std::sin(a); }},
        {"sinh", [](double a) { return std::sinh(a); }},
        {"sqrt", [](double a) { return std::sqrt(a); }},
        {"tan", [](double a) { return std::tan(a); }},
        {"tanh", [](double a) { return std::tanh(a); }},
    };
    for (const auto& [fname, fn] : kUnary)
        if (w == fname) return fn(f(arguments(name, 1, 1)[0]));

    if (w == "atan2" || w == "pow" || w == "mod" || w == "div") {
        const auto a = arguments(name, 2, 2);
        const double p = f(a[0]), q = f(a[1]);
        if (w == "atan2") return std::atan2(p, q);
        if (w == "pow") return std::pow(p, q);
        if (w == "mod") return std::fmod(p, q);
        return std::trunc(p / q);
    }
    if (w == "min" || w == "max") {
        const auto a = arguments(name, 2, 1024);
        double r = f(a[0]);
        for (std::size_t i = 1; i < a.size(); ++i)
            r = w == "min" ? std::min(r, f(a[i])) : std::max(r, f(a[i]));
        return r;
    }
    if (w == "select") {
        const auto a = arguments(name, 3, 4);
        const double s = f(a[0]);
        if (a.size() == 3) return s < 0 ? a[1] : a[2];
        return s < 0 ? a[1] : s == 0 ? a[2] : a[3];
    }
    if (w == "seed") {
        const double s = f(arguments(name, 1, 1)[0]);
        random_streams_.push_back(std::uint32_t(
            clamped(s, std::numeric_limits<int>::min(), std::numeric_limits<int>::max())));
        return double(random_streams_.size() - 1);
    }
    if (w == "rand") {
        const double i = f(arguments(name, 1, 1)[0]);
        if (!(i >= 0) || i >= double(random_streams_.size()))
            throw error_at(name,
                           "rand() takes a stream that seed() made, got " + format_pov_number(i));
        std::uint32_t& state = random_streams_[std::size_t(i)];
        state = state * 1812433253u + 12345u;
        return double(state) / double(0xFFFFFFFFu);
    }
    // Vectors.
    if (w == "vlength") {
        const PovVector v = vec(arguments(name, 1, 1)[0]);
        return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
    if (w == "vnormalize") {
        PovVector v = vec(arguments(name, 1, 1)[0]);
        const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (length == 0) throw error_at(name, "vnormalize of a zero vector");
        for (int i = 0; i < 3; ++i) v[i] /= length;
        v.size = 3;
        return v;
    }
    if (w == "vdot" || w == "vcross") {
        const auto a = arguments(name, 2, 2);
        const PovVector p = vec(a[0]), q = vec(a[1]);
        if (w == "vdot") return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
        return vector3(p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2],
                       p[0] * q[1] - p[1] * q[0]);
    }
    if (w == "vrotate") {
        // About x, then y, then z, by the components of the second vector in degrees.
        const auto a = arguments(name, 2, 2);
        PovVector p = vec(a[0]);
        const PovVector angles = vec(a[1]);
        p = axis_rotate(p, vector3(1, 0, 0), angles[0]);
        p = axis_rotate(p, vector3(0, 1, 0), angles[1]);
        return axis_rotate(p, vector3(0, 0, 1), angles[2]);
    }
    if (w == "vaxis_rotate") {
        const auto a = arguments(name, 3, 3);
        const PovVector axis = vec(a[1]);
        if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0)
            throw error_at(name, "vaxis_rotate about a zero axis");
        return axis_rotate(vec(a[0]), axis, f(a[2]));
    }
    // Strings.
    if (w == "str") {
        const auto a = arguments(name, 3, 3);
        return format_float(f(a[0]), clamped(f(a[1]), -200, 200), clamped(f(a[2]), -1, 100));
    }
    if (w == "vstr") {
        const auto a = arguments(name, 5, 5);
        const int n = clamped(f(a[0]), 0, 6);
        const PovVector v = vector_of(a[1], name, "in vstr", 2);
        if (n < 2 || n > 5) throw error_at(name, "vstr takes 2 to 5 components");
        std::string text;
        for (int i = 0; i < n; ++i) {
            if (i > 0) text += str(a[2]);
            text += format_float(v[i], clamped(f(a[3]), -200, 200), clamped(f(a[4]), -1, 100));
        }
        return checked_string(text, name);
    }
    if (w == "concat") {
        std::string text;
        for (const PovValue& part : arguments(name, 1, 1024)) text += str(part);
        return checked_string(text, name);
    }
    if (w == "chr") {
        const double c = f(arguments(name, 1, 1)[0]);
        if (!(c >= 1 && c <= 255)) throw error_at(name, "chr takes 1 to 255");
        return std::string(1, char(int(c)));
    }
    if (w == "asc") {
        const std::string s = str(arguments(name, 1, 1)[0]);
        return s.empty() ? 0.0 : double(static_cast<unsigned char>(s[0]));
    }
    if (w == "strlen") return double(str(arguments(name, 1, 1)[0]).size());
    if (w == "strupr" || w == "strlwr") {
        std::string s = str(arguments(name, 1, 1)[0]);
        for (char& c : s)
            c = char(w == "strupr" ? std::toupper(static_cast<unsigned char>(c))
                                   : std::tolower(static_cast<unsigned char>(c)));
        return s;
    }
    if (w == "substr") {
        const auto a = arguments(name, 3, 3);
        const std::string s = str(a[0]);
        const double start = f(a[1]), length = f(a[2]);
        if (!(start >= 1) || !(length >= 0) || start - 1 + length > double(s.size()))
            throw error_at(name, "substr reaches outside its string of " +
                                     std::to_string(s.size()) + " characters");
        return s.substr(std::size_t(start) - 1, std::size_t(length));
    }
    if (w == "strcmp") {
        const auto a = arguments(name, 2, 2);
        const int c = str(a[0]).compare(str(a[1]));
        return double(c < 0 ? -1 : c > 0 ? 1 : 0);
    }
    if (w == "val") {
        const std::string s = str(arguments(name, 1, 1)[0]);
        return std::atof(s.c_str());
    }
    if ((w == "min_extent" || w == "max_extent") && extent_reader_) {
        const PovValue object = arguments(name, 1, 1)[0];
        const auto* item = std::get_if<std::shared_ptr<const PovItemRef>>(&object);
        if (!item) throw error_at(name, w + " takes an object, got " + kind_of(object));
        const auto [low, high] = extent_reader_(**item, name);
        return w == "min_extent" ? low : high;
    }
    if (w == "trace" && trace_reader_) {
        // trace(OBJECT, A, B [, NORMAL]): the first hit of the ray from A along B, or <0, 0, 0>;
        // NORMAL, a vector declared before, takes the normal there (<0, 0, 0> for none).
        expect("(", "after trace");
        const PovValue object = expression();
        const auto* item = std::get_if<std::shared_ptr<const PovItemRef>>(&object);
        if (!item)
            throw error_at(name,
                           std::string("trace takes an object first, got ") + kind_of(object));
        expect(",", "after trace's object");
        const PovVector from = vector_expression("as trace's start");
        expect(",", "after trace's start");
        const PovVector direction = vector_expression("as trace's direction");
        PovValue* normal = nullptr;
        if (accept(",")) {
            const PovToken id = raw_next();
            normal = symbols_.find(id.text);
            if (!normal || !std::holds_alternative<PovVector>(*normal))
                throw error_at(id,
                               "trace's fourth argument must be a vector declared before, "
                               "which takes the normal; got " +
                                   describe(id));
        }
        expect(")", "after trace's arguments");
        const std::optional<TraceHit> hit = trace_reader_(*item, from, direction, name);
        if (normal) *normal = hit ? hit->normal : vector3(0, 0, 0);
        return hit ? hit->point : vector3(0, 0, 0);
    }
    if (w == "defined") {
        expect("(", "after defined");
        const PovToken id = raw_next();  // a macro's name is not called here
        expect(")", "after defined's identifier");
        // A file handle is defined while it is open, and a file read to its end no more.
        if (const auto file = open_files_.find(id.text); file != open_files_.end())
            return double(!file->second.at_end);
        return double(symbols_.find(id.text) != nullptr || macros_.contains(id.text));
    }
    if (w == "dimensions" || w == "dimension_size") {
        const auto a = arguments(name, w == "dimensions" ? 1 : 2, w == "dimensions" ? 1 : 2);
        const auto* array = std::get_if<std::shared_ptr<PovArray>>(&a[0]);
        if (!array) throw error_at(name, w + " takes an array, got " + kind_of(a[0]));
        if (w == "dimensions") return double((*array)->sizes.size());
        const double d = f(a[1]);
        if (!(d >= 1) || d > double((*array)->sizes.size())) return 0.0;
        return double((*array)->sizes[std::size_t(d) - 1]);
    }
    return std::nullopt;
}

}  // namespace glint
