// POV-Ray's language core: tokens, expressions, directives, macros, includes and limits. Where a
// value is POV-Ray's own (functions, str() formatting, rand streams, rotations), the expected
// numbers are what POV-Ray 3.7.0.10 prints for the same lines with #debug.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "glint/scene/pov/pov_parser.h"

namespace glint {
namespace {

struct Outcome {
    std::vector<std::string> tokens;    // what reaches the scene parser, as text
    std::vector<std::string> messages;  // #debug and #warning
};

PovLanguageOptions test_options() {
    PovLanguageOptions options;
    options.max_loop_iterations = 10'000;
    options.max_macro_depth = 50;
    return options;
}

Outcome run(const std::string& text, const PovLanguageOptions& options = test_options(),
            const std::string& file = "scene.pov") {
    PovFiles files;
    files.add(file, text);
    PovParser parser(files, options);
    Outcome result;
    for (PovToken token = parser.next(); token.kind != PovTokenKind::end; token = parser.next())
        result.tokens.push_back(token.text);
    result.messages = parser.messages();
    return result;
}

// The error a text gives, as glint prints it; "" when it gives none.
std::string error_of(const std::string& text, const PovLanguageOptions& options = test_options()) {
    try {
        run(text, options);
    } catch (const SceneError& e) {
        return format_scene_error(e);
    }
    return "";
}

// The #debug lines of a text.
std::vector<std::string> debug(const std::string& text) { return run(text).messages; }

TEST(PovLexer, NumbersStringsCommentsAndSymbols) {
    PovFiles files;
    files.add("a.pov",
              "1 1.5 .5 2. 1e3 2.5E-2 \"a\\tb\\\"\" /* x /* nested */ y */ // line\n"
              "<= >= != < # declare _name2 {");
    const std::vector<PovToken> tokens = lex_pov(files, 0);
    ASSERT_EQ(tokens.size(), 15u);
    const double numbers[] = {1, 1.5, 0.5, 2, 1000, 0.025};
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(tokens[i].kind, PovTokenKind::number);
        EXPECT_EQ(tokens[i].number, numbers[i]);
    }
    EXPECT_EQ(tokens[6].kind, PovTokenKind::string);
    EXPECT_EQ(tokens[6].text, "a\tb\"");
    EXPECT_TRUE(tokens[7].is_symbol("<="));
    EXPECT_TRUE(tokens[8].is_symbol(">="));
    EXPECT_TRUE(tokens[9].is_symbol("!="));
    EXPECT_TRUE(tokens[10].is_symbol("<"));
    EXPECT_TRUE(tokens[11].is(PovTokenKind::directive, "declare"));
    EXPECT_TRUE(tokens[12].is_word("_name2"));
    EXPECT_EQ(tokens[12].at.line, 2u);
    EXPECT_EQ(tokens[12].at.column, 22u);
    EXPECT_EQ(tokens[12].at.length, 6u);
    EXPECT_TRUE(tokens[13].is_symbol("{"));
    EXPECT_EQ(tokens[14].kind, PovTokenKind::end);
}

TEST(PovLexer, BadTextIsALocatedError) {
    EXPECT_EQ(error_of("#declare A = \"abc\n"),
              "scene.pov:1:14: error: string is not closed: \" without its \"\n"
              "    1 | #declare A = \"abc\n"
              "      |              ^\n");
    EXPECT_EQ(debug("#debug \"two\nlines\""), std::vector<std::string>{"two\nlines"});
    EXPECT_NE(error_of("sphere /* a /* b */").find("comment is not closed"), std::string::npos);
    EXPECT_NE(error_of("sphere @").find("unexpected character '@'"), std::string::npos);
    EXPECT_NE(error_of("\"a\\q\"").find("unknown escape \\q"), std::string::npos);
    EXPECT_NE(error_of("1e999").find("number 1e999 is out of range"), std::string::npos);
}

TEST(PovExpressions, PrecedenceAndPromotion) {
    EXPECT_EQ(debug("#debug str(1 + 2 * 3 - 4 / 2, 0, 1)"), std::vector<std::string>{"5.0"});
    EXPECT_EQ(debug("#debug str(-2 * -3, 0, 0)"), std::vector<std::string>{"6"});
    EXPECT_EQ(debug("#debug str((1 < 2) & (3 >= 3) | 0, 0, 0)"), std::vector<std::string>{"1"});
    EXPECT_EQ(debug("#debug str(0 ? 2 : 1 ? 3 : 4, 0, 0)"), std::vector<std::string>{"3"});
    EXPECT_EQ(debug("#debug str(!0 + !5, 0, 0)"), std::vector<std::string>{"1"});
    EXPECT_EQ(debug("#debug vstr(3, 2 * x + y - <0, 0, 1> / 2, \",\", 0, 1)"),
              std::vector<std::string>{"2.0,1.0,-0.5"});
    EXPECT_EQ(debug("#debug str(<1, 2, 3>.y + (x + z).z, 0, 0)"), std::vector<std::string>{"3"});
    // POV-Ray widens the shorter vector with zeros.
    EXPECT_EQ(debug("#debug vstr(5, <1,2> + <1,2,3,4,5>, \",\", 0, 0)"),
              std::vector<std::string>{"2,4,3,4,5"});
    // Strings compare by their characters, as POV-Ray compares them.
    EXPECT_EQ(debug("#declare S = \"\";\n#debug str((S != \"\") + 2 * (\"ab\" = \"ab\") + "
                    "4 * (\"b\" > \"a\") + 8 * (\"a\" >= \"b\"), 0, 0)"),
              std::vector<std::string>{"6"});
    EXPECT_NE(error_of("#if (\"a\" = 1) #end").find("expected a string after '='"),
              std::string::npos);
}

TEST(PovExpressions, FunctionsGiveWhatPovRayPrints) {
    EXPECT_EQ(debug("#debug vstr(3, vrotate(<0,1,0>, <90,0,0>), \",\", 0, 3)"),
              std::vector<std::string>{"0.000,0.000,1.000"});
    EXPECT_EQ(debug("#debug vstr(3, vrotate(<1,0,0>, <0,90,0>), \",\", 0, 3)"),
              std::vector<std::string>{"0.000,0.000,-1.000"});
    EXPECT_EQ(debug("#debug vstr(3, vaxis_rotate(<1,0,0>, <0,0,1>, 90), \",\", 0, 3)"),
              std::vector<std::string>{"0.000,1.000,0.000"});
    EXPECT_EQ(debug("#debug concat(str(-3.7,0,0), \" \", str(3.14159, 8, 3), \" \", "
                    "str(2.5, -6, 1), \" \", str(1/3, 0, -1))"),
              std::vector<std::string>{"-4    3.142 0002.5 0.333333"});
    EXPECT_EQ(debug("#debug concat(str(int(-3.7),0,0), \" \", str(mod(-7,3),0,2), \" \", "
                    "str(div(-7,3),0,2), \" \", str(log(100),0,2))"),
              std::vector<std::string>{"-3 -1.00 -2.00 2.00"});
    EXPECT_EQ(debug("#declare S = seed(42); #debug concat(str(rand(S),0,10), \" \", "
                    "str(rand(S),0,10))"),
              std::vector<std::string>{"0.7235829112 0.3299792596"});
    EXPECT_EQ(debug("#debug concat(str(select(-1, 1, 2, 3),0,0), str(select(0, 1, 2, 3),0,0), "
                    "str(select(1, 1, 2, 3),0,0), str(select(0, 1, 2),0,0))"),
              std::vector<std::string>{"1232"});
    EXPECT_EQ(debug("#debug concat(substr(\"hello\", 2, 3), \" \", strupr(\"abc\"), \" \", "
                    "chr(65), \" \", str(asc(\"A\"),0,0), \" \", str(strlen(\"hello\"),0,0), "
                    "\" \", str(val(\"2.5\"),0,1))"),
              std::vector<std::string>{"ell ABC A 65 5 2.5"});
    EXPECT_EQ(debug("#debug vstr(2, <1,2>, \", \", 3, 1)"), std::vector<std::string>{"1.0, 2.0"});
    EXPECT_EQ(debug("#debug concat(str(1e10, 0, -1), \" \", str(0.000012345, 0, -1))"),
              std::vector<std::string>{"10000000000.000000 0.000012"});
    EXPECT_EQ(debug("#debug str(vlength(<3, 4, 0>) + vdot(x, y) + min(4, 2, 3) + pow(2, 3), 0, 0)"),
              std::vector<std::string>{"15"});
}

TEST(PovExpressions, ColoursAreFiveComponentVectors) {
    EXPECT_EQ(debug("#declare C = rgb <1, 0.5, 0.25> filter 0.3; #debug vstr(5, C, \",\", 0, 2)"),
              std::vector<std::string>{"1.00,0.50,0.25,0.30,0.00"});
    EXPECT_EQ(debug("#declare C = color 0.5; #debug vstr(5, C, \",\", 0, 2)"),
              std::vector<std::string>{"0.50,0.50,0.50,0.50,0.50"});
    EXPECT_EQ(
        debug("#declare C = colour red 1 blue 0.5 transmit 0.2; #debug vstr(5, C, \",\", 0, 1)"),
        std::vector<std::string>{"1.0,0.0,0.5,0.0,0.2"});
    EXPECT_EQ(debug("#declare C = rgbt <0, 1, 0, 0.7>; #debug str(C.transmit + C.green, 0, 1)"),
              std::vector<std::string>{"1.7"});
    EXPECT_EQ(debug("#declare V = < -1 2 (1 + 2) >; #debug vstr(3, V, \",\", 0, 0)"),
              std::vector<std::string>{"-1,2,3"});
    // As POV-Ray 3.7 prints it: single components after rgb change it (another rgb starts the
    // next colour: PovScene.CommasBetweenValuesMayBeLeftOut).
    EXPECT_EQ(debug("#declare C = color rgb <1, 0.5, 0.25> green 0.1 filter 0.3;"
                    "#debug vstr(5, C, \",\", 0, 2)"),
              std::vector<std::string>{"1.00,0.10,0.25,0.30,0.00"});
}

TEST(PovDirectives, IfElseifElseNestAndSkip) {
    const std::string text = R"(
        #declare A = 2;
        #if (A = 1) one
        #elseif (A = 2) two #if (0) never #else nested #end
        #else three
        #end
        #ifdef (A) defined #end
        #ifndef (B) undefined #end
        #if (0) #while (1) #end skipped #end
    )";
    EXPECT_EQ(run(text).tokens,
              (std::vector<std::string>{"two", "nested", "defined", "undefined"}));
}

