// Compiles expression text into a postfix program: a recursive-descent parser that emits
// instructions as it goes, folds constant parts, and reports errors with byte spans and notes.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "glint/geometry/expression.h"
#include "glint/sampling/perlin_noise.h"

namespace glint {

namespace {

struct Function {
    std::string_view name;
    ExpressionOp op;
    int arity;
};

// Sorted by name: the error notes list them in this order.
constexpr std::array kFunctions{
    Function{"abs", ExpressionOp::kAbs, 1},     Function{"atan2", ExpressionOp::kAtan2, 2},
    Function{"cos", ExpressionOp::kCos, 1},     Function{"exp", ExpressionOp::kExp, 1},
    Function{"floor", ExpressionOp::kFloor, 1}, Function{"log", ExpressionOp::kLog, 1},
    Function{"max", ExpressionOp::kMax, 2},     Function{"min", ExpressionOp::kMin, 2},
    Function{"noise", ExpressionOp::kNoise, 3}, Function{"sin", ExpressionOp::kSin, 1},
    Function{"sqrt", ExpressionOp::kSqrt, 1},   Function{"trunc", ExpressionOp::kTrunc, 1},
};
constexpr std::array<std::string_view, kFunctions.size()> kFunctionNames{
    "abs", "atan2", "cos", "exp", "floor", "log", "max", "min", "noise", "sin", "sqrt", "trunc"};

const Function* find_function(std::string_view name) {
    for (const Function& f : kFunctions)
        if (f.name == name) return &f;
    return nullptr;
}

// Levenshtein distance for "did you mean" notes; names here are short.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

// " (did you mean "x"?)" when a candidate is a plausible typo of `name`: at most a third of the
// longer name's length in edits (at least one), and not a complete rewrite. The same rule as
// the scene loader's suggestions.
std::string did_you_mean(std::string_view name, const std::vector<std::string_view>& candidates) {
    if (name.size() > 64) return {};
    std::string_view best;
    std::size_t best_distance = 0;
    for (const std::string_view candidate : candidates) {
        const std::size_t longer = std::max(name.size(), candidate.size());
        const std::size_t d = edit_distance(name, candidate);
        if (d > std::max<std::size_t>(1, longer / 3) || d >= longer) continue;
        if (best.empty() || d < best_distance) best = candidate, best_distance = d;
    }
    return best.empty() ? std::string() : " (did you mean \"" + std::string(best) + "\"?)";
}

std::string join(const std::vector<std::string_view>& names) {
    std::string out;
    for (const std::string_view n : names) {
        if (!out.empty()) out += ", ";
        out += n;
    }
    return out;
}

enum class TokenKind { kNumber, kName, kSymbol, kEnd };

struct Token {
    TokenKind kind = TokenKind::kEnd;
    std::size_t offset = 0;
    std::size_t length = 0;
    double number = 0;  // kNumber
    char symbol = 0;    // kSymbol: one of + - * / ^ ( ) ,
};

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_name_char(char c) { return is_name_start(c) || is_digit(c); }

// A value on the compile-time stack: where it came from, and its value if it is a constant
// (then its code is exactly the last instruction emitted for it, and it can be folded).
struct Operand {
    std::size_t begin = 0, end = 0;
    bool constant = false;
    double value = 0;
};

class Compiler {
public:
    Compiler(std::string_view source, const ExpressionConstants& constants)
        : source_(source), constants_(constants) {}

    std::optional<ExpressionError> compile(std::vector<ExpressionInstruction>& program) {
        if (!check_constants()) return error_;
        if (source_.size() > Expression::kMaxSource) {
            fail(Expression::kMaxSource, source_.size() - Expression::kMaxSource,
                 "expression too long (more than " + std::to_string(Expression::kMaxSource) +
                     " characters)");
            return error_;
        }
        if (!advance()) return error_;
        if (token_.kind == TokenKind::kEnd) {
            fail(0, source_.size(), "empty expression");
            return error_;
        }
        if (!parse_sum()) return error_;
        if (token_.kind != TokenKind::kEnd && !trailing_token_error()) return error_;
        program = std::move(code_);
        return std::nullopt;
    }

private:
    // ---- errors -------------------------------------------------------------------------
    bool fail(std::size_t offset, std::size_t length, std::string message,
              std::vector<std::string> notes = {}) {
        if (!error_) error_ = ExpressionError{offset, length, std::move(message), std::move(notes)};
        return false;
    }
    bool fail_at(const Token& t, std::string message, std::vector<std::string> notes = {}) {
        return fail(t.offset, t.length, std::move(message), std::move(notes));
    }
    std::string_view text(std::size_t begin, std::size_t end) const {
        return source_.substr(begin, end - begin);
    }
    std::string quoted(const Token& t) const {
        if (t.kind == TokenKind::kEnd) return "the end";
        // Appended piecewise: "\"" + std::string + "\"" trips GCC 12's -Wrestrict.
        std::string out(1, '"');
        out.append(text(t.offset, t.offset + t.length));
        out += '"';
        return out;
    }

