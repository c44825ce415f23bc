// POV-Ray's expressions, evaluated as they are parsed: ?:, |, &, comparisons, + -, * /, unary
// + - !, member access (.x, .red, ...), vectors <a, b, c>, colours, arrays and identifiers.
#include <cmath>
#include <limits>

#include "glint/scene/pov/pov_parser.h"
#include "glint/scene/quote.h"

namespace glint {

namespace {

bool truthy(double value) { return value != 0; }

// The component a member names, and the vector size it needs; -1 for no such member.
int member_index(std::string_view name) {
    if (name == "x" || name == "u" || name == "red") return 0;
    if (name == "y" || name == "v" || name == "green") return 1;
    if (name == "z" || name == "blue") return 2;
    if (name == "t" || name == "filter") return 3;
    if (name == "transmit") return 4;
    return -1;
}

}  // namespace

PovValue PovParser::expression() {
    const Nested nested(*this, peek());
    return conditional();
}

double PovParser::float_of(const PovValue& value, const PovToken& at, std::string_view what) const {
    if (const double* f = std::get_if<double>(&value)) return *f;
    throw error_at(at, "expected a float " + std::string(what) + ", got " + kind_of(value));
}

PovVector PovParser::vector_of(const PovValue& value, const PovToken& at, std::string_view what,
                               int size) const {
    if (const double* f = std::get_if<double>(&value)) return PovVector::of(*f, size);
    if (const PovVector* v = std::get_if<PovVector>(&value)) {
        PovVector widened = *v;
        widened.size = std::max(v->size, size);
        return widened;
    }
    throw error_at(at, "expected a vector " + std::string(what) + ", got " + kind_of(value));
}

std::string PovParser::string_of(const PovValue& value, const PovToken& at,
                                 std::string_view what) const {
    if (const std::string* s = std::get_if<std::string>(&value)) return *s;
    throw error_at(at, "expected a string " + std::string(what) + ", got " + kind_of(value));
}

std::string PovParser::checked_string(std::string text, const PovToken& at) const {
    if (text.size() > options_.max_string_length)
        throw error_at(at, "string is longer than " + std::to_string(options_.max_string_length) +
                               " characters");
    return text;
}

double PovParser::float_expression(std::string_view what) {
    const PovToken at = peek();
    return float_of(expression(), at, what);
}

PovVector PovParser::vector_expression(std::string_view what, int size) {
    const PovToken at = peek();
    return vector_of(expression(), at, what, size);
}

namespace {

// What a scene's items store is a float: beyond a float's range is not finite either.
bool fits_float(double value) {
    return std::isfinite(value) && std::abs(value) <= double(std::numeric_limits<float>::max());
}

}  // namespace

PovVector PovParser::color_expression(std::string_view what) {
    const PovToken at = peek();
    if (at.is_word("color") || at.is_word("colour")) next();
    PovVector v = vector_of(expression(), at, what, 5);
    v.size = 5;
    // A declared colour may take POV-Ray's colour keywords after it: `Red transmit 0.5`.
    for (;;) {
        const PovToken& more = peek();
        const int index = more.kind == PovTokenKind::identifier ? member_index(more.text) : -1;
        if (index < 0 || more.is_word("x") || more.is_word("y") || more.is_word("z") ||
            more.is_word("t") || more.is_word("u") || more.is_word("v"))
            break;
        const PovToken keyword = next();
        v[index] = float_of(additive(), keyword, "after " + keyword.text);
    }
    for (int i = 0; i < 5; ++i)
        if (!fits_float(v[i]))
            throw error_at(at, "colour " + std::string(what) + " must be finite");
    return v;
}

double PovParser::finite_float(std::string_view what) {
    const PovToken at = peek();
    struct Restore {
        bool& flag;
        bool was;
        ~Restore() { flag = was; }
    } restore{item_float_, item_float_};
    item_float_ = true;
    const double value = float_of(expression(), at, what);
    if (!fits_float(value))
        throw error_at(at, "the number " + std::string(what) + " must be finite, got " +
                               format_pov_number(value));
    return value;
}

int PovParser::whole_number(std::string_view what, int min, int max) {
    const PovToken at = peek();
    const double value = finite_float(what);
    if (!(value >= min && value <= max) || value != std::floor(value))
        throw error_at(at, "the number " + std::string(what) + " must be a whole number from " +
                               std::to_string(min) + " to " + std::to_string(max) + ", got " +
                               format_pov_number(value));
    return int(value);
}

std::vector<double> PovParser::finite_list(std::string_view what, std::size_t count) {
    expect("<", what);
    const bool was_in_vector = in_vector_;
    in_vector_ = true;
    std::vector<double> values;
    for (std::size_t i = 0; i < count; ++i) {
        if (i > 0)
            expect(",", "between the " + std::to_string(count) + " numbers " + std::string(what));
        values.push_back(finite_float(what));
    }
    in_vector_ = was_in_vector;
    expect(">", "after the " + std::to_string(count) + " numbers " + std::string(what));
    return values;
}

PovVector PovParser::finite_vector(std::string_view what, int size) {
    const PovToken at = peek();
    const PovVector v = vector_of(expression(), at, what, size);
    for (int i = 0; i < v.size; ++i)
        if (!fits_float(v[i]))
            throw error_at(at, "the vector " + std::string(what) + " must be finite");
    return v;
}

std::string PovParser::string_expression(std::string_view what) {
    // Strings have no operators: nothing is read past the string (a directive after
    // `#include "file"` runs after the file).
    const PovToken at = peek();
    return string_of(primary(), at, what);
}

PovValue PovParser::conditional() {
    const PovToken at = peek();
    PovValue condition = logical_or();
    if (!accept("?")) return condition;
    const bool chosen = truthy(float_of(condition, at, "before '?'"));
    PovValue a = conditional();
    expect(":", "in the conditional a ? b : c");
    PovValue b = conditional();
    return chosen ? a : b;
}

PovValue PovParser::logical_or() {
    const PovToken at = peek();
    PovValue left = logical_and();
    while (accept("|")) {
        const double a = float_of(left, at, "before '|'");
        const double b = float_of(logical_and(), at, "after '|'");
        left = double(truthy(a) || truthy(b));
    }
    return left;
}

PovValue PovParser::logical_and() {
    const PovToken at = peek();
    PovValue left = comparison();
    while (accept("&")) {
        const double a = float_of(left, at, "before '&'");
        const double b = float_of(comparison(), at, "after '&'");
        left = double(truthy(a) && truthy(b));
    }
    return left;
}

PovValue PovParser::comparison() {
    const PovToken at = peek();
    PovValue left = additive();
    for (;;) {
        const PovToken& op = peek();
        if (op.kind != PovTokenKind::symbol) return left;
        const std::string& s = op.text;
        // Inside < >, a '>' closes the vector: comparisons there need parentheses.
        if (!(s == "<" || s == "<=" || s == "=" || s == ">=" || s == "!=" ||
              (s == ">" && !in_vector_)))
            return left;
        // `box { <0, 0, 0> <1, 1, 1> }`: after a vector, '<' starts the next value.
        if (s == "<" && (!std::holds_alternative<double>(left) || item_float_)) return left;
        const std::string which = next().text;
        // Two strings compare by their characters, as POV-Ray compares them; else two floats.
        int order = 0;  // <0, 0, >0: left before, equal to or after right
        if (std::holds_alternative<std::string>(left)) {
            const std::string a = std::get<std::string>(left);
            order = a.compare(string_of(additive(), at, "after '" + which + "'"));
        } else {
            const double a = float_of(left, at, "before '" + which + "'");
            const double b = float_of(additive(), at, "after '" + which + "'");
            // NaN compares unequal and unordered, as in C.
            if (!(a == b)) order = a < b ? -1 : a > b ? 1 : 2;
        }
        bool result = false;
        if (which == "<")
            result = order < 0;
        else if (which == "<=")
            result = order <= 0;
        else if (which == "=")
            result = order == 0;
        else if (which == ">=")
            result = order == 0 || order == 1;
        else if (which == ">")
            result = order == 1;
        else
            result = order != 0;
        left = double(result);
    }
}

PovValue PovParser::additive() {
    const PovToken at = peek();
    PovValue left = multiplicative();
    for (;;) {
        const bool plus = peek().is_symbol("+");
        if (!plus && !peek().is_symbol("-")) return left;
        next();
        PovValue right = multiplicative();
        const char op = plus ? '+' : '-';
        if (std::holds_alternative<double>(left) && std::holds_alternative<double>(right)) {
            left = plus ? std::get<double>(left) + std::get<double>(right)
                        : std::get<double>(left) - std::get<double>(right);
        } else {
            left = combine(vector_of(left, at, "in + or -", 2),
                           vector_of(right, at, "in + or -", 2), op);
        }
    }
}

PovValue PovParser::multiplicative() {
    const PovToken at = peek();
    PovValue left = unary();
    for (;;) {
        const bool times = peek().is_symbol("*");
        if (!times && !peek().is_symbol("/")) return left;
        next();
        PovValue right = unary();
        if (std::holds_alternative<double>(left) && std::holds_alternative<double>(right)) {
            left = times ? std::get<double>(left) * std::get<double>(right)
                         : std::get<double>(left) / std::get<double>(right);
        } else {
            // A vector times a float scales it; two vectors multiply component by component.
            const int size = std::max(
                std::holds_alternative<PovVector>(left) ? std::get<PovVector>(left).size : 2,
                std::holds_alternative<PovVector>(right) ? std::get<PovVector>(right).size : 2);
            left = combine(vector_of(left, at, "in * or /", size),
                           vector_of(right, at, "in * or /", size), times ? '*' : '/');
        }
    }
}

PovValue PovParser::unary() {
    const PovToken& op = peek();
    if (op.is_symbol("-") || op.is_symbol("+") || op.is_symbol("!")) {
        const PovToken token = next();
        PovValue value = unary();
        if (token.text == "+") return value;
        if (token.text == "!") return double(!truthy(float_of(value, token, "after '!'")));
        if (const double* f = std::get_if<double>(&value)) return -*f;
        PovVector v = vector_of(value, token, "after '-'", 2);
        for (int i = 0; i < v.size; ++i) v[i] = -v[i];
        return v;
    }
    return postfix();
}

PovValue PovParser::postfix() {
    PovValue value = primary();
    while (peek().is_symbol(".")) {
        const PovToken dot = next();
        const PovToken member = next();
        const int index = member.kind == PovTokenKind::identifier ? member_index(member.text) : -1;
        if (index < 0)
            throw error_at(member,
                           "expected a component after '.' (x, y, z, t, u, v, red, "
                           "green, blue, filter, transmit), got " +
                               describe(member));
        const PovVector v = vector_of(value, dot, "before '.'", 2);
        if (index >= v.size)
            throw error_at(member, "a vector of " + std::to_string(v.size) +
                                       " components has no ." + member.text);
        value = v[index];
    }
    return value;
}

PovValue PovParser::primary() {
    const PovToken token = next();
    switch (token.kind) {
        case PovTokenKind::number:
            return token.number;
        case PovTokenKind::string:
            return checked_string(token.text, token);
        case PovTokenKind::symbol:
            if (token.text == "(") {
                const bool was_in_vector = in_vector_, was_item_float = item_float_;
                in_vector_ = item_float_ = false;
                PovValue value = expression();
                in_vector_ = was_in_vector;
                item_float_ = was_item_float;
                expect(")", "to close '('");
                return value;
            }
            if (token.text == "<") return vector_literal(token);
            break;
        case PovTokenKind::identifier:
            return identifier_value(token);
        default:
            break;
    }
    throw error_at(token, "expected a value, got " + describe(token));
}

PovValue PovParser::vector_literal(const PovToken& open) {
    const bool was_in_vector = in_vector_;
    in_vector_ = true;
    PovVector v;
    v.size = 0;
    // Commas between components may be left out, as in POV-Ray: `< -1 0 0 >`.
    // A comma before the closing '>' is left over, as POV-Ray reads `<0.2, 0.1, 0.5,>`.
    const auto another = [this] {
        if (accept(",")) return !peek().is_symbol(">");
        const PovToken& t = peek();
        return t.kind == PovTokenKind::number || t.kind == PovTokenKind::identifier ||
               t.is_symbol("(") || t.is_symbol("-") || t.is_symbol("+");
    };
    do {
        const PovToken at = peek();
        if (v.size == 5) throw error_at(at, "a vector has at most 5 components");
        v[v.size++] = float_of(expression(), at, "as a vector component");
    } while (another());
    in_vector_ = was_in_vector;
    expect(">", "to close the vector");
    if (v.size < 2) throw error_at(open, "a vector has at least 2 components");
    return v;
}

PovValue PovParser::color_keywords(const PovToken& first) {
    PovVector color = PovVector::of(0, 5);
    PovToken keyword = first;
    for (;;) {
        const std::string& w = keyword.text;
        if (w == "color" || w == "colour") {
            // An expression, or the keywords that follow.
            const PovToken& after = peek();
            const bool keywords = after.is_word("rgb") || after.is_word("rgbf") ||
                                  after.is_word("rgbt") || after.is_word("rgbft") ||
                                  after.is_word("red") || after.is_word("green") ||
                                  after.is_word("blue") || after.is_word("filter") ||
                                  after.is_word("transmit") || after.is_word("srgb");
            if (keywords) {
                keyword = next();
                continue;
            }
            color = vector_of(additive(), after, "after color", 5);
        } else if (w == "rgb" || w == "srgb") {
            const PovVector v = vector_of(additive(), keyword, "after " + w, 3);
            for (int i = 0; i < 3; ++i) color[i] = v[i];
            if (w == "srgb")
                for (int i = 0; i < 3; ++i)
                    color[i] = color[i] <= 0.04045 ? color[i] / 12.92
                                                   : std::pow((color[i] + 0.055) / 1.055, 2.4);
        } else if (w == "rgbf" || w == "rgbt") {
            const PovVector v = vector_of(additive(), keyword, "after " + w, 4);
            for (int i = 0; i < 3; ++i) color[i] = v[i];
            color[w == "rgbf" ? 3 : 4] = v[3];
        } else if (w == "rgbft") {
            const PovVector v = vector_of(additive(), keyword, "after rgbft", 5);
            for (int i = 0; i < 5; ++i) color[i] = v[i];
        } else {
            color[member_index(w)] = float_of(additive(), keyword, "after " + w);
        }
        // Single components may follow; another rgb starts the next colour (`checker rgb 1
        // rgb 0`).
        const PovToken& more = peek();
        if (!(more.is_word("red") || more.is_word("green") || more.is_word("blue") ||
              more.is_word("filter") || more.is_word("transmit")))
            break;
        keyword = next();
    }
    color.size = 5;
    return color;
}

PovValue PovParser::identifier_value(const PovToken& name) {
    const std::string& w = name.text;
    if (w == "color" || w == "colour" || w == "rgb" || w == "rgbf" || w == "rgbt" || w == "rgbft" ||
        w == "srgb" || w == "red" || w == "green" || w == "blue" || w == "filter" ||
        w == "transmit")
        return color_keywords(name);
    if (w == "array") return array_declaration(name);
    if (auto value = builtin(name)) return std::move(*value);
    if (item_reader_)
        if (auto item = item_reader_(name)) return std::move(*item);
    PovValue* declared = symbols_.find(w);
    if (!declared) throw error_at(name, quote(w) + " is not declared");
    if (const auto* array = std::get_if<std::shared_ptr<PovArray>>(declared);
        array && peek().is_symbol("[")) {
        return element(name, **array, false);
    }
    return *declared;
}

PovValue PovParser::array_declaration(const PovToken& keyword) {
    auto array = std::make_shared<PovArray>();
    std::size_t count = 1;
    while (peek().is_symbol("[")) {
        next();
        const PovToken at = peek();
        const double size = float_of(expression(), at, "as an array size");
        expect("]", "after the array size");
        if (!(size >= 1) || size > double(options_.max_array_elements) / double(count))
            throw error_at(at, "array size must be 1 to " +
                                   std::to_string(options_.max_array_elements) +
                                   " elements in all, got " + format_pov_number(size));
        array->sizes.push_back(std::size_t(size));
        count *= std::size_t(size);
    }
    if (array->sizes.empty()) throw error_at(keyword, "expected '[' and a size after array");
    array->elements.resize(count);
    if (accept("{")) {
        // Nested braces, one level a dimension, elements in row-major order.
        std::size_t filled = 0;
        const auto fill = [&](auto& self, std::size_t dim) -> void {
            for (std::size_t i = 0; i < array->sizes[dim]; ++i) {
                if (i > 0) accept(",");  // optional, as in POV-Ray
                if (dim + 1 < array->sizes.size()) {
                    expect("{", "to open a row of the array");
                    self(self, dim + 1);
                    expect("}", "to close a row of the array (more elements than its size?)");
                } else {
                    array->elements[filled++] = std::make_shared<PovValue>(expression());
                }
            }
        };
        fill(fill, 0);
        accept(",");
        expect("}", "to close the array (more elements than its size?)");
    }
    return array;
}

PovValue& PovParser::element(const PovToken& name, PovArray& array, bool assigning) {
    auto& slot = element_slot(name, array);
    if (!slot && !assigning)
        throw error_at(name,
                       "element of " + quote(name.text) + " is read before it is given a value");
    if (!slot) slot = std::make_shared<PovValue>(0.0);
    return *slot;
}

std::shared_ptr<PovValue>& PovParser::element_slot(const PovToken& name, PovArray& array) {
    std::size_t index = 0;
    for (std::size_t dim = 0; dim < array.sizes.size(); ++dim) {
        expect("[", "for the array's next dimension");
        const PovToken at = peek();
        const double i = float_of(expression(), at, "as an array index");
        expect("]", "after the array index");
        if (!(i >= 0) || i >= double(array.sizes[dim]))
            throw error_at(at, "index " + format_pov_number(i) + " is outside " + quote(name.text) +
                                   "'s 0.." + std::to_string(array.sizes[dim] - 1));
        index = index * array.sizes[dim] + std::size_t(i);
    }
    return array.elements[index];
}

}  // namespace glint