TEST(PovDirectives, WhileForAndSwitch) {
    EXPECT_EQ(run("#declare I = 0; #while (I < 3) a #declare I = I + 1; #end").tokens,
              (std::vector<std::string>{"a", "a", "a"}));
    EXPECT_EQ(debug("#for (I, 1, 7, 3) #debug str(I, 0, 0) #end"),
              (std::vector<std::string>{"1", "4", "7"}));
    EXPECT_EQ(debug("#for (I, 3, 1, -1) #debug str(I, 0, 0) #end"),
              (std::vector<std::string>{"3", "2", "1"}));
    EXPECT_TRUE(run("#for (I, 1, 0) never #end").tokens.empty());
    const std::string choose = R"(
        #switch (N)
          #case (1) one #break
          #range (2, 4) two_to_four
          #case (5) five_too #break
          #else other
        #end)";
    EXPECT_EQ(run("#declare N = 1;" + choose).tokens, std::vector<std::string>{"one"});
    EXPECT_EQ(run("#declare N = 3;" + choose).tokens,
              (std::vector<std::string>{"two_to_four", "five_too"}));  // falls through
    EXPECT_EQ(run("#declare N = 9;" + choose).tokens, std::vector<std::string>{"other"});
}

TEST(PovDirectives, MacrosTakeArgumentsAndScopeTheirLocals) {
    const std::string text = R"(
        #declare Outer = 10;
        #macro Add(A, B) (A + B) #end
        #macro Count(N) #local I = 0; #while (I < N) item #local I = I + 1; #end #end
        #macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
        #declare R = Add(Outer, 5) * 2;
        #debug str(R, 0, 0)
        Count(2)
        #debug str(Fact(5), 0, 0)
        #ifdef (I) leaked #end
        #ifdef (A) leaked #end
    )";
    const Outcome r = run(text);
    EXPECT_EQ(r.messages, (std::vector<std::string>{"30", "120"}));
    EXPECT_EQ(r.tokens, (std::vector<std::string>{"item", "item"}));
}

