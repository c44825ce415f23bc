// The language core of POV-Ray's scene description language, as POV-Ray runs it: tokens come
// through directives (#declare, #if, #while, #for, #switch, #macro, #include, ...) and macro
// calls, which act on the stream as it is read, and expressions are evaluated as they are
// parsed. The scene's items (objects, textures, camera, lights) are read on top of it by their
// own parsers, which ask for tokens and values here.
#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "glint/scene/pov/pov_files.h"
#include "glint/scene/pov/pov_lexer.h"
#include "glint/scene/pov/pov_symbols.h"
#include "glint/scene/pov/pov_value.h"
#include "glint/scene/read_sandbox.h"

namespace glint {

// The standard include folders of an installed POV-Ray (Debian's povray-includes), if any.
std::vector<std::filesystem::path> default_pov_include_folders();

// Where #include looks and what bounds a scene's work (an endless #while is an error, not a hang).
struct PovLanguageOptions {
    // After the including file's folder and the scene's: `+L` folders, then POV-Ray's standard
    // includes when installed (standard_include_folders).
    std::vector<std::filesystem::path> include_folders;
    // Readable by the path found, links and all: Debian links POV-Ray's fonts there from the
    // system's font folder.
    std::vector<std::filesystem::path> standard_include_folders = default_pov_include_folders();
    const ReadSandbox* sandbox = nullptr;       // files outside it are refused; null: no checks
    double clock = 0;                           // the `clock` identifier
    int image_width = 320, image_height = 240;  // `image_width`, `image_height`
    std::int64_t max_loop_iterations = SceneLimits{}.script_loop_iterations;  // all together
    int max_macro_depth = 200;
    int max_include_depth = 64;
    std::size_t max_array_elements = std::size_t(1) << 24;
    std::size_t max_string_length = std::size_t(1) << 20;
};

class PovParser {
public:
    // Reads the scene file's text (already in `files` as file 0).
    PovParser(PovFiles& files, PovLanguageOptions options);
    const PovLanguageOptions& options() const { return options_; }
    // The render's built-in floats (image_width, image_height, clock, frame_number, ...);
    // nothing for other names.
    std::optional<double> render_float(std::string_view name) const;

    // --- Tokens ---
    // The next token after directives and macro calls, which act as it is taken.
    PovToken next();
    // The token after the current one, as a lookahead past an expression sees it: #if, #else,
    // #end and the other directives that steer have run, but a directive that acts (#declare,
    // #debug, #include, ...) or a macro's name is not acted on yet, so a value is complete
    // before the directive after it runs.
    const PovToken& peek();
    // The next token after directives and macro calls, acting on them, not taking it: what a
    // parser deciding on the next item or keyword looks at.
    const PovToken& peek_item();
    // The next token, which must be the symbol; an error naming `what` otherwise.
    void expect(std::string_view symbol, std::string_view what);
    bool accept(std::string_view symbol);  // consumes the symbol if it is next
    bool accept_word(std::string_view word);
    // Reads past the block `{ ... }` after `keyword` (its opening brace is next).
    void skip_braced(const PovToken& keyword);
    // Reads to the '}' that closes a block whose '{' has been read; `opened` names it in errors.
    void skip_to_closing_brace(const PovToken& opened);

    // --- Values ---
    PovValue expression();
    double float_expression(std::string_view what);
    // A vector of at least `size` components (a float is promoted to all of them).
    PovVector vector_expression(std::string_view what, int size = 3);
    PovVector color_expression(std::string_view what);  // a 5-vector: r, g, b, filter, transmit
    // As above, and an error unless every component is finite: what a scene's items take.
    // A '<' after an item's float starts the next value rather than comparing
    // (`vertex_vectors { 3 <0, 0, 0> ...`, `sphere_sweep { ... 0.5 <-3, 1, 0> ...`): POV-Ray
    // reads no comparison in an item's float unless it is in parentheses.
    double finite_float(std::string_view what);
    // A finite float that is a whole number in [min, max] (counts, levels).
    int whole_number(std::string_view what, int min, int max);
    // <a, b, ...> of exactly `count` finite numbers (a matrix's twelve).
    std::vector<double> finite_list(std::string_view what, std::size_t count);
    PovVector finite_vector(std::string_view what, int size = 3);
    std::string string_expression(std::string_view what);

