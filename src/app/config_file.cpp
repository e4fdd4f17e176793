#include "rocksweep/app/config_file.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <map>
#include <regex>

#include "rocksweep/core/errors.hpp"

namespace rocksweep {

namespace {

/// A key-value pair as read: where the key sits and what it holds, as CLI11 strings.
struct Entry {
    std::vector<std::string> path;  ///< table path and dotted key parts
    std::vector<std::string> inputs;
    int line;
};

/// The escapes of a basic string, `\n` and the like, read and written.
struct Escape {
    char letter, meaning;
};
constexpr Escape escapes[] = {{'"', '"'}, {'\\', '\\'}, {'n', '\n'}, {'t', '\t'}, {'r', '\r'}, {'b', '\b'}, {'f', '\f'}};

bool is_bare(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::string list(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "[" : ", [") + n + "]";
    return out;
}

/// One pass over the text; each method consumes what it names or throws with the line.
class Parser {
public:
    Parser(std::string text, std::string file, std::vector<std::string> tables)
        : s_(std::move(text)), file_(std::move(file)), allowed_tables_(std::move(tables)) {
        if (s_.rfind("\xEF\xBB\xBF", 0) == 0) i_ = 3;  // a BOM may open the file, nowhere else
    }

    std::vector<Entry> entries() {
        std::vector<std::string> table;
        while (!done()) {
            skip_blank();
            if (done()) break;
            if (peek() == '\r' && peek(1) == '\n') ++i_;
            if (peek() == '\n') {
                next_line();
                continue;
            }
            if (peek() == '#') {
                skip_comment();
                continue;
            }
            if (peek() == '[') {
                table = table_header();
            } else {
                Entry e;
                e.line = line_;
                e.path = table;
                for (std::string& k : key_path()) e.path.push_back(std::move(k));
                skip_blank();
                expect('=', "'=' after a key");
                skip_blank();
                e.inputs = value(true);
                out_.push_back(std::move(e));
            }
            end_of_line();
        }
        return std::move(out_);
    }

    [[noreturn]] void fail(const std::string& what, int line = 0) const {
        throw InputError("config", file_, "line " + std::to_string(line ? line : line_) + ": " + what);
    }

private:
    bool done() const { return i_ >= s_.size(); }
    char peek(std::size_t ahead = 0) const { return i_ + ahead < s_.size() ? s_[i_ + ahead] : '\0'; }
    void next_line() {
        ++i_;
        ++line_;
    }
    void skip_blank() {
        while (!done() && (peek() == ' ' || peek() == '\t')) ++i_;
    }
    void skip_comment() {
        while (!done() && peek() != '\n' && !(peek() == '\r' && peek(1) == '\n')) {
            check_char(peek(), "a comment");
            ++i_;
        }
    }
    /// Blank lines and comments, as between the values of an array.
    void skip_space_and_comments() {
        for (;;) {
            skip_blank();
            if (peek() == '\r' && peek(1) == '\n') ++i_;
            if (peek() == '\n') next_line();
            else if (peek() == '#') skip_comment();
            else return;
        }
    }
    void end_of_line() {
        skip_blank();
        if (peek() == '#') skip_comment();
        if (peek() == '\r' && peek(1) == '\n') ++i_;
        if (done()) return;
        if (peek() != '\n') fail("unexpected " + shown(peek()) + " after the value (one key = value per line)");
        next_line();
    }
    void expect(char c, const std::string& what) {
        if (peek() != c) fail("expected " + what + ", found " + (done() ? std::string("the end of the file") : shown(peek())));
        ++i_;
    }
    std::string shown(char c) const {
        const unsigned char u = static_cast<unsigned char>(c);
        if (s_.compare(i_, 3, "\xEF\xBB\xBF") == 0) return "a byte-order mark (U+FEFF)";
        if (c == '\n') return "the end of the line";
        if (u < 0x20 || u == 0x7F || u >= 0x80) {
            char buf[16];
            std::snprintf(buf, sizeof buf, "byte 0x%02X", u);
            return buf;
        }
        return std::string("'") + c + "'";
    }
    /// Control characters have no place in a TOML file outside escapes (tabs aside).
    void check_char(char c, const std::string& where) const {
        const unsigned char u = static_cast<unsigned char>(c);
        if ((u < 0x20 && c != '\t') || u == 0x7F) fail("a control character (" + shown(c) + ") in " + where);
    }