TEST(PovDirectives, DeclareLocalUndefVersionAndArrays) {
    const std::string text = R"(
        #version 3.6;
        #debug str(version, 0, 1)
        #declare A = array[2][3] { {1, 2, 3}, {4, 5, 6} };
        #declare A[1][0] = 40;
        #debug str(A[1][0] + A[0][2] + dimensions(A) + dimension_size(A, 2), 0, 0)
        #declare P = array[3] { <1, 2> <3, 4>, <5, 6,> };  // commas optional, as in POV-Ray
        #debug str(P[1].u + P[2].v, 0, 0)
        #declare S = "x";
        #undef S
        #ifndef (S) gone #end
        #declare B = array[2];
        #declare B[0] = "s";
        #debug B[0]
    )";
    const Outcome r = run(text);
    EXPECT_EQ(r.messages, (std::vector<std::string>{"3.6", "48", "9", "s"}));
    EXPECT_EQ(r.tokens, std::vector<std::string>{"gone"});
}

TEST(PovDirectives, MistakesAreLocatedErrors) {
    EXPECT_NE(error_of("#declare A = B + 1;").find("scene.pov:1:14: error: \"B\" is not declared"),
              std::string::npos);
    EXPECT_NE(error_of("#if (1) a").find("#if is not closed by #end"), std::string::npos);
    EXPECT_NE(error_of("#end").find("#end without an open"), std::string::npos);
    EXPECT_NE(error_of("#macro M(A) A #end M(1, 2)").find("macro \"M\" takes 1 arguments, got 2"),
              std::string::npos);
    EXPECT_NE(error_of("#declare V = <1, 2>.z;").find("has no .z"), std::string::npos);
    EXPECT_NE(error_of("#declare A = array[2]; #declare B = A[2];").find("outside \"A\"'s 0..1"),
              std::string::npos);
    EXPECT_NE(
        error_of("#declare A = array[2]; #declare B = A[1];").find("before it is given a value"),
        std::string::npos);
    EXPECT_NE(error_of("#declare A = sin(\"x\");").find("expected a float in sin, got a string"),
              std::string::npos);
    EXPECT_NE(error_of("#error \"stop here\"").find("error: #error: stop here"), std::string::npos);
    EXPECT_NE(error_of("#fopen F \"x\" read").find("cannot find the file \"x\""),
              std::string::npos);
    EXPECT_NE(
        error_of("#declare S = seed(1); #declare R = rand(S + 1);").find("rand() takes a stream"),
        std::string::npos);
}