    bool check_constants() {
        for (const auto& [name, value] : constants_) {
            if (name == "x" || name == "y" || name == "z")
                return fail(0, 0, "constant \"" + name + "\" would hide the coordinate " + name);
            if (!std::isfinite(value))
                return fail(0, 0, "constant \"" + name + "\" is not a finite number");
        }
        return true;
    }

    bool trailing_token_error() {
        if (token_.kind == TokenKind::kSymbol && token_.symbol == ')')
            return fail_at(token_, "unmatched \")\"");
        if (token_.kind == TokenKind::kSymbol && token_.symbol == ',')
            return fail_at(token_, "\",\" outside a function call");
        std::vector<std::string> notes;
        if (previous_kind_ == TokenKind::kNumber)
            notes.push_back("multiplication is written with \"*\", as in 2*x");
        return fail_at(token_, "missing operator before " + quoted(token_), std::move(notes));
    }

    // ---- lexer --------------------------------------------------------------------------
    bool advance() {
        previous_kind_ = token_.kind;
        while (pos_ < source_.size() && (source_[pos_] == ' ' || source_[pos_] == '\t' ||
                                         source_[pos_] == '\n' || source_[pos_] == '\r'))
            ++pos_;
        token_ = Token{TokenKind::kEnd, pos_, 0};
        if (pos_ == source_.size()) return true;
        const char c = source_[pos_];
        if (is_digit(c) || (c == '.' && pos_ + 1 < source_.size() && is_digit(source_[pos_ + 1])))
            return lex_number();
        if (is_name_start(c)) {
            std::size_t end = pos_ + 1;
            while (end < source_.size() && is_name_char(source_[end])) ++end;
            token_ = Token{TokenKind::kName, pos_, end - pos_};
            pos_ = end;
            return true;
        }
        if (std::string_view("+-*/^(),").find(c) != std::string_view::npos) {
            token_ = Token{TokenKind::kSymbol, pos_, 1, 0, c};
            ++pos_;
            return true;
        }
        // One character, which for UTF-8 may take up to four bytes.
        std::size_t length = 1;
        const auto lead = static_cast<unsigned char>(c);
        if (lead >= 0xC0) length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : 2;
        length = std::min(length, source_.size() - pos_);
        std::string shown(source_.substr(pos_, length));
        if (lead < 0x20 || lead == 0x7F) {
            constexpr char kHex[] = "0123456789abcdef";
            shown = std::string("\\x") + kHex[lead >> 4] + kHex[lead & 15];
        }
        return fail(pos_, length, "unexpected character \"" + shown + "\"",
                    {"expressions use numbers, x, y, z, named constants, + - * / ^, parentheses "
                     "and the functions " +
                     join({kFunctionNames.begin(), kFunctionNames.end()})});
    }

    // C-style: digits [. digits] [(e|E) [+-] digits], or . digits ...
    bool lex_number() {
        std::size_t end = pos_;
        while (end < source_.size() && is_digit(source_[end])) ++end;
        if (end < source_.size() && source_[end] == '.') {
            ++end;
            while (end < source_.size() && is_digit(source_[end])) ++end;
        }
        if (end < source_.size() && (source_[end] == 'e' || source_[end] == 'E')) {
            std::size_t exponent = end + 1;
            if (exponent < source_.size() && (source_[exponent] == '+' || source_[exponent] == '-'))
                ++exponent;
            if (exponent >= source_.size() || !is_digit(source_[exponent])) {
                std::size_t bad = exponent;
                while (bad < source_.size() && is_name_char(source_[bad])) ++bad;
                return fail(pos_, bad - pos_,
                            "malformed number \"" + std::string(text(pos_, bad)) + "\"",
                            {"an exponent needs digits, as in 1e-3"});
            }
            end = exponent;
            while (end < source_.size() && is_digit(source_[end])) ++end;
        }
        double value = 0;
        const auto [ptr, ec] = std::from_chars(source_.data() + pos_, source_.data() + end, value);
        if (ec == std::errc::result_out_of_range || !std::isfinite(value))
            return fail(pos_, end - pos_,
                        "number \"" + std::string(text(pos_, end)) + "\" is out of range");
        if (ec != std::errc() || ptr != source_.data() + end)
            return fail(pos_, end - pos_,
                        "malformed number \"" + std::string(text(pos_, end)) + "\"");
        token_ = Token{TokenKind::kNumber, pos_, end - pos_, value};
        pos_ = end;
        return true;
    }