    // What reads an item (an object, a texture, ...) where an expression finds its keyword: the
    // value of `#declare Ball = sphere { ... }`. Returns nothing for a word that starts none.
    using ItemReader = std::function<std::optional<PovValue>(const PovToken& keyword)>;
    void set_item_reader(ItemReader reader) { item_reader_ = std::move(reader); }
    // min_extent and max_extent: the corners of a declared object's bounding box.
    using ExtentReader =
        std::function<std::pair<PovVector, PovVector>(const PovItemRef&, const PovToken& at)>;
    void set_extent_reader(ExtentReader reader) { extent_reader_ = std::move(reader); }
    // trace(): where the ray from `from` along `direction` first meets a declared object, and
    // the surface's normal there (pointing out of it); nothing where it misses.
    struct TraceHit {
        PovVector point, normal;
    };
    using TraceReader = std::function<std::optional<TraceHit>(
        const std::shared_ptr<const PovItemRef>&, const PovVector& from, const PovVector& direction,
        const PovToken& at)>;
    void set_trace_reader(TraceReader reader) { trace_reader_ = std::move(reader); }

    PovSymbols& symbols() { return symbols_; }
    // The element that the subscripts next in the stream name, `name` having been read; an
    // error when it has no value.
    PovValue array_element(const PovToken& name, PovArray& array) {
        return element(name, array, false);
    }
    // The first #version of the scene file itself; none in a scene written before POV-Ray 3.7.
    std::optional<double> scene_version() const { return scene_version_; }
    // What #debug and #warning printed, in order.
    const std::vector<std::string>& messages() const { return messages_; }

    // Held while reading something that may hold itself (an expression, a directive, an
    // object): past kMaxNesting levels the scene is an error, not a stack overflow.
    static constexpr int kMaxNesting = 200;
    class Nested {
    public:
        Nested(PovParser& parser, const PovToken& at);
        ~Nested() { --parser_.nesting_; }
        Nested(const Nested&) = delete;
        Nested& operator=(const Nested&) = delete;

    private:
        PovParser& parser_;
    };

    // The file `name` as #include, #fopen and text's fonts find it: in the including file's
    // folder, the scene's, then the include folders; inside the sandbox. Its path and text.
    std::pair<std::filesystem::path, std::string> read_file(const PovToken& directive,
                                                            const PovToken& name_token,
                                                            const std::string& name,
                                                            std::string_view what);

    SceneError error_at(const PovToken& token, std::string message,
                        std::vector<std::string> notes = {}) const {
        return files_.error_at(token.at, std::move(message), std::move(notes));
    }

private:
    // A run of tokens being read: a file (the scene or an include) or a macro's body.
    struct Frame {
        const std::vector<PovToken>* tokens;
        std::size_t pos, end;
        enum class Kind { file, include, macro } kind;
        std::size_t conditions;  // the control stack's depth when it began
    };
    // An open #if, #while, #for or #switch.
    struct Control {
        enum class Kind { if_branch, while_loop, for_loop, switch_case } kind;
        PovToken directive;   // for errors
        std::size_t frame;    // frames_ index the loop runs in
        std::size_t loop_to;  // #while: its directive's index; #for: the body's first token
        std::string counter;  // #for
        double last = 0, step = 0;
    };
    struct Macro {
        std::string name;
        std::vector<std::string> parameters;
        const std::vector<PovToken>* tokens;
        std::size_t body, end;  // [body, end): the tokens between the ')' and the #end
        PovToken defined_at;
    };

