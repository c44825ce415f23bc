// POV-Ray's function { } onto glint's expression text (geometry/expression.h): numbers, x, y,
// z or the function's own parameters, + - * / ^, the built-in functions glint's expressions
// can write, declared floats and calls of declared functions (written out in place), and the
// internal functions of functions.inc whose formulas glint has.
#include <algorithm>
#include <functional>
#include <string_view>

#include "glint/geometry/expression.h"
#include "glint/scene/pov/pov_item_reader.h"
#include "glint/scene/pov/pov_polynomial.h"
#include "glint/scene/quote.h"

namespace glint {

namespace {

// functions.inc's internal functions: internal(N) with POV-Ray's formula over x, y, z ($0-$2)
// and the extra parameters after them, or none where glint cannot write it yet.
struct Internal {
    int number;
    std::string_view name;
    int arity;
    std::string_view text;
};
constexpr Internal kInternals[] = {
    {57, "f_r", 3, "sqrt($0^2+$1^2+$2^2)"},
    {60, "f_rounded_box", 7,
     "sqrt(max(0,abs($0)-($4-$3))^2+max(0,abs($1)-($5-$3))^2+max(0,abs($2)-($6-$3))^2)-$3-1e-6"},
    {61, "f_sphere", 4, "sqrt($0^2+$1^2+$2^2)-$3"},
    {68, "f_superellipsoid", 5,
     "1-((abs($0)^(2/$3)+abs($1)^(2/$3))^($3/$4)+abs($2)^(2/$4))^($4/2)"},
    {70, "f_torus", 5, "sqrt((sqrt($0^2+$2^2)-$3)^2+$1^2)-$4"},
    {47, "f_ph", 3, "atan2(sqrt($0^2+$2^2),$1)"},
    {59, "f_ridged_mf", 9, ""},
    {69, "f_th", 3, "atan2($0,$2)"},
    // POV-Ray's noise lies in [0, 1]; glint's Perlin noise, which looks alike, in [-1, 1].
    {76, "f_noise3d", 3, "(0.5+0.5*noise($0,$1,$2))"},
};

// A built-in function of POV-Ray's function language as glint's expression text of its
// arguments (each in parentheses already); empty when glint's expressions cannot write it.
struct Builtin {
    std::string_view name;
    int arity;  // -1: two or more
    std::function<std::string(const std::vector<std::string>&)> text;
};

std::string folded(std::string_view name, const std::vector<std::string>& a) {
    std::string text = a[0];
    for (std::size_t i = 1; i < a.size(); ++i)
        text = std::string(name) + "(" + text + "," + a[i] + ")";
    return text;
}

const std::vector<Builtin>& builtins() {
    using Args = std::vector<std::string>;
    const auto unary = [](std::string_view glint_name) {
        return [glint_name](const Args& a) { return std::string(glint_name) + a[0]; };
    };
    static const std::vector<Builtin> kBuiltins = {
        {"abs", 1, unary("abs")},
        {"sqrt", 1, unary("sqrt")},
        {"sin", 1, unary("sin")},
        {"cos", 1, unary("cos")},
        {"exp", 1, unary("exp")},
        {"ln", 1, unary("log")},
        {"log", 1, [](const Args& a) { return "(log" + a[0] + "/log(10))"; }},
        {"tan", 1, [](const Args& a) { return "(sin" + a[0] + "/cos" + a[0] + ")"; }},
        {"sinh", 1, [](const Args& a) { return "((exp" + a[0] + "-exp(-" + a[0] + "))/2)"; }},
        {"cosh", 1, [](const Args& a) { return "((exp" + a[0] + "+exp(-" + a[0] + "))/2)"; }},
        {"tanh", 1, [](const Args& a) { return "(1-2/(exp(2*" + a[0] + ")+1))"; }},
        {"radians", 1, [](const Args& a) { return "(" + a[0] + "*pi/180)"; }},
        {"degrees", 1, [](const Args& a) { return "(" + a[0] + "*180/pi)"; }},
        {"pow", 2, [](const Args& a) { return "(" + a[0] + "^" + a[1] + ")"; }},
        {"atan2", 2, [](const Args& a) { return "atan2(" + a[0] + "," + a[1] + ")"; }},
        {"atan", 1, [](const Args& a) { return "atan2(" + a[0] + ",1)"; }},
        {"floor", 1, unary("floor")},
        {"ceil", 1, [](const Args& a) { return "(-floor(-" + a[0] + "))"; }},
        {"int", 1, unary("trunc")},
        // POV-Ray's mod is C's fmod: the remainder takes the sign of a.
        {"mod", 2,
         [](const Args& a) {
             return "(" + a[0] + "-" + a[1] + "*trunc(" + a[0] + "/" + a[1] + "))";
         }},
        {"div", 2, [](const Args& a) { return "trunc(" + a[0] + "/" + a[1] + ")"; }},
        {"min", -1, [](const Args& a) { return folded("min", a); }},
        {"max", -1, [](const Args& a) { return folded("max", a); }},
    };
    return kBuiltins;
}

// POV-Ray's other built-in functions, which glint's expressions cannot write yet.
bool is_unwritable_builtin(std::string_view name) {
    static constexpr std::string_view kOthers[] = {"acos",  "acosh", "asin", "asinh",
                                                   "atanh", "prod",  "sum",  "select"};
    return std::find(std::begin(kOthers), std::end(kOthers), name) != std::end(kOthers);
}

// A recursive descent over the body's tokens, by POV-Ray's precedence: sums of products of
// signed powers.
class FunctionBody {
public:
    // Without parameters of its own, a function's are x, y and z, and u and v name x and y.
    FunctionBody(PovParser& parser, const std::vector<std::string>& parameters,
                 std::string& unsupported)
        : parser_(parser),
          parameters_(parameters.empty() ? kDefault : parameters),
          aliases_(parameters.empty()),
          unsupported_(unsupported) {}