TEST(PovDirectives, EndlessLoopsAndRunawayMacrosAreErrorsNotHangs) {
    EXPECT_NE(error_of("#while (1) #end").find("loops ran more than 10000 times"),
              std::string::npos);
    EXPECT_NE(error_of("#macro M() M() #end M()").find("macros nest deeper than 50"),
              std::string::npos);
    EXPECT_NE(error_of("#declare A = array[100000][100000];").find("array size must be"),
              std::string::npos);
    EXPECT_NE(error_of("#declare A = " + std::string(300, '(') + "1" + std::string(300, ')') + ";")
                  .find("nested more than 200 levels"),
              std::string::npos);
    PovLanguageOptions small = test_options();
    small.max_string_length = 8;
    EXPECT_NE(error_of("#declare S = concat(\"abcde\", \"fghij\");", small).find("longer than 8"),
              std::string::npos);
}

class PovIncludes : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ =
            std::filesystem::temp_directory_path() /
            ("glint_pov_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(folder_ / "lib");
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }
    void write(const std::string& name, const std::string& text) {
        std::ofstream(folder_ / name) << text;
    }
    std::filesystem::path folder_;
};

TEST_F(PovIncludes, IncludedFilesDeclareAndTheirLocalsStayInside) {
    write("shapes.inc",
          "#declare Size = 2; #local Hidden = 1; #macro Twice(V) 2 * V #end inc_token");
    write("lib/deep.inc", "#declare Deep = 7;");
    PovLanguageOptions options = test_options();
    options.include_folders = {folder_ / "lib"};
    const Outcome r =
        run("#include \"shapes.inc\" after #include \"deep.inc\"\n"
            "#debug str(Twice(Size) + Deep, 0, 0)\n#ifdef (Hidden) leaked #end",
            options, (folder_ / "scene.pov").string());
    EXPECT_EQ(r.tokens, (std::vector<std::string>{"inc_token", "after"}));
    EXPECT_EQ(r.messages, std::vector<std::string>{"11"});
}

TEST_F(PovIncludes, ErrorsInsideAnIncludeNameTheIncludeStack) {
    write("bad.inc", "#declare A = Missing;");
    std::string printed;
    try {
        run("\n#include \"bad.inc\"", test_options(), (folder_ / "scene.pov").string());
    } catch (const SceneError& e) {
        printed = format_scene_error(e);
    }
    EXPECT_NE(printed.find("bad.inc:1:14: error: \"Missing\" is not declared"), std::string::npos)
        << printed;
    EXPECT_NE(printed.find("note: included from " + (folder_ / "scene.pov").string() + ":2:1"),
              std::string::npos)
        << printed;
    try {
        run("#include \"nowhere.inc\"", test_options(), (folder_ / "scene.pov").string());
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot find the include file \"nowhere.inc\""),
                  std::string::npos);
    }
}