    bool is_symbol(char c) const { return token_.kind == TokenKind::kSymbol && token_.symbol == c; }

    // ---- grammar ------------------------------------------------------------------------
    // sum     := product (("+" | "-") product)*
    // product := unary (("*" | "/") unary)*
    // unary   := ("-" | "+") unary | power
    // power   := primary ("^" unary)?          right-associative; -x^2 is -(x^2)
    // primary := number | name | name "(" sum ("," sum)* ")" | "(" sum ")"
    bool parse_sum() {
        if (!parse_product()) return false;
        while (is_symbol('+') || is_symbol('-')) {
            const Token op = token_;
            if (!advance() || !parse_product()) return false;
            if (!emit_binary(op.symbol == '+' ? ExpressionOp::kAdd : ExpressionOp::kSubtract) ||
                !fold_check())
                return false;
        }
        return true;
    }

    bool parse_product() {
        if (!parse_unary()) return false;
        while (is_symbol('*') || is_symbol('/')) {
            const Token op = token_;
            if (!advance() || !parse_unary()) return false;
            if (!emit_binary(op.symbol == '*' ? ExpressionOp::kMultiply : ExpressionOp::kDivide) ||
                !fold_check())
                return false;
        }
        return true;
    }

    bool parse_unary() {
        if (is_symbol('-') || is_symbol('+')) {
            const Token op = token_;
            if (!enter(op) || !advance() || !parse_unary()) return false;
            --depth_;
            if (op.symbol == '+') {
                operands_.back().begin = op.offset;
                return true;
            }
            return emit_unary(ExpressionOp::kNegate, op.offset);
        }
        return parse_power();
    }

    bool parse_power() {
        if (!parse_primary()) return false;
        if (!is_symbol('^')) return true;
        const Token op = token_;
        if (!enter(op) || !advance() || !parse_unary()) return false;
        --depth_;
        return emit_power() && fold_check();
    }

    bool parse_primary() {
        const Token t = token_;
        if (t.kind == TokenKind::kNumber)
            return push_constant(t.number, t.offset, t.offset + t.length) && advance();
        if (t.kind == TokenKind::kName) {
            if (!advance()) return false;
            if (is_symbol('(')) return parse_call(t);
            return push_name(t);
        }
        if (is_symbol('(')) {
            if (!enter(t) || !advance() || !parse_sum()) return false;
            --depth_;
            if (!is_symbol(')'))
                return fail_at(token_, "expected \")\" before " + quoted(token_),
                               {"to close the \"(\" at byte " + std::to_string(t.offset)});
            operands_.back().begin = t.offset;
            operands_.back().end = token_.offset + 1;
            return advance();
        }
        if (t.kind == TokenKind::kEnd)
            return fail_at(t, "missing operand", {"the expression ends after an operator"});
        return fail_at(t, "missing operand",
                       {"expected a number, a name or \"(\" before " + quoted(t)});
    }

    bool parse_call(const Token& name_token) {
        const std::string_view name =
            text(name_token.offset, name_token.offset + name_token.length);
        const Function* function = find_function(name);
        if (!function) {
            const std::vector<std::string_view> names(kFunctionNames.begin(), kFunctionNames.end());
            return fail_at(name_token, "unknown function \"" + std::string(name) + "\"",
                           {"functions are: " + join(names) + did_you_mean(name, names)});
        }
        if (!enter(name_token) || !advance()) return false;  // past "("
        int arguments = 0;
        if (!is_symbol(')')) {
            for (;;) {
                if (!parse_sum()) return false;
                ++arguments;
                if (is_symbol(',')) {
                    if (!advance()) return false;
                    continue;
                }
                if (is_symbol(')')) break;
                return fail_at(token_, "expected \",\" or \")\" before " + quoted(token_),
                               {"in the arguments of " + std::string(name) + "(...)"});
            }
        }
        --depth_;
        const std::size_t end = token_.offset + 1;
        if (arguments != function->arity) {
            return fail(name_token.offset, end - name_token.offset,
                        std::string(name) + " takes " + std::to_string(function->arity) +
                            (function->arity == 1 ? " argument" : " arguments") + ", got " +
                            std::to_string(arguments));
        }
        const bool ok = function->arity == 1   ? emit_unary(function->op, name_token.offset)
                        : function->arity == 2 ? emit_binary(function->op)
                                               : emit_noise();
        if (!ok) return false;
        operands_.back().begin = name_token.offset;
        operands_.back().end = end;
        if (!fold_check()) return false;
        return advance();
    }

