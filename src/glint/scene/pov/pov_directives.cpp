// POV-Ray's directives: #declare and #local, #undef, #if/#ifdef/#ifndef/#elseif/#else, #while,
// #for, #switch/#case/#range/#break, #macro, #include, #version and #debug/#warning/#error.
#include <cmath>

#include "glint/scene/pov/pov_parser.h"
#include "glint/scene/quote.h"

namespace glint {

namespace {

bool opens_block(const std::string& word) {
    return word == "if" || word == "ifdef" || word == "ifndef" || word == "while" ||
           word == "for" || word == "switch" || word == "macro";
}

}  // namespace

double PovParser::parenthesized_float(std::string_view what) {
    expect("(", what);
    const double value = float_expression(what);
    expect(")", what);
    return value;
}

void PovParser::directive(const PovToken& token) {
    const Nested nested(*this, token);
    // A directive's expressions stand alone, whatever vector or item's float it interrupts.
    struct Restore {
        PovParser& parser;
        bool in_vector, item_float;
        ~Restore() {
            parser.in_vector_ = in_vector;
            parser.item_float_ = item_float;
        }
    } restore{*this, in_vector_, item_float_};
    in_vector_ = item_float_ = false;
    const std::string& word = token.text;
    if (word == "declare" || word == "local") return declare(token, word == "local");
    if (word == "undef") {
        const PovToken name = next();
        if (name.kind != PovTokenKind::identifier)
            throw error_at(name, "expected an identifier after #undef, got " + describe(name));
        if (!symbols_.undef(name.text) && macros_.erase(name.text) == 0)
            throw error_at(name, quote(name.text) + " is not declared, so #undef cannot remove it");
        return;
    }
    if (word == "if") return if_directive(token, parenthesized_float("after #if") != 0);
    if (word == "ifdef" || word == "ifndef") {
        expect("(", "after #" + word);
        const PovToken name = raw_next();
        if (name.kind != PovTokenKind::identifier)
            throw error_at(name, "expected an identifier in #" + word + ", got " + describe(name));
        bool defined = symbols_.find(name.text) || macros_.contains(name.text);
        // An array's element (`#ifdef (Names[I])`) is defined once it is given a value.
        if (peek().is_symbol("[")) {
            PovValue* value = symbols_.find(name.text);
            auto* array = value ? std::get_if<std::shared_ptr<PovArray>>(value) : nullptr;
            if (!array) throw error_at(name, quote(name.text) + " is not an array");
            defined = element_slot(name, **array) != nullptr;
        }
        expect(")", "after #" + word + "'s identifier");
        return if_directive(token, word == "ifdef" ? defined : !defined);
    }
    if (word == "else" || word == "elseif") {
        // Reached while running a branch of #if, or a clause of #switch: the rest is skipped.
        if (controls_.empty() || (controls_.back().kind != Control::Kind::if_branch &&
                                  controls_.back().kind != Control::Kind::switch_case))
            throw error_at(token, "#" + word + " without #if");
        if (controls_.back().kind == Control::Kind::switch_case) return;  // falls into #else
        skip_block(token, false);  // an #elseif's condition is never evaluated
        controls_.pop_back();
        return;
    }
    if (word == "while") return while_directive(token);
    if (word == "for") return for_directive(token);
    if (word == "switch") return switch_directive(token);
    if (word == "case" || word == "range") {
        // A clause reached from the one before it (no #break): it runs too, as in C.
        if (controls_.empty() || controls_.back().kind != Control::Kind::switch_case)
            throw error_at(token, "#" + word + " outside #switch");
        expect("(", "after #" + word);
        do expression();
        while (accept(","));
        expect(")", "after #" + word);
        return;
    }
    if (word == "break") {
        if (controls_.empty() || controls_.back().kind != Control::Kind::switch_case)
            throw error_at(token, "#break outside #switch");
        skip_block(controls_.back().directive, false);
        controls_.pop_back();
        return;
    }
    if (word == "end") return end_directive(token);
    if (word == "macro") return macro_definition(token);
    if (word == "include") return include(token);
    if (word == "fopen") return fopen_directive(token);
    if (word == "fclose") return fclose_directive(token);
    if (word == "read") return read_directive(token);
    if (word == "write") return write_directive(token);
    if (word == "version") {
        const double version = float_expression("after #version");
        symbols_.declare("version", version);
        if (token.at.file == 0 && !scene_version_) scene_version_ = version;
        accept(";");
        return;
    }
    if (word == "debug" || word == "warning") {
        messages_.push_back(string_expression("after #" + word));
        return;
    }
    if (word == "error") throw error_at(token, "#error: " + string_expression("after #error"));
    if (word == "default" && item_reader_) {
        item_reader_(token);
        return;
    }
    throw error_at(token, "#" + word + " is not supported",
                   {"glint reads POV-Ray's directives #declare, #local, #undef, #if, #ifdef, "
                    "#ifndef, #else, #elseif, #while, #for, #switch, #macro, #include, #fopen, "
                    "#fclose, #read, #write, #version, #debug, #warning and #error "
                    "(docs/povray.md)"});
}

void PovParser::declare(const PovToken& directive, bool local) {
    PovToken name = next();
    // `#declare deprecated [once] "message" Name = ...` (POV-Ray 3.7): the name follows.
    if (name.is_word("deprecated")) {
        accept_word("once");
        string_expression("after deprecated");
        name = next();
    }
    if (name.kind != PovTokenKind::identifier)
        throw error_at(
            name, "expected an identifier after #" + directive.text + ", got " + describe(name));
    // An element of a declared array: A[i][j] = value.
    if (peek().is_symbol("[")) {
        PovValue* array = symbols_.find(name.text);
        if (!array || !std::holds_alternative<std::shared_ptr<PovArray>>(*array))
            throw error_at(name, quote(name.text) + " is not an array");
        PovValue& slot = element(name, *std::get<std::shared_ptr<PovArray>>(*array), true);
        expect("=", "after the array element");
        slot = expression();
        accept(";");
        return;
    }
    expect("=", "after " + quote(name.text));
    PovValue value = expression();
    if (local)
        symbols_.local(name.text, std::move(value));
    else
        symbols_.declare(name.text, std::move(value));
    accept(";");
}

void PovParser::if_directive(const PovToken& directive, bool value) {
    if (value) {
        controls_.push_back({Control::Kind::if_branch, directive, frames_.size() - 1, 0, {}, 0, 0});
        return;
    }
    // Skip to the #else that runs, or past the #end.
    for (;;) {
        const PovToken stop = skip_block(directive, true);
        if (stop.text == "end") return;
        if (stop.text == "else") {
            controls_.push_back(
                {Control::Kind::if_branch, directive, frames_.size() - 1, 0, {}, 0, 0});
            return;
        }
        if (stop.text == "elseif") {
            if (parenthesized_float("after #elseif") != 0) {
                controls_.push_back(
                    {Control::Kind::if_branch, directive, frames_.size() - 1, 0, {}, 0, 0});
                return;
            }
            continue;
        }
        throw error_at(stop, "#" + stop.text + " inside #" + directive.text);
    }
}

PovToken PovParser::skip_block(const PovToken& opened, bool stop_at_else) {
    int depth = 0;
    for (;;) {
        const Frame& f = frames_.back();
        if (f.pos >= f.end) throw error_at(opened, "#" + opened.text + " is not closed by #end");
        PovToken token = raw_next();
        if (token.kind != PovTokenKind::directive) continue;
        if (opens_block(token.text)) {
            ++depth;
        } else if (token.text == "end") {
            if (depth == 0) return token;
            --depth;
        } else if (depth == 0 && stop_at_else &&
                   (token.text == "else" || token.text == "elseif" || token.text == "case" ||
                    token.text == "range" || token.text == "break")) {
            return token;
        }
    }
}

void PovParser::while_directive(const PovToken& directive) {
    const std::size_t at = frames_.back().pos - 1;  // the #while token, to evaluate again
    if (parenthesized_float("after #while") == 0) {
        skip_block(directive, false);
        return;
    }
    controls_.push_back({Control::Kind::while_loop, directive, frames_.size() - 1, at, {}, 0, 0});
}

void PovParser::for_directive(const PovToken& directive) {
    expect("(", "after #for");
    const PovToken name = next();
    if (name.kind != PovTokenKind::identifier)
        throw error_at(name, "expected the counter's identifier in #for, got " + describe(name));
    expect(",", "after #for's counter");
    const double start = float_expression("#for's start");
    expect(",", "after #for's start");
    const double last = float_expression("#for's end");
    double step = 1;
    if (accept(",")) step = float_expression("#for's step");
    expect(")", "after #for");
    if (step == 0 || !std::isfinite(step)) throw error_at(directive, "#for's step must not be 0");
    symbols_.local(name.text, start);
    if (step > 0 ? start > last : start < last) {
        skip_block(directive, false);
        return;
    }
    controls_.push_back({Control::Kind::for_loop, directive, frames_.size() - 1, frames_.back().pos,
                         name.text, last, step});
}

void PovParser::switch_directive(const PovToken& directive) {
    const double value = parenthesized_float("after #switch");
    // Skip to the first clause that matches (or #else), or past the #end.
    for (;;) {
        const PovToken stop = skip_block(directive, true);
        if (stop.text == "end") return;
        bool matches = stop.text == "else";
        if (stop.text == "case") {
            matches = parenthesized_float("after #case") == value;
        } else if (stop.text == "range") {
            expect("(", "after #range");
            const double low = float_expression("#range's low end");
            expect(",", "between #range's ends");
            const double high = float_expression("#range's high end");
            expect(")", "after #range");
            matches = low <= value && value <= high;
        } else if (stop.text != "else") {
            continue;  // a #break before any clause matched
        }
        if (matches) {
            controls_.push_back(
                {Control::Kind::switch_case, directive, frames_.size() - 1, 0, {}, 0, 0});
            return;
        }
    }
}

void PovParser::count_loop(const Control& control) {
    if (++loop_iterations_ > options_.max_loop_iterations)
        throw error_at(control.directive,
                       "loops ran more than " + std::to_string(options_.max_loop_iterations) +
                           " times: is this #" + control.directive.text + " endless?");
}

void PovParser::end_directive(const PovToken& directive) {
    if (controls_.empty() || controls_.size() <= frames_.back().conditions)
        throw error_at(directive, "#end without an open #if, #while, #for, #switch or #macro");
    Control& control = controls_.back();
    switch (control.kind) {
        case Control::Kind::if_branch:
        case Control::Kind::switch_case:
            controls_.pop_back();
            return;
        case Control::Kind::while_loop:
            count_loop(control);
            frames_[control.frame].pos = control.loop_to;  // to the #while, evaluated again
            controls_.pop_back();
            return;
        case Control::Kind::for_loop: {
            count_loop(control);
            PovValue* counter = symbols_.find(control.counter);
            if (!counter || !std::holds_alternative<double>(*counter))
                throw error_at(control.directive, "#for's counter " + quote(control.counter) +
                                                      " is no longer a float");
            const double value = std::get<double>(*counter) + control.step;
            *counter = value;
            if (control.step > 0 ? value > control.last : value < control.last) {
                controls_.pop_back();
                return;
            }
            frames_[control.frame].pos = control.loop_to;
            return;
        }
    }
}

void PovParser::macro_definition(const PovToken& directive) {
    Macro macro;
    macro.defined_at = directive;
    const PovToken name = raw_next();
    if (name.kind != PovTokenKind::identifier)
        throw error_at(name, "expected the macro's name after #macro, got " + describe(name));
    macro.name = name.text;
    PovToken token = raw_next();
    if (!token.is_symbol("("))
        throw error_at(token, "expected '(' after the macro name, got " + describe(token));
    token = raw_next();
    while (!token.is_symbol(")")) {
        if (token.kind != PovTokenKind::identifier)
            throw error_at(token, "expected a parameter name, got " + describe(token));
        macro.parameters.push_back(token.text);
        token = raw_next();
        if (token.is_symbol(",")) token = raw_next();
    }
    const Frame& f = frames_.back();
    macro.tokens = f.tokens;
    macro.body = f.pos;
    skip_block(directive, false);
    macro.end = frames_.back().pos - 1;  // the #end
    macros_[macro.name] = std::move(macro);
}

}  // namespace glint