    std::vector<std::string> table_header() {
        const int line = line_;
        ++i_;
        if (peek() == '[') fail("arrays of tables ([[...]]) are not used by rocksweep");
        skip_blank();
        std::vector<std::string> path = key_path();
        skip_blank();
        expect(']', "']' closing the table name");
        if (path.size() != 1 || std::find(allowed_tables_.begin(), allowed_tables_.end(), path[0]) == allowed_tables_.end())
            fail("table [" + shorten(join(path)) + "] is not one of rocksweep's: " + list(allowed_tables_));
        if (!tables_.emplace(path, line).second)
            fail("table [" + join(path) + "] is defined twice (first on line " + std::to_string(tables_[path]) + ")");
        return path;
    }

    std::vector<std::string> key_path() {
        std::vector<std::string> parts{key()};
        for (;;) {
            skip_blank();
            if (peek() != '.') return parts;
            ++i_;
            skip_blank();
            parts.push_back(key());
        }
    }
    std::string key() {
        if (peek() == '"' || peek() == '\'') {
            std::string k = string_value();
            if (k.empty()) fail("an empty key");
            return k;
        }
        std::string k;
        while (!done() && is_bare(peek())) k += s_[i_++];
        if (k.empty()) fail("a key of letters, digits, '-' and '_', found " + (done() ? std::string("the end of the file") : shown(peek())));
        return k;
    }

    /// A value as CLI11 inputs: one string per scalar, the elements of an array.
    std::vector<std::string> value(bool top) {
        const char c = peek();
        if (c == '[') {
            if (!top) fail("arrays inside arrays are not used by rocksweep");
            ++i_;
            const int opened = line_;
            std::vector<std::string> items;
            for (;;) {
                skip_space_and_comments();
                if (done()) fail("an array without its closing ']'", opened);
                if (peek() == ']') break;
                items.push_back(value(false).front());
                skip_space_and_comments();
                if (done()) fail("an array without its closing ']'", opened);
                if (peek() == ',') {
                    ++i_;
                    continue;
                }
                if (peek() != ']') expect(']', "',' or ']' in an array");
            }
            ++i_;
            if (items.empty()) fail("an empty array: give at least one value");
            return items;
        }
        if (c == '{') fail("inline tables ({...}) are not used by rocksweep");
        if (c == '"' || c == '\'') return {string_value()};
        std::string word;
        while (!done() && (is_bare(peek()) || peek() == '.' || peek() == '+' || peek() == ':')) word += s_[i_++];
        if (word == "true" || word == "false") return {word};
        if (word.empty()) fail("a value, found " + (done() ? std::string("the end of the file") : shown(peek())));
        return {number(word)};
    }

