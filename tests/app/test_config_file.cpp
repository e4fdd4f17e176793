// Config files (TomlConfig) and option validators: what they accept, and how they refuse.
#include <gtest/gtest.h>

#include <sstream>

#include "rocksweep/app/config_file.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/app/option_checks.hpp"
#include "rocksweep/app/options.hpp"

using namespace rocksweep;

namespace {

std::vector<CLI::ConfigItem> read(const std::string& text) {
    const TomlConfig config({"sweep", "simulate"}, {"block", "grid"}, [] { return std::string("test.toml"); });
    std::istringstream in(text);
    return config.from_config(in);
}

/// The message of the InputError that reading `text` throws ("" if none).
std::string refusal(const std::string& text) {
    try {
        read(text);
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "config");
        EXPECT_EQ(e.value(), "test.toml");
        return e.allowed();
    }
    return "";
}

std::string check(const CLI::Validator& v, std::string in) { return v(in); }

}  // namespace

TEST(TomlConfig, ReadsTablesMultiLineArraysUnderscoresAndStrings) {
    const auto items = read(
        "\xEF\xBB\xBF# comment\n"
        "mass = 3_361.0  # kg\r\n"
        "[block]\n"
        "'half-width' = 0.30\n"
        "equations = \"non\\\"linear\"\n"
        "[grid]\n"
        "kmin-ratios = [\n  0.5, # half\n\n  1e-1,\n]\n"
        "[sweep]\n"
        "quiet = true\n"
        "output = \"\"\n");
    ASSERT_EQ(items.size(), 5u);  // output = "" is an unset option
    EXPECT_EQ(items[0].name, "mass");
    EXPECT_EQ(items[0].inputs, std::vector<std::string>{"3361.0"});
    EXPECT_TRUE(items[1].parents.empty());  // [block] only groups
    EXPECT_EQ(items[1].name, "half-width");
    EXPECT_EQ(items[2].inputs, std::vector<std::string>{"non\"linear"});
    EXPECT_EQ(items[3].inputs, (std::vector<std::string>{"0.5", "1e-1"}));
    EXPECT_EQ(items[4].parents, std::vector<std::string>{"sweep"});
    EXPECT_EQ(items[4].inputs, std::vector<std::string>{"true"});
}

TEST(TomlConfig, RefusesWithTheLine) {
    const std::pair<std::string, std::string> cases[] = {
        {"a = 1\nb = 2\na = 3\n",
         "line 3: key 'a' is set twice (first on line 1)"},
        {"mass = 1\n[block]\nmass = 2\n",
         "line 3: key 'mass' is set twice (first on line 1)"},
        {"a = 1\nb\xEF\xBB\xBF = 2\n",
         "line 2: expected '=' after a key, found a byte-order mark (U+FEFF)"},
        {"[tables]\n",
         "line 1: table [tables] is not one of rocksweep's: [sweep], [simulate], [block], [grid]"},
        {"x = [1,\n2\n",
         "line 1: an array without its closing ']'"},
        {"x = 1__0\n",
         "line 1: '1__0' is not a number (an underscore must sit between two digits)"},
        {"x = _10\n",
         "line 1: '_10' is not a number (an underscore must sit between two digits)"},
        {"x = 1 2\n",
         "line 1: unexpected '2' after the value (one key = value per line)"},
        {"x = [[1]]\n",
         "line 1: arrays inside arrays are not used by rocksweep"},
        {"x = 1979-05-27\n",
         "line 1: '1979-05-27' is not a value (a string needs quotes; dates are not used by rocksweep)"},
        {"x = \"a\n",
         "line 1: a string without its closing quote"},
        {"[grid]\n[grid]\n",
         "line 2: table [grid] is defined twice (first on line 1)"},
        {"grid.block.x = 1\n",
         "line 1: key 'x' is in table [grid]; the tables are [sweep], [simulate], [block], [grid]"},
    };
    for (const auto& [text, message] : cases) EXPECT_EQ(refusal(text), message) << text;
}