    std::string sum() {
        const PovParser::Nested nested(parser_, parser_.peek());
        std::string text = product();
        while (parser_.peek().is_symbol("+") || parser_.peek().is_symbol("-")) {
            const std::string op = parser_.next().text;
            text = "(" + text + op + product() + ")";
            check_length(text);
        }
        const PovToken& after = parser_.peek();
        if (after.is_symbol("<") || after.is_symbol(">") || after.is_symbol("=") ||
            after.is_symbol("<=") || after.is_symbol(">=") || after.is_symbol("!=") ||
            after.is_symbol("&") || after.is_symbol("|") || after.is_symbol("?"))
            throw parser_.error_at(
                after,
                "comparisons and logic (" + after.text + ") in a function are not supported yet",
                {"docs/povray.md lists what glint reads"});
        return text;
    }

private:
    std::string product() {
        std::string text = signed_power();
        while (parser_.peek().is_symbol("*") || parser_.peek().is_symbol("/")) {
            const std::string op = parser_.next().text;
            text = "(" + text + op + signed_power() + ")";
        }
        return text;
    }

    std::string signed_power() {
        const PovParser::Nested nested(parser_, parser_.peek());
        if (parser_.accept("-")) return "(-" + signed_power() + ")";
        if (parser_.accept("+")) return signed_power();
        if (parser_.peek().is_symbol("!"))
            throw parser_.error_at(parser_.peek(), "logic (!) in a function is not supported yet",
                                   {"docs/povray.md lists what glint reads"});
        std::string base = primary();
        if (parser_.accept("^")) base = "(" + base + "^" + signed_power() + ")";
        return base;
    }

    std::vector<std::string> arguments(const PovToken& name) {
        parser_.expect("(", "after the function " + quote(name.text));
        std::vector<std::string> list;
        if (parser_.accept(")")) return list;
        do list.push_back("(" + sum() + ")");
        while (parser_.accept(","));
        parser_.expect(")", "after the arguments of " + quote(name.text));
        return list;
    }

    void check_arity(const PovToken& name, std::size_t given, int wanted) {
        if (wanted >= 0 ? given != std::size_t(wanted) : given < 2)
            throw parser_.error_at(name, quote(name.text) + " takes " +
                                             (wanted >= 0 ? std::to_string(wanted) : "2 or more") +
                                             " arguments, got " + std::to_string(given));
    }

    void check_length(const std::string& text) {
        if (text.size() > Expression::kMaxSource)
            throw parser_.error_at(parser_.peek(),
                                   "the function is too long for glint (more than " +
                                       std::to_string(Expression::kMaxSource) +
                                       " characters written out)");
    }

    void note_unsupported(const std::string& what) {
        if (unsupported_.empty()) unsupported_ = what;
    }

