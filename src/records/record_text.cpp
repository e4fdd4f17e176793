#include "record_text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>

#include "rocksweep/core/errors.hpp"

namespace rocksweep::detail {

namespace {

std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// A spreadsheet's CSV separates at commas (spaces around them are padding); other files at runs
// of whitespace. Empty fields between commas are kept so that they are reported, not skipped.
std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> out;
    if (line.find(',') != std::string_view::npos) {
        for (std::size_t start = 0;;) {
            const std::size_t comma = line.find(',', start);
            out.push_back(trim(line.substr(start, comma - start)));
            if (comma == std::string_view::npos) break;
            start = comma + 1;
        }
        return out;
    }
    for (std::size_t i = 0; i < line.size();) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

double parse_number(const std::string& field, const std::string& where, std::string_view text, int column) {
    double x = 0.0;
    std::string what(1, '\'');
    what.append(text).append("' (column ").append(std::to_string(column)).append(")");
    if (text.empty()) throw InputError(field, where, "column " + std::to_string(column) + " is empty (a number was expected)");
    if (!to_double(text, x)) throw InputError(field, where, what + " is not a number");
    if (!std::isfinite(x)) throw InputError(field, where, what + " is not a finite number");
    return x;
}

std::ifstream open(const std::string& field, const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(field, path, "a readable record file (it cannot be opened)");
    return in;
}

bool is_comment_or_blank(std::string_view line) { return line.empty() || line[0] == '#' || line[0] == '%'; }

std::string at(const std::string& path, int line) { return path + " line " + std::to_string(line); }

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

// The number that follows `key` on `text` (after optional '=' and spaces), or NaN.
double number_after(const std::string& text, const std::string& key) {
    auto pos = text.find(key);
    if (pos == std::string::npos) return NAN;
    pos += key.size();
    while (pos < text.size() && (text[pos] == ' ' || text[pos] == '=')) ++pos;
    double x = NAN;
    std::from_chars(text.data() + pos, text.data() + text.size(), x);
    return x;
}

// The unit an .AT2 header names, as units_to_g spells it; "" if not known.
std::string at2_units(const std::string& unit) {
    if (unit == "G") return "g";
    for (const char* gal : {"CM/S/S", "CM/SEC/SEC", "CM/S^2", "CM/S2", "GAL"})
        if (unit == gal) return "cm/s^2";
    for (const char* si : {"M/S/S", "M/SEC/SEC", "M/S^2", "M/S2"})
        if (unit == si) return "m/s^2";
    return {};
}

}  // namespace

bool to_double(std::string_view text, double& x) {
    if (text.size() > 1 && text[0] == '+') text.remove_prefix(1);  // from_chars knows no leading '+'
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    return !text.empty() && ec == std::errc() && end == text.data() + text.size();
}

std::vector<Samples> read_columns(const std::string& field, const std::string& path, int skip_lines,
                                  const std::vector<Wanted>& wanted) {
    std::ifstream in = open(field, path);
    std::vector<Samples> out(wanted.size());
    std::size_t width = 0;
    int width_line = 0;
    std::string text;
    for (int n = 1; std::getline(in, text); ++n) {
        const std::string_view line = trim(text);
        if (n <= skip_lines || is_comment_or_blank(line)) continue;
        const std::vector<std::string_view> fields = split_fields(line);
        if (width == 0) {
            width = fields.size();
            width_line = n;
            for (const Wanted& w : wanted)
                if (w.column < 1 || static_cast<std::size_t>(w.column) > width)
                    throw InputError(w.option, std::to_string(w.column),
                                     "a column of " + path + ", 1 to " + std::to_string(width) + " (line " + std::to_string(n) +
                                         " has " + std::to_string(width) + ")");
        } else if (fields.size() != width) {
            throw InputError(field, at(path, n),
                             std::to_string(fields.size()) + " columns where line " + std::to_string(width_line) + " has " +
                                 std::to_string(width) + " (every line needs the same columns)");
        }
        for (std::size_t c = 0; c < fields.size(); ++c) {
            const double x = parse_number(field, at(path, n), fields[c], static_cast<int>(c + 1));
            for (std::size_t k = 0; k < wanted.size(); ++k) {
                if (static_cast<std::size_t>(wanted[k].column) != c + 1) continue;
                out[k].values.push_back(x);
                out[k].lines.push_back(n);
            }
        }
    }
    return out;
}

At2 read_at2(const std::string& field, const std::string& path) {
    std::ifstream in = open(field, path);
    std::string header[4];
    for (int n = 0; n < 4; ++n)
        if (!std::getline(in, header[n]))
            throw InputError(field, path,
                             "a PEER .AT2 file: four header lines, then the samples (it ends on line " + std::to_string(n) + ")");
    At2 a;
    const std::string kind = upper(header[2]);
    const auto unit_pos = kind.find("UNITS OF");
    const std::string unit = unit_pos == std::string::npos ? "" : std::string(trim(std::string_view(kind).substr(unit_pos + 8)));
    if (kind.find("ACCELERATION") == std::string::npos || unit.empty())
        throw InputError(field, at(path, 3),
                         "'" + std::string(trim(header[2])) +
                             "' does not state an acceleration unit (a PEER .AT2 says 'ACCELERATION TIME SERIES IN UNITS OF G')");
    a.units = at2_units(unit);
    if (a.units.empty()) throw InputError(field, at(path, 3), "unit '" + unit + "' is not one of G, CM/S/S, M/S/S");

    // NGA-West2 writes "NPTS=  2000, DT=   0.020 SEC"; the older NGA flatfiles "2000  0.0200  NPTS, DT".
    const std::string sizes = upper(header[3]);
    double npts = NAN;
    if (sizes.find("NPTS=") != std::string::npos || sizes.find("NPTS =") != std::string::npos) {
        npts = number_after(sizes, "NPTS");
        a.dt_s = number_after(sizes, "DT");
    } else if (sizes.find("NPTS") != std::string::npos) {
        std::istringstream numbers(sizes);
        if (!(numbers >> npts >> a.dt_s)) npts = NAN;
    }
    if (!(npts >= 1 && npts == std::floor(npts) && npts < 1e9) || !std::isfinite(a.dt_s))
        throw InputError(
            field, at(path, 4),
            "'" + std::string(trim(header[3])) + "' does not give NPTS and DT (e.g. 'NPTS=  2000, DT=   0.020 SEC')");

    std::string text;
    for (int n = 5; std::getline(in, text); ++n) {
        const std::string_view line = trim(text);
        if (line.empty()) continue;
        int column = 0;
        for (std::string_view f : split_fields(line)) {
            a.samples.values.push_back(parse_number(field, at(path, n), f, ++column));
            a.samples.lines.push_back(n);
        }
    }
    if (a.samples.values.size() != static_cast<std::size_t>(npts))
        throw InputError(field, path,
                         std::to_string(a.samples.values.size()) +
                             " samples after the header where line 4 says NPTS = " + format_number(npts));
    return a;
}

}  // namespace rocksweep::detail