// TOML's integers in base 16, 8 and 2 (issue 21): handed on in decimal, as the validators read.
TEST(TomlConfig, ReadsHexOctalAndBinaryIntegers) {
    const auto items = read("a = 0x10\nb = 0xDEAD_beef\nc = 0o17\nd = 0b1010\ne = [0x1, 0o7]\nf = 0x7fffffffffffffff\n");
    ASSERT_EQ(items.size(), 6u);
    EXPECT_EQ(items[0].inputs, std::vector<std::string>{"16"});
    EXPECT_EQ(items[1].inputs, std::vector<std::string>{"3735928559"});
    EXPECT_EQ(items[2].inputs, std::vector<std::string>{"15"});
    EXPECT_EQ(items[3].inputs, std::vector<std::string>{"10"});
    EXPECT_EQ(items[4].inputs, (std::vector<std::string>{"1", "7"}));
    EXPECT_EQ(items[5].inputs, std::vector<std::string>{"9223372036854775807"});
    const std::pair<std::string, std::string> cases[] = {
        {"x = +0x10\n", "line 1: '+0x10' is not a number (TOML's 0x, 0o and 0b integers take no sign)"},
        {"x = 0x\n", "line 1: '0x' is not a hexadecimal integer (no digits)"},
        {"x = 0o8\n", "line 1: '0o8' is not an octal integer (digits, '_' only between two)"},
        {"x = 0b12\n", "line 1: '0b12' is not a binary integer (digits, '_' only between two)"},
        {"x = 0x_1\n", "line 1: '0x_1' is not a hexadecimal integer (digits, '_' only between two)"},
        {"x = 0x8000000000000000\n", "line 1: '0x8000000000000000' is larger than TOML's largest integer, 2^63 - 1"},
    };
    for (const auto& [text, message] : cases) EXPECT_EQ(refusal(text), message) << text;
}

TEST(TomlConfig, ReadsBackWhatEffectiveConfigWrites) {
    CLI::App app;
    double mass = 3361.0, gravity = 9.81, radius = 0.0;
    std::vector<double> range{1.0, 22.0};
    std::vector<std::string> kinds{"free", "constant"};
    std::string name = "a \"quoted\" \\ name";
    bool flag = false, other_flag = false;
    app.add_option("--mass", mass)->capture_default_str();
    app.add_option("--gravity", gravity)->capture_default_str();
    app.add_option("--radius", radius);  // no default and not given: no value to write
    app.add_option("--range", range)->expected(2)->capture_default_str();
    app.add_option("--kinds", kinds)->capture_default_str();
    app.add_option("--name", name)->capture_default_str();
    app.add_flag("--flag", flag);
    app.add_flag("--other-flag", other_flag);
    CLI::App* sweep = app.add_subcommand("sweep");
    std::size_t chunk = 512;
    std::string output;
    sweep->add_option("--chunk", chunk)->capture_default_str();
    sweep->add_option("-o,--output", output);
    CLI::App* simulate = app.add_subcommand("simulate");
    double omega = 4.0;
    simulate->add_option("--omega-ratio", omega)->capture_default_str();
    app.parse("--mass 3361.50 --kinds adaptive --flag sweep --chunk 64 -o out.h5", false);

    const std::string text =
        effective_config(app, "sweep", [](const std::string& key) { return key != "gravity" && key != "output"; });
    EXPECT_EQ(text,
              "mass = 3361.50\n"
              "range = [1, 22]\n"
              "kinds = [\"adaptive\"]\n"
              "name = \"a \\\"quoted\\\" \\\\ name\"\n"
              "flag = true\n"
              "sweep.chunk = 64\n");
    const auto items = read(text);
    ASSERT_EQ(items.size(), 6u);
    EXPECT_EQ(items[0].inputs, std::vector<std::string>{"3361.50"});  // as given: bitwise the same double
    EXPECT_EQ(items[1].inputs, (std::vector<std::string>{"1", "22"}));
    EXPECT_EQ(items[2].inputs, std::vector<std::string>{"adaptive"});
    EXPECT_EQ(items[3].inputs, std::vector<std::string>{name});
    EXPECT_EQ(items[4].inputs, std::vector<std::string>{"true"});
    EXPECT_EQ(items[5].parents, std::vector<std::string>{"sweep"});
    EXPECT_EQ(items[5].name, "chunk");
    EXPECT_EQ(items[5].inputs, std::vector<std::string>{"64"});
}