    std::string primary() {
        const PovToken t = parser_.next();
        if (t.kind == PovTokenKind::number) return expression_number(t.number);
        if (t.is_symbol("(")) {
            std::string inner = sum();
            parser_.expect(")", "to close the parenthesis");
            return inner;
        }
        if (t.kind != PovTokenKind::identifier)
            throw parser_.error_at(t,
                                   "expected a number, a parameter or a function in the "
                                   "function, got " +
                                       describe(t));
        const auto parameter = std::find(parameters_.begin(), parameters_.end(), t.text);
        if (parameter != parameters_.end())
            return "$" + std::to_string(parameter - parameters_.begin());
        if (aliases_ && (t.text == "u" || t.text == "v")) return t.text == "u" ? "$0" : "$1";
        if (t.text == "pi") return "pi";
        if (const std::optional<double> value = parser_.render_float(t.text))
            return expression_number(*value);
        if (t.text == "pattern" || t.text == "pigment" || t.text == "transform" ||
            t.text == "spline") {
            parser_.skip_braced(t);
            note_unsupported("a " + t.text + " function");
            return "0";
        }
        for (const Builtin& b : builtins())
            if (b.name == t.text) {
                const std::vector<std::string> a = arguments(t);
                check_arity(t, a.size(), b.arity);
                return b.text(a);
            }
        if (is_unwritable_builtin(t.text)) {
            arguments(t);
            note_unsupported(t.text);
            return "0";
        }
        if (const PovValue* value = parser_.symbols().find(t.text)) {
            if (const auto* number = std::get_if<double>(value)) return expression_number(*number);
            const auto* ref = std::get_if<std::shared_ptr<const PovItemRef>>(value);
            if (const PovFunction* f = ref ? std::get_if<PovFunction>(&(*ref)->item) : nullptr) {
                const std::vector<std::string> a = arguments(t);
                if (f->arity >= 0) check_arity(t, a.size(), f->arity);
                // A pigment function's member (.red, .gray, ...).
                if (parser_.accept(".")) parser_.next();
                if (!f->unsupported.empty()) note_unsupported(f->unsupported);
                std::string text = call_text(*f, a);
                check_length(text);
                return text;
            }
        }
        throw parser_.error_at(t, quote(t.text) +
                                      " is not a parameter, a declared float or a "
                                      "function glint reads in a function");
    }

    static inline const std::vector<std::string> kDefault{"x", "y", "z"};
    PovParser& parser_;
    const std::vector<std::string>& parameters_;
    bool aliases_;
    std::string& unsupported_;
};

}  // namespace

std::string call_text(const PovFunction& function, const std::vector<std::string>& arguments) {
    std::string out;
    const std::string& text = function.text;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '$') {
            out += text[i];
            continue;
        }
        std::size_t index = 0;
        while (i + 1 < text.size() && text[i + 1] >= '0' && text[i + 1] <= '9')
            index = 10 * index + std::size_t(text[++i] - '0');
        out += index < arguments.size() ? arguments[index] : "0";
    }
    return out;
}

std::string PovItemReader::function_body(const std::vector<std::string>& parameters,
                                         std::string& unsupported) {
    FunctionBody body(parser_, parameters, unsupported);
    return body.sum();
}

PovFunction PovItemReader::function(const PovToken& keyword) {
    PovFunction f;
    f.at = keyword.at;
    std::vector<std::string> parameters;  // none: x, y and z
    if (parser_.accept("(")) {
        if (!parser_.accept(")")) {
            do {
                const PovToken name = parser_.next();
                if (name.kind != PovTokenKind::identifier)
                    throw parser_.error_at(name,
                                           "expected a parameter name, got " + describe(name));
                parameters.push_back(name.text);
            } while (parser_.accept(","));
            parser_.expect(")", "after the function's parameters");
        }
        f.arity = int(parameters.size());
    }
    parser_.expect("{", "after function");
    if (parser_.peek().is_word("internal")) {
        const PovToken internal = parser_.next();
        parser_.expect("(", "after internal");
        const int number = parser_.whole_number("as the internal function's number", 0, 1000);
        parser_.expect(")", "after the internal function's number");
        parser_.expect("}", "after internal( )");
        for (const Internal& i : kInternals)
            if (i.number == number) {
                f.arity = i.arity;
                f.text = i.text;
                if (f.text.empty()) f.unsupported = i.name;
                return f;
            }
        // Its arity is unknown here: any call stops at `unsupported` anyway.
        f.arity = -1;
        f.unsupported = internal.text + "(" + std::to_string(number) + ")";
        return f;
    }
    f.text = function_body(parameters, f.unsupported);
    parser_.expect("}", "to close the function");
    return f;
}

}  // namespace glint