    bool push_name(const Token& t) {
        const std::string_view name = text(t.offset, t.offset + t.length);
        const std::size_t end = t.offset + t.length;
        if (name == "x" || name == "y" || name == "z") {
            const ExpressionOp op = name == "x"   ? ExpressionOp::kX
                                    : name == "y" ? ExpressionOp::kY
                                                  : ExpressionOp::kZ;
            return push(ExpressionInstruction{op}, Operand{t.offset, end});
        }
        if (const auto it = constants_.find(name); it != constants_.end())
            return push_constant(it->second, t.offset, end);
        if (name == "pi") return push_constant(std::numbers::pi, t.offset, end);
        if (find_function(name))
            return fail_at(t, "function \"" + std::string(name) + "\" needs its argument list",
                           {"write " + std::string(name) + "(...)"});
        std::vector<std::string_view> names{"x", "y", "z"};
        for (const auto& c : constants_) names.push_back(c.first);
        if (!constants_.contains("pi")) names.push_back("pi");
        return fail_at(t, "unknown name \"" + std::string(name) + "\"",
                       {"names are: " + join(names) + did_you_mean(name, names)});
    }

    bool enter(const Token& t) {
        if (++depth_ <= Expression::kMaxNesting) return true;
        return fail_at(t, "expression nested too deeply (more than " +
                              std::to_string(Expression::kMaxNesting) + " levels)");
    }

    // ---- emission and constant folding ---------------------------------------------------
    bool push(ExpressionInstruction in, Operand operand) {
        if (code_.size() >= Expression::kMaxProgram)
            return fail(operand.begin, operand.end - operand.begin,
                        "expression too long (more than " +
                            std::to_string(Expression::kMaxProgram) + " operations)");
        code_.push_back(in);
        operands_.push_back(operand);
        return true;
    }
    bool push_constant(double value, std::size_t begin, std::size_t end) {
        return push(ExpressionInstruction{ExpressionOp::kConstant, 0, value},
                    Operand{begin, end, true, value});
    }

    // Replaces the last `count` constant operands (and their instructions) by `value`.
    void fold(int count, double value) {
        const std::size_t begin = operands_[operands_.size() - count].begin;
        const std::size_t end = operands_.back().end;
        code_.resize(code_.size() - count);
        operands_.resize(operands_.size() - count);
        code_.push_back(ExpressionInstruction{ExpressionOp::kConstant, 0, value});
        operands_.push_back(Operand{begin, end, true, value});
    }
    // A folded constant must be a real, finite number: "1/0" or "sqrt(-1)" is a mistake. Called
    // once the operand's span is final.
    bool fold_check() {
        const Operand& top = operands_.back();
        if (!top.constant || std::isfinite(top.value)) return true;
        const std::string part(text(top.begin, top.end));
        return fail(top.begin, top.end - top.begin,
                    std::isnan(top.value) ? "\"" + part + "\" has no real value"
                                          : "\"" + part + "\" is infinite");
    }

    bool emit_unary(ExpressionOp op, std::size_t begin) {
        Operand& a = operands_.back();
        a.begin = begin;
        if (a.constant) {
            fold(1, apply(op, a.value, 0));
            return true;
        }
        return push_op(ExpressionInstruction{op}, 1);
    }

    bool emit_binary(ExpressionOp op) {
        const Operand& a = operands_[operands_.size() - 2];
        const Operand& b = operands_.back();
        if (a.constant && b.constant) {
            fold(2, apply(op, a.value, b.value));
            return true;
        }
        return push_op(ExpressionInstruction{op}, 2);
    }

    bool emit_noise() {
        const Operand* p = &operands_[operands_.size() - 3];
        if (p[0].constant && p[1].constant && p[2].constant) {
            fold(3, perlin_noise(Point3{float(p[0].value), float(p[1].value), float(p[2].value)}));
            return true;
        }
        return push_op(ExpressionInstruction{ExpressionOp::kNoise}, 3);
    }