    /// TOML numbers to what std::stod reads: underscores only between digits, then removed;
    /// 0x, 0o and 0b integers written in decimal.
    std::string number(const std::string& w) {
        const std::string body = (w[0] == '+' || w[0] == '-') ? w.substr(1) : w;
        if (body == "inf" || body == "nan") return (w[0] == '-' ? "-" : "") + body;
        if (body.size() > 1 && body[0] == '0' && (body[1] == 'x' || body[1] == 'o' || body[1] == 'b')) {
            if (body.size() != w.size()) fail("'" + shorten(w) + "' is not a number (TOML's 0x, 0o and 0b integers take no sign)");
            return based_integer(w);
        }
        std::string out;
        bool any_digit = false;
        for (std::size_t k = 0; k < w.size(); ++k) {
            const char c = w[k];
            if (c == '_') {
                if (!(k > 0 && is_digit(w[k - 1]) && k + 1 < w.size() && is_digit(w[k + 1])))
                    fail("'" + shorten(w) + "' is not a number (an underscore must sit between two digits)");
                continue;
            }
            if (!(is_digit(c) || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'))
                fail("'" + shorten(w) + "' is not a value (a string needs quotes; dates are not used by rocksweep)");
            any_digit = any_digit || is_digit(c);
            out += c;
        }
        // What is left must be one number: 1979-05-27 is made of the same characters.
        char* end = nullptr;
        std::strtod(out.c_str(), &end);
        if (!any_digit || end != out.c_str() + out.size())
            fail("'" + shorten(w) + "' is not a value (a string needs quotes; dates are not used by rocksweep)");
        return out;
    }

    /// A TOML integer in base 16 (0x), 8 (0o) or 2 (0b), as its decimal digits; at most 2^63 - 1.
    std::string based_integer(const std::string& w) {
        const int base = w[1] == 'x' ? 16 : w[1] == 'o' ? 8 : 2;
        const char* name = base == 16 ? "a hexadecimal" : base == 8 ? "an octal" : "a binary";
        const auto digit = [base](char c) {
            const int d = is_digit(c) ? c - '0' : (c >= 'a' && c <= 'f') ? c - 'a' + 10 : (c >= 'A' && c <= 'F') ? c - 'A' + 10 : 99;
            return d < base ? d : -1;
        };
        unsigned long long x = 0;
        for (std::size_t k = 2; k < w.size(); ++k) {
            if (w[k] == '_' && k > 2 && k + 1 < w.size() && digit(w[k - 1]) >= 0 && digit(w[k + 1]) >= 0) continue;
            const int d = digit(w[k]);
            if (d < 0) fail("'" + shorten(w) + "' is not " + name + " integer (digits, '_' only between two)");
            if (x > (static_cast<unsigned long long>(INT64_MAX) - d) / base)
                fail("'" + shorten(w) + "' is larger than TOML's largest integer, 2^63 - 1");
            x = x * base + d;
        }
        if (w.size() == 2) fail("'" + w + "' is not " + std::string(name) + " integer (no digits)");
        return std::to_string(x);
    }

    std::string string_value() {
        const char q = s_[i_++];
        if (peek() == q && peek(1) == q) fail("multi-line strings are not used by rocksweep");
        std::string out;
        for (;;) {
            if (done() || peek() == '\n') fail("a string without its closing quote");
            const char c = s_[i_++];
            if (c == q) return out;
            check_char(c, "a string (write it as an escape)");
            if (c != '\\' || q == '\'') {
                out += c;
                continue;
            }
            const char e = s_[i_++];
            const auto* it = std::find_if(std::begin(escapes), std::end(escapes), [e](const Escape& x) { return x.letter == e; });
            if (it == std::end(escapes)) fail(std::string("an unknown escape \\") + e + " in a string");
            out += it->meaning;
        }
    }

    static std::string join(const std::vector<std::string>& p) {
        std::string out;
        for (const std::string& k : p) out += (out.empty() ? "" : ".") + k;
        return out;
    }

    std::string s_, file_;
    std::vector<std::string> allowed_tables_;
    std::size_t i_ = 0;
    int line_ = 1;
    std::vector<Entry> out_;
    std::map<std::vector<std::string>, int> tables_;
};

/// Written bare, a value must read back as the same string: numbers as Parser::number leaves
/// them (no underscores, no sign that it would keep) and the two booleans.
bool reads_back_bare(const std::string& v) {
    static const std::regex number(R"(-?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)");
    return v == "true" || v == "false" || std::regex_match(v, number);
}

std::string toml_value(const std::string& v) {
    if (reads_back_bare(v)) return v;
    std::string out = "\"";
    for (const char c : v) {
        const auto* it = std::find_if(std::begin(escapes), std::end(escapes), [c](const Escape& x) { return x.meaning == c; });
        out += it == std::end(escapes) ? std::string(1, c) : std::string{'\\', it->letter};
    }
    return out + "\"";
}

/// An option's value for the config: what was given, else its default ("" none). CLI11 shows
/// a vector's default as "[a,b]".
std::vector<std::string> values_of(const CLI::Option& opt) {
    if (opt.count() > 0) return opt.results();
    const std::string& d = opt.get_default_str();
    if (d.empty() || opt.get_type_size_max() == 0) return {};  // flags: only when given
    if (d.size() < 2 || d.front() != '[' || d.back() != ']') return {d};
    std::vector<std::string> out;
    std::size_t from = 1;
    for (std::size_t comma; (comma = d.find(',', from)) != std::string::npos; from = comma + 1) out.push_back(d.substr(from, comma - from));
    out.push_back(d.substr(from, d.size() - 1 - from));
    return out;
}

}  // namespace

std::string effective_config(const CLI::App& app, const std::string& subcommand,
                             const std::function<bool(const std::string& name)>& written) {
    std::string out;
    auto add = [&](const CLI::App& a, const std::string& prefix) {
        for (const CLI::Option* opt : a.get_options()) {
            const std::string& name = opt->get_single_name();
            if (opt == a.get_config_ptr() || !written(name)) continue;
            const std::vector<std::string> values = values_of(*opt);
            if (values.empty()) continue;
            out += prefix + name + " = ";
            if (values.size() == 1 && opt->get_items_expected_max() <= 1) {
                out += toml_value(values[0]) + "\n";
                continue;
            }
            for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "[") + toml_value(values[i]);
            out += "]\n";
        }
    };
    add(app, "");
    if (!subcommand.empty()) add(*app.get_subcommand(subcommand), subcommand + ".");
    return out;
}

TomlConfig::TomlConfig(std::vector<std::string> subcommands, std::vector<std::string> groups,
                       std::function<std::string()> file_name)
    : subcommands_(std::move(subcommands)), groups_(std::move(groups)), file_name_(std::move(file_name)) {}

std::vector<CLI::ConfigItem> TomlConfig::from_config(std::istream& input) const {
    const std::string text{std::istreambuf_iterator<char>(input), std::istreambuf_iterator<char>()};
    std::vector<std::string> all = subcommands_;
    all.insert(all.end(), groups_.begin(), groups_.end());
    Parser parser(text, file_name_ ? file_name_() : "config", all);
    auto has = [](const std::vector<std::string>& v, const std::string& x) { return std::find(v.begin(), v.end(), x) != v.end(); };
    std::vector<CLI::ConfigItem> items;
    std::map<std::pair<std::string, std::string>, int> seen;  // (subcommand, key) -> line
    for (Entry& e : parser.entries()) {
        CLI::ConfigItem item;
        std::size_t k = 0;
        if (e.path.size() > 1 && has(subcommands_, e.path[0])) item.parents = {e.path[k++]};
        if (e.path.size() > k + 1 && has(groups_, e.path[k])) ++k;  // a group only groups
        if (e.path.size() != k + 1)
            parser.fail("key '" + shorten(e.path.back()) + "' is in table [" + shorten(e.path[0]) + "]; the tables are " + list(all), e.line);
        item.name = e.path[k];
        const std::string sub = item.parents.empty() ? "" : item.parents[0];
        // The same option twice, even under two group tables, is a mistake CLI11 would report
        // as a count mismatch: name it and both lines here.
        const auto [it, fresh] = seen.emplace(std::make_pair(sub, item.name), e.line);
        if (!fresh)
            parser.fail("key '" + shorten(item.name) + "' is set twice (first on line " + std::to_string(it->second) + ")", e.line);
        // ConfigTOML writes an option without a value as `key=""` (the /provenance/config of
        // every output): read back, that is an unset option, not an empty value.
        if (e.inputs.size() == 1 && e.inputs[0].empty()) continue;
        item.inputs = std::move(e.inputs);
        items.push_back(std::move(item));
    }
    return items;
}

}  // namespace rocksweep