    // Raw tokens, no directives.
    const PovToken& raw_peek() const;
    PovToken raw_next();
    void pop_finished_frames();
    PovToken fetch();                        // the next raw token, across frames
    bool acts(const PovToken& token) const;  // an acting directive or a macro's name
    void next_acting();                      // takes the peeked directive or macro call

    void directive(const PovToken& token);
    void declare(const PovToken& directive, bool local);
    void if_directive(const PovToken& directive, bool value);
    void skip_branch(const PovToken& directive, bool to_end);
    void while_directive(const PovToken& directive);
    void for_directive(const PovToken& directive);
    void switch_directive(const PovToken& directive);
    void end_directive(const PovToken& directive);
    void macro_definition(const PovToken& directive);
    void call_macro(const PovToken& name, const Macro& macro);
    void include(const PovToken& directive);
    // #fopen, #fclose, #read and #write (pov_file_io.cpp).
    void fopen_directive(const PovToken& directive);
    void fclose_directive(const PovToken& directive);
    void read_directive(const PovToken& directive);
    void write_directive(const PovToken& directive);
    void count_loop(const Control& control);
    // Skips raw tokens to the #end that closes an opened block (or, with stop_at_else, to an
    // #else, #elseif, #case, #range or #break at its level, which it returns).
    PovToken skip_block(const PovToken& opened, bool stop_at_else);
    double parenthesized_float(std::string_view what);

    // Expressions, by precedence.
    PovValue conditional();
    PovValue logical_or();
    PovValue logical_and();
    PovValue comparison();
    PovValue additive();
    PovValue multiplicative();
    PovValue unary();
    PovValue postfix();
    PovValue primary();
    PovValue vector_literal(const PovToken& open);
    PovValue color_keywords(const PovToken& first);
    PovValue identifier_value(const PovToken& name);
    std::optional<PovValue> builtin(const PovToken& name);
    PovValue array_declaration(const PovToken& keyword);
    // The element that [i][j]... names; reading one never given a value is an error.
    PovValue& element(const PovToken& name, PovArray& array, bool assigning);
    // The element's slot, null while it has no value: the [i][j]... after the name read.
    std::shared_ptr<PovValue>& element_slot(const PovToken& name, PovArray& array);
    std::vector<PovValue> arguments(const PovToken& name, std::size_t min, std::size_t max);
    double float_of(const PovValue& value, const PovToken& at, std::string_view what) const;
    PovVector vector_of(const PovValue& value, const PovToken& at, std::string_view what,
                        int size) const;
    std::string string_of(const PovValue& value, const PovToken& at, std::string_view what) const;
    std::string checked_string(std::string text, const PovToken& at) const;

    PovFiles& files_;
    PovLanguageOptions options_;
    std::deque<std::vector<PovToken>> token_lists_;  // every file's tokens, kept for macros
    std::vector<Frame> frames_;
    std::vector<Control> controls_;
    std::unordered_map<std::string, Macro> macros_;
    PovSymbols symbols_;
    std::vector<std::string> messages_;
    std::optional<PovToken> peeked_;
    std::optional<double> scene_version_;
    std::int64_t loop_iterations_ = 0;
    int macro_depth_ = 0;
    int nesting_ = 0;
    int include_depth_ = 0;
    // One stream of rand() numbers per seed() call, as POV-Ray keeps them.
    std::vector<std::uint32_t> random_streams_;
    bool in_vector_ = false;   // '>' closes the vector rather than comparing
    bool item_float_ = false;  // in an item's float: '<' starts the value after it
    // A scene never writes a file: what it writes is kept here, by the name it gave, for its own
    // #read and #include, and dropped with the parse.
    std::map<std::string, std::string> written_;
    std::size_t written_bytes_ = 0;
    struct OpenFile {
        std::string name;
        bool writing = false;
        std::string text;  // read: the file's text
        std::size_t at = 0;
        bool at_end = false;
    };
    std::map<std::string, OpenFile> open_files_;  // by handle
    ItemReader item_reader_;
    ExtentReader extent_reader_;
    TraceReader trace_reader_;
};

}  // namespace glint