    bool emit_power() {
        const Operand& a = operands_[operands_.size() - 2];
        const Operand& b = operands_.back();
        if (a.constant && b.constant) {
            fold(2, std::pow(a.value, b.value));
            return true;
        }
        if (!b.constant) return push_op(ExpressionInstruction{ExpressionOp::kPower}, 2);
        // A constant exponent: drop its instruction and specialise the power.
        const double p = b.value;
        code_.pop_back();
        const std::size_t end = operands_.back().end;
        operands_.pop_back();
        operands_.back().end = end;
        if (p == std::nearbyint(p) && std::abs(p) <= 1 << 30)
            return push_op(ExpressionInstruction{ExpressionOp::kPowerInteger, int(p)}, 1);
        return push_op(ExpressionInstruction{ExpressionOp::kPowerConstant, 0, p}, 1);
    }

    // Pushes an operator that consumes `arity` operands and leaves one.
    bool push_op(ExpressionInstruction in, int arity) {
        const std::size_t begin = operands_[operands_.size() - arity].begin;
        const std::size_t end = operands_.back().end;
        operands_.resize(operands_.size() - arity);
        return push(in, Operand{begin, end});
    }

    static double apply(ExpressionOp op, double a, double b) {
        switch (op) {
            case ExpressionOp::kNegate:
                return -a;
            case ExpressionOp::kAdd:
                return a + b;
            case ExpressionOp::kSubtract:
                return a - b;
            case ExpressionOp::kMultiply:
                return a * b;
            case ExpressionOp::kDivide:
                return a / b;
            case ExpressionOp::kSin:
                return std::sin(a);
            case ExpressionOp::kCos:
                return std::cos(a);
            case ExpressionOp::kExp:
                return std::exp(a);
            case ExpressionOp::kLog:
                return std::log(a);
            case ExpressionOp::kSqrt:
                return std::sqrt(a);
            case ExpressionOp::kAbs:
                return std::abs(a);
            case ExpressionOp::kFloor:
                return std::floor(a);
            case ExpressionOp::kTrunc:
                return std::trunc(a);
            case ExpressionOp::kMin:
                return std::min(a, b);
            case ExpressionOp::kMax:
                return std::max(a, b);
            case ExpressionOp::kAtan2:
                return std::atan2(a, b);
            default:
                return std::numeric_limits<double>::quiet_NaN();
        }
    }

    std::string_view source_;
    const ExpressionConstants& constants_;
    std::size_t pos_ = 0;
    Token token_;
    TokenKind previous_kind_ = TokenKind::kEnd;
    int depth_ = 0;
    std::vector<ExpressionInstruction> code_;
    std::vector<Operand> operands_;
    std::optional<ExpressionError> error_;
};

// The evaluation stack's high-water mark.
int stack_depth(std::span<const ExpressionInstruction> program) {
    int depth = 0, deepest = 0;
    for (const ExpressionInstruction& in : program) {
        switch (in.op) {
            case ExpressionOp::kConstant:
            case ExpressionOp::kX:
            case ExpressionOp::kY:
            case ExpressionOp::kZ:
                ++depth;
                break;
            case ExpressionOp::kAdd:
            case ExpressionOp::kSubtract:
            case ExpressionOp::kMultiply:
            case ExpressionOp::kDivide:
            case ExpressionOp::kPower:
            case ExpressionOp::kMin:
            case ExpressionOp::kMax:
            case ExpressionOp::kAtan2:
                --depth;
                break;
            case ExpressionOp::kNoise:
                depth -= 2;
                break;
            default:
                break;  // unary: one in, one out
        }
        deepest = std::max(deepest, depth);
    }
    return deepest;
}

}  // namespace

std::span<const std::string_view> expression_functions() { return kFunctionNames; }

std::variant<Expression, ExpressionError> compile_expression(std::string_view source,
                                                             const ExpressionConstants& constants) {
    Expression expression;
    Compiler compiler(source, constants);
    if (auto error = compiler.compile(expression.program_)) return std::move(*error);
    expression.stack_depth_ = stack_depth(expression.program_);
    if (expression.stack_depth_ > Expression::kMaxStack) {
        return ExpressionError{0,
                               source.size(),
                               "expression needs more than " +
                                   std::to_string(Expression::kMaxStack) +
                                   " values at once to evaluate",
                               {"nest fewer parentheses on the right of operators"}};
    }
    expression.source_ = std::string(source);
    return expression;
}

}  // namespace glint