TEST(DefinesRun, KeepsWhatTheRunUsedOnly) {
    Options o;
    for (const char* key : {"output", "resume", "overwrite", "quiet"}) EXPECT_FALSE(defines_run("sweep", key, o)) << key;
    EXPECT_TRUE(defines_run("sweep", "theta-f-ratios", o));
    EXPECT_TRUE(defines_run("sweep", "mass", o));
    EXPECT_FALSE(defines_run("sweep", "paper-dt", o));
    o.grid.anchorages = {"free"};
    EXPECT_FALSE(defines_run("sweep", "theta-f-ratios", o));
    EXPECT_FALSE(defines_run("sweep", "strength-ratio", o));
    EXPECT_FALSE(defines_run("sweep", "adaptive-law", o));
    EXPECT_TRUE(defines_run("simulate", "omega-ratio", o));
    EXPECT_FALSE(defines_run("simulate", "omega-ratio-range", o));
    EXPECT_FALSE(defines_run("simulate", "theta-f-ratio", o));  // a free block
    EXPECT_FALSE(defines_run("simulate", "record-units", o));
    o.single.record = "sylmar.dat";
    o.single.anchorage = "constant";
    o.single.stiffness = 2e5;
    for (const char* key : {"pulse", "omega-ratio", "amplitude-ratio", "phase", "vertical-amplitude", "theta-f-ratio", "kmin-ratio"})
        EXPECT_FALSE(defines_run("simulate", key, o)) << key;
    for (const char* key : {"record", "record-units", "record-scale", "stiffness", "strength-ratio"})
        EXPECT_TRUE(defines_run("simulate", key, o)) << key;
    o.block.radius_m = 1.5;
    EXPECT_FALSE(defines_run("simulate", "half-width", o));
}

TEST(OptionChecks, SayWhichOfNotANumberNotAnIntegerOutOfRange) {
    const CLI::Validator mass = number_in(1e-3, 1e9, "kg");
    EXPECT_EQ(check(mass, "3361"), "");
    EXPECT_EQ(check(mass, "3x"), "3x is invalid: not a number; allowed: a number in [0.001, 1e9] kg");
    EXPECT_EQ(check(mass, " 1"), " 1 is invalid: not a number; allowed: a number in [0.001, 1e9] kg");
    EXPECT_EQ(check(mass, "nan"), "nan is invalid: not a finite number; allowed: a number in [0.001, 1e9] kg");
    EXPECT_EQ(check(mass, "1e308"), "1e308 is invalid: out of range; allowed: a number in [0.001, 1e9] kg");
    EXPECT_EQ(check(number_in(0, 1, "", true), "0"), "0 is invalid: out of range; allowed: a number in (0, 1]");
    const CLI::Validator points = integer_in(1, 100000);
    EXPECT_EQ(check(points, "181"), "");
    EXPECT_EQ(check(points, "1.5"), "1.5 is invalid: not an integer; allowed: an integer in [1, 100000]");
    EXPECT_EQ(check(points, "x"), "x is invalid: not a number; allowed: an integer in [1, 100000]");
    EXPECT_EQ(check(points, "99999999999999999999"), "99999999999999999999 is invalid: out of range; allowed: an integer in [1, 100000]");
    EXPECT_EQ(check(integer_of({1, 8}), ""), "\"\" is invalid: not a number; allowed: one of 1, 8");
    EXPECT_EQ(check(one_of({"g", "m/s^2"}), "G"), "G is invalid: not a known word; allowed: one of g, m/s^2");
    const std::string long_value(200, '7');
    EXPECT_EQ(check(mass, long_value), std::string(160, '7') + "… is invalid: out of range; allowed: a number in [0.001, 1e9] kg");
}

TEST(Errors, ValuesShortenedAndNumbersWrittenAsTyped) {
    EXPECT_EQ(shorten("abc", 2), "ab…");
    EXPECT_EQ(shorten("a\nb"), "a\\x0Ab");
    EXPECT_EQ(shorten("ééé", 2), "éé…");  // never inside a UTF-8 sequence
    EXPECT_EQ(format_short(1e308), "1e308");
    EXPECT_EQ(format_short(2.5e-7), "2.5e-7");
    EXPECT_EQ(format_number(1e-5), "1e-05");  // the form record and file messages keep
    EXPECT_EQ(format_short(0.3), "0.3");
    EXPECT_EQ(format_bound(1e12), "1e12");
}
