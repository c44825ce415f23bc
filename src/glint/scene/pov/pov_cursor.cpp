// The token stream of a POV-Ray scene: the scene file, included files and macro bodies, read
// through the directives and macro calls that act on it.
#include <algorithm>
#include <fstream>
#include <sstream>

#include "glint/scene/pov/pov_parser.h"
#include "glint/scene/quote.h"

namespace glint {

std::vector<std::filesystem::path> default_pov_include_folders() {
    std::vector<std::filesystem::path> folders;
    for (const char* folder :
         {"/usr/share/povray-3.7/include", "/usr/local/share/povray-3.7/include"}) {
        std::error_code error;
        if (std::filesystem::is_directory(folder, error)) folders.emplace_back(folder);
    }
    return folders;
}

PovParser::Nested::Nested(PovParser& parser, const PovToken& at) : parser_(parser) {
    if (++parser_.nesting_ > kMaxNesting) {
        --parser_.nesting_;
        throw parser_.error_at(at, "nested more than " + std::to_string(kMaxNesting) +
                                       " levels deep (expressions, directives inside them, or "
                                       "objects inside objects)");
    }
}

PovParser::PovParser(PovFiles& files, PovLanguageOptions options)
    : files_(files), options_(std::move(options)) {
    token_lists_.push_back(lex_pov(files_, 0));
    const auto& tokens = token_lists_.back();
    frames_.push_back({&tokens, 0, tokens.size() - 1, Frame::Kind::file, 0});
}

const PovToken& PovParser::raw_peek() const {
    const Frame& f = frames_.back();
    if (f.pos < f.end) return (*f.tokens)[f.pos];
    return f.tokens->back();  // the end token of its file
}

PovToken PovParser::raw_next() {
    Frame& f = frames_.back();
    if (f.pos < f.end) return (*f.tokens)[f.pos++];
    return f.tokens->back();
}

// A finished include or macro body hands the stream back to what called it.
void PovParser::pop_finished_frames() {
    while (frames_.size() > 1 && frames_.back().pos >= frames_.back().end) {
        const Frame& f = frames_.back();
        if (controls_.size() > f.conditions) {
            const Control& open = controls_.back();
            throw error_at(open.directive,
                           "#" + open.directive.text + " is not closed by #end " +
                               (f.kind == Frame::Kind::macro ? "in its macro" : "in its file"));
        }
        if (f.kind == Frame::Kind::macro) --macro_depth_;
        if (f.kind == Frame::Kind::include) --include_depth_;
        symbols_.pop_scope();
        frames_.pop_back();
    }
}

namespace {

// Directives that choose which tokens come next: they run even as a lookahead reads past them,
// so that a macro's value chosen by #if ... #else ... #end reads on.
bool steers(const PovToken& token) {
    static const std::string_view kSteering[] = {"if",     "ifdef", "ifndef", "else",
                                                 "elseif", "end",   "while",  "for",
                                                 "switch", "case",  "range",  "break"};
    return token.kind == PovTokenKind::directive &&
           std::find(std::begin(kSteering), std::end(kSteering), token.text) != std::end(kSteering);
}

}  // namespace

bool PovParser::acts(const PovToken& token) const {
    return token.kind == PovTokenKind::directive ||
           (token.kind == PovTokenKind::identifier && macros_.contains(token.text));
}

PovToken PovParser::fetch() {
    for (;;) {
        pop_finished_frames();
        PovToken token = raw_next();
        if (steers(token)) {
            directive(token);
            continue;
        }
        if (token.kind == PovTokenKind::end && !controls_.empty()) {
            const Control& open = controls_.back();
            throw error_at(open.directive, "#" + open.directive.text + " is not closed by #end");
        }
        return token;
    }
}

const PovToken& PovParser::peek() {
    if (!peeked_) peeked_ = fetch();
    return *peeked_;
}

const PovToken& PovParser::peek_item() {
    while (acts(peek())) next_acting();
    return *peeked_;
}

void PovParser::next_acting() {
    PovToken token = std::move(*peeked_);
    peeked_.reset();
    if (token.kind == PovTokenKind::directive)
        directive(token);
    else
        call_macro(token, macros_.at(token.text));
}

PovToken PovParser::next() {
    for (;;) {
        peek();
        if (!acts(*peeked_)) {
            PovToken token = std::move(*peeked_);
            peeked_.reset();
            return token;
        }
        next_acting();
    }
}

void PovParser::expect(std::string_view symbol, std::string_view what) {
    const PovToken token = next();
    if (!token.is_symbol(symbol))
        throw error_at(token, "expected '" + std::string(symbol) + "' " + std::string(what) +
                                  ", got " + describe(token));
}

bool PovParser::accept(std::string_view symbol) {
    if (!peek().is_symbol(symbol)) return false;
    next();
    return true;
}

bool PovParser::accept_word(std::string_view word) {
    if (!peek().is_word(word)) return false;
    next();
    return true;
}

void PovParser::skip_braced(const PovToken& keyword) {
    expect("{", "after " + keyword.text);
    skip_to_closing_brace(keyword);
}

void PovParser::skip_to_closing_brace(const PovToken& opened) {
    for (int depth = 1; depth > 0;) {
        const PovToken t = next();
        if (t.kind == PovTokenKind::end)
            throw error_at(opened, opened.text + " { is not closed by }");
        depth += t.is_symbol("{") ? 1 : t.is_symbol("}") ? -1 : 0;
    }
}

void PovParser::call_macro(const PovToken& name, const Macro& macro) {
    // Arguments are read before the body starts: in the caller's scope.
    expect("(", "after the macro name " + quote(name.text));
    std::vector<PovValue> values;
    if (!accept(")")) {
        do values.push_back(expression());
        while (accept(","));
        expect(")", "after the macro's arguments");
    }
    if (values.size() != macro.parameters.size())
        throw error_at(name,
                       "macro " + quote(name.text) + " takes " +
                           std::to_string(macro.parameters.size()) + " arguments, got " +
                           std::to_string(values.size()),
                       {"it is defined at " + files_.name(macro.defined_at.at.file) + ":" +
                        std::to_string(macro.defined_at.at.line)});
    if (macro_depth_ >= options_.max_macro_depth)
        throw error_at(name, "macros nest deeper than " + std::to_string(options_.max_macro_depth) +
                                 " calls (endless recursion?)");
    ++macro_depth_;
    symbols_.push_scope();
    for (std::size_t i = 0; i < values.size(); ++i)
        symbols_.local(macro.parameters[i], std::move(values[i]));
    frames_.push_back({macro.tokens, macro.body, macro.end, Frame::Kind::macro, controls_.size()});
}

void PovParser::include(const PovToken& directive) {
    const PovToken name_token = peek();
    const std::string name = string_expression("after #include");
    if (include_depth_ >= options_.max_include_depth)
        throw error_at(directive, "#include nests deeper than " +
                                      std::to_string(options_.max_include_depth) + " files");
    auto [found, text] = read_file(directive, name_token, name, "include file");
    const std::uint32_t file = files_.add(found.string(), std::move(text), &directive.at);
    token_lists_.push_back(lex_pov(files_, file));
    const auto& tokens = token_lists_.back();
    ++include_depth_;
    symbols_.push_scope();
    frames_.push_back({&tokens, 0, tokens.size() - 1, Frame::Kind::include, controls_.size()});
}

std::pair<std::filesystem::path, std::string> PovParser::read_file(const PovToken& directive,
                                                                   const PovToken& name_token,
                                                                   const std::string& name,
                                                                   std::string_view what) {
    // A file the scene wrote itself (#write) is read back from memory.
    if (const auto written = written_.find(name); written != written_.end())
        return {name, written->second};
    // The including file's folder, the scene's, then the include folders.
    std::vector<std::filesystem::path> folders;
    const auto folder_of = [&](std::uint32_t file) {
        return std::filesystem::path(files_.name(file)).parent_path();
    };
    folders.push_back(folder_of(directive.at.file));
    if (folder_of(0) != folders.back()) folders.push_back(folder_of(0));
    folders.insert(folders.end(), options_.include_folders.begin(), options_.include_folders.end());
    std::filesystem::path found;
    for (const auto& folder : folders) {
        std::error_code error;
        const std::filesystem::path candidate = folder / name;
        if (std::filesystem::is_regular_file(candidate, error)) {
            found = candidate;
            break;
        }
    }
    if (found.empty()) {
        std::vector<std::string> notes;
        std::string looked;
        for (const auto& folder : folders)
            looked += (looked.empty() ? "" : ", ") +
                      (folder.empty() ? std::string(".") : folder.string());
        notes.push_back("looked in " + looked);
        if (options_.include_folders.empty())
            notes.push_back("POV-Ray's standard includes come with Debian's povray-includes");
        throw error_at(name_token, "cannot find the " + std::string(what) + " " + quote(name),
                       std::move(notes));
    }
    // The include folders may be read, and the standard ones by the path found.
    const auto& standard = options_.standard_include_folders;
    if (options_.sandbox && !may_read(*options_.sandbox, found) &&
        !std::any_of(options_.include_folders.begin(), options_.include_folders.end(),
                     [&](const auto& folder) {
                         return is_inside(std::filesystem::weakly_canonical(found),
                                          std::filesystem::weakly_canonical(folder));
                     }) &&
        !std::any_of(standard.begin(), standard.end(), [&](const auto& folder) {
            return is_inside(found.lexically_normal(), folder.lexically_normal());
        }))
        throw error_at(name_token, "the scene may not read " + quote(found.string()),
                       {"allow its folder with --allow-read FOLDER"});
    std::ifstream in(found, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) throw error_at(name_token, "cannot read " + quote(found.string()));
    return {found, text.str()};
}

}  // namespace glint
