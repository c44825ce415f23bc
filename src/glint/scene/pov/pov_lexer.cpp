#include "glint/scene/pov/pov_lexer.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>

#include "glint/scene/quote.h"

namespace glint {

namespace {

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

class Lexer {
public:
    Lexer(const PovFiles& files, std::uint32_t file)
        : files_(files), file_(file), text_(files.text(file)) {}

    std::vector<PovToken> run() {
        std::vector<PovToken> tokens;
        for (;;) {
            skip_space_and_comments();
            PovToken token;
            token.at = here();
            if (pos_ >= text_.size()) {
                tokens.push_back(std::move(token));
                return tokens;
            }
            const char c = text_[pos_];
            if (is_name_start(c)) {
                token.kind = PovTokenKind::identifier;
                token.text = take_name();
            } else if (is_digit(c) ||
                       (c == '.' && pos_ + 1 < text_.size() && is_digit(text_[pos_ + 1]))) {
                read_number(token);
            } else if (c == '"') {
                read_string(token);
            } else if (c == '#') {
                advance(1);
                while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t'))
                    advance(1);
                if (pos_ >= text_.size() || !is_name_start(text_[pos_]))
                    throw files_.error_at(token.at, "expected a directive name after '#'",
                                          {"directives are #declare, #local, #include, #if, "
                                           "#while, #for, #macro and the like"});
                token.kind = PovTokenKind::directive;
                token.text = take_name();
            } else {
                read_symbol(token);
            }
            token.at.length =
                std::uint32_t(std::max<std::size_t>(1, pos_ - (line_start_ + token.at.column - 1)));
            if (token.at.line != line_) token.at.length = 1;  // a string across lines
            tokens.push_back(std::move(token));
        }
    }

private:
    PovPosition here() const { return {file_, line_, std::uint32_t(pos_ - line_start_ + 1), 1}; }

    void advance(std::size_t n) {
        for (std::size_t i = 0; i < n && pos_ < text_.size(); ++i) {
            if (text_[pos_] == '\n') {
                ++line_;
                line_start_ = pos_ + 1;
            }
            ++pos_;
        }
    }

    void skip_space_and_comments() {
        while (pos_ < text_.size()) {
            const char c = text_[pos_];
            if (std::isspace(static_cast<unsigned char>(c))) {
                advance(1);
            } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '/') {
                while (pos_ < text_.size() && text_[pos_] != '\n') advance(1);
            } else if (c == '/' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '*') {
                skip_block_comment();
            } else {
                return;
            }
        }
    }

    // POV-Ray's block comments nest: /* a /* b */ c */ is one comment.
    void skip_block_comment() {
        const PovPosition start = here();
        int depth = 0;
        while (pos_ < text_.size()) {
            if (text_.compare(pos_, 2, "/*") == 0) {
                ++depth;
                advance(2);
            } else if (text_.compare(pos_, 2, "*/") == 0) {
                advance(2);
                if (--depth == 0) return;
            } else {
                advance(1);
            }
        }
        throw files_.error_at(start, "comment is not closed: /* without */");
    }

    std::string take_name() {
        const std::size_t start = pos_;
        while (pos_ < text_.size() && is_name_char(text_[pos_])) advance(1);
        return std::string(text_.substr(start, pos_ - start));
    }