TEST_F(PovIncludes, TheSandboxRefusesFilesOutsideIt) {
    const std::filesystem::path outside = folder_ / "lib" / "secret.inc";
    write("lib/secret.inc", "#declare Secret = 1;");
    std::filesystem::create_directories(folder_ / "scene");
    const ReadSandbox sandbox = make_read_sandbox(folder_ / "scene" / "scene.pov");
    PovLanguageOptions options = test_options();
    options.sandbox = &sandbox;
    EXPECT_NE(error_of("#include \"" + outside.string() + "\"", options).find("may not read"),
              std::string::npos);
}

// A scene never writes a file: #write keeps its text in memory for the scene's own #read and
// #include; #read reads the scene's files through the sandbox, value by value.
TEST_F(PovIncludes, FileDirectivesWriteToMemoryAndReadBack) {
    const Outcome r =
        run("#fopen F \"data.txt\" write\n"
            "#write (F, \"\\\"two\\\",\", 2, \",\", <1, 2, 3>, \"\\n\")\n"
            "#fclose F\n"
            "#fopen F \"data.txt\" read\n"
            "#read (F, S, N, V)\n"
            "#debug concat(S, \" \", str(N, 0, 1), \" \", vstr(3, V, \",\", 0, 0))\n"
            "#debug str(defined(F), 0, 0)\n"
            "#read (F, More)\n"
            "#debug str(defined(F), 0, 0)\n"
            "#ifdef (More) defined #end\n"
            "#fclose F\n"
            "#fopen G \"part.inc\" write #write (G \"#declare Made = 7;\") #fclose G\n"
            "#include \"part.inc\" #debug str(Made, 0, 0)\n",
            test_options(), (folder_ / "scene.pov").string());
    // The last value read, the handle is undefined: a #while (defined(F)) loop ends there.
    EXPECT_EQ(r.messages, (std::vector<std::string>{"two 2.0 1,2,3", "0", "0", "7"}));
    EXPECT_TRUE(r.tokens.empty());
    EXPECT_FALSE(std::filesystem::exists(folder_ / "data.txt"));  // nothing was written
    // A file of the scene's folder, read to its end in a loop.
    write("list.txt", "1, 2,\n3");
    EXPECT_EQ(run("#declare Sum = 0; #fopen L \"list.txt\" read\n"
                  "#while (defined(L)) #read (L, X) #declare Sum = Sum + X; #end\n"
                  "#debug str(Sum, 0, 0)",
                  test_options(), (folder_ / "scene.pov").string())
                  .messages,
              std::vector<std::string>{"6"});
    write("bad.txt", "1, oops");
    EXPECT_NE(error_of("#fopen B \"" + (folder_ / "bad.txt").string() + "\" read #read (B, X, Y)")
                  .find("cannot read a value for \"Y\""),
              std::string::npos);
    EXPECT_NE(error_of("#fclose Nothing").find("is not an open file"), std::string::npos);
    EXPECT_NE(error_of("#fopen W \"w.txt\" write #read (W, X)").find("not a file open for reading"),
              std::string::npos);
    EXPECT_NE(error_of("#fopen W \"w.txt\" readonly").find("expected read, write or append"),
              std::string::npos);
    // An array's element is defined once it has a value.
    EXPECT_EQ(run("#declare A = array[2]; #declare A[1] = 3;\n"
                  "#ifdef (A[0]) zero #end #ifdef (A[1]) one #end #ifndef (A[0]) none #end")
                  .tokens,
              (std::vector<std::string>{"one", "none"}));
}

TEST_F(PovIncludes, FilesReadAreInsideTheSandbox) {
    write("lib/secret.txt", "1");
    std::filesystem::create_directories(folder_ / "scene");
    const ReadSandbox sandbox = make_read_sandbox(folder_ / "scene" / "scene.pov");
    PovLanguageOptions options = test_options();
    options.sandbox = &sandbox;
    EXPECT_NE(
        error_of("#fopen S \"" + (folder_ / "lib" / "secret.txt").string() + "\" read", options)
            .find("may not read"),
        std::string::npos);
}

TEST(PovStandardIncludes, ColorsIncDeclaresPovRaysColours) {
    PovLanguageOptions options = test_options();
    options.include_folders = default_pov_include_folders();
    options.max_loop_iterations = 10'000'000;
    if (options.include_folders.empty()) GTEST_SKIP() << "povray-includes is not installed";
    const Outcome r =
        run("#include \"colors.inc\" #debug vstr(5, Red, \",\", 0, 1)\n"
            "#debug vstr(3, NeonPink, \",\", 0, 2)",
            options);
    EXPECT_EQ(r.messages, (std::vector<std::string>{"1.0,0.0,0.0,0.0,0.0", "1.00,0.43,0.78"}));
}

}  // namespace
}  // namespace glint