    void read_number(PovToken& token) {
        const std::size_t start = pos_;
        while (pos_ < text_.size() && is_digit(text_[pos_])) advance(1);
        if (pos_ < text_.size() && text_[pos_] == '.') {
            advance(1);
            while (pos_ < text_.size() && is_digit(text_[pos_])) advance(1);
        }
        if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
            std::size_t p = pos_ + 1;
            if (p < text_.size() && (text_[p] == '+' || text_[p] == '-')) ++p;
            if (p < text_.size() && is_digit(text_[p])) {
                advance(p - pos_);
                while (pos_ < text_.size() && is_digit(text_[pos_])) advance(1);
            }
        }
        token.kind = PovTokenKind::number;
        token.text = std::string(text_.substr(start, pos_ - start));
        // "1." is a number in POV-Ray; from_chars wants a digit after the point.
        std::string digits = token.text;
        if (digits.back() == '.') digits += '0';
        const auto [end, ec] =
            std::from_chars(digits.data(), digits.data() + digits.size(), token.number);
        if (ec != std::errc() || end != digits.data() + digits.size() ||
            !std::isfinite(token.number)) {
            PovPosition at = token.at;
            at.length = std::uint32_t(token.text.size());
            throw files_.error_at(at, "number " + token.text + " is out of range");
        }
    }

    void read_string(PovToken& token) {
        advance(1);
        token.kind = PovTokenKind::string;
        for (;;) {
            // A string may run over lines, as in POV-Ray.
            if (pos_ >= text_.size())
                throw files_.error_at(token.at, "string is not closed: \" without its \"");
            const char c = text_[pos_];
            if (c == '"') {
                advance(1);
                return;
            }
            if (c != '\\') {
                token.text += c;
                advance(1);
                continue;
            }
            const PovPosition escape = here();
            advance(1);
            const char e = pos_ < text_.size() ? text_[pos_] : '\0';
            advance(1);
            switch (e) {
                case 'a':
                    token.text += '\a';
                    break;
                case 'b':
                    token.text += '\b';
                    break;
                case 'f':
                    token.text += '\f';
                    break;
                case 'n':
                    token.text += '\n';
                    break;
                case 'r':
                    token.text += '\r';
                    break;
                case 't':
                    token.text += '\t';
                    break;
                case 'v':
                    token.text += '\v';
                    break;
                case '0':
                    token.text += '\0';
                    break;
                case '\\':
                    token.text += '\\';
                    break;
                case '\'':
                    token.text += '\'';
                    break;
                case '"':
                    token.text += '"';
                    break;
                default:
                    throw files_.error_at(escape,
                                          std::string("unknown escape \\") + e + " in a string",
                                          {"escapes are \\a \\b \\f \\n \\r \\t \\v \\0 \\\\ "
                                           "\\' \\\""});
            }
        }
    }

    void read_symbol(PovToken& token) {
        const char c = text_[pos_];
        const char next = pos_ + 1 < text_.size() ? text_[pos_ + 1] : '\0';
        token.kind = PovTokenKind::symbol;
        if ((c == '<' || c == '>' || c == '!') && next == '=') {
            token.text = {c, '='};
            advance(2);
            return;
        }
        if (std::string_view("{}()[]<>,;+-*/=!?:.&|^").find(c) == std::string_view::npos) {
            const bool printable = std::isprint(static_cast<unsigned char>(c));
            throw files_.error_at(
                here(), printable ? "unexpected character '" + std::string(1, c) + "'"
                                  : "unexpected byte " +
                                        std::to_string(int(static_cast<unsigned char>(c))));
        }
        token.text = std::string(1, c);
        advance(1);
    }

    const PovFiles& files_;
    std::uint32_t file_;
    std::string_view text_;
    std::size_t pos_ = 0;
    std::uint32_t line_ = 1;
    std::size_t line_start_ = 0;
};

}  // namespace

std::vector<PovToken> lex_pov(const PovFiles& files, std::uint32_t file) {
    return Lexer(files, file).run();
}

std::string describe(const PovToken& token) {
    switch (token.kind) {
        case PovTokenKind::identifier:
            return quote(token.text);
        case PovTokenKind::number:
            return "the number " + token.text;
        case PovTokenKind::string:
            return "the string " + quote(token.text);
        case PovTokenKind::symbol:
            return "'" + token.text + "'";
        case PovTokenKind::directive:
            return "#" + token.text;
        case PovTokenKind::end:
            return "the end of the file";
    }
    return "a token";
}

}  // namespace glint
