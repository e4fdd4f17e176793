#include "rocksweep/records/record_suite.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "record_text.hpp"
#include "rocksweep/core/errors.hpp"

namespace rocksweep {

namespace {

namespace fs = std::filesystem;

class SuiteReader {
public:
    explicit SuiteReader(const std::string& path) : path_(path), folder_(fs::path(path).parent_path()) {}

    RecordSuite read() {
        std::ifstream in(path_);
        if (!in) throw InputError("suite", path_, "a readable CSV file (it cannot be opened)");
        RecordSuite suite;
        suite.path = path_;
        std::string text;
        for (line_ = 1; std::getline(in, text); ++line_) {
            if (line_ == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a spreadsheet's UTF-8 mark
            if (!text.empty() && text.back() == '\r') text.pop_back();
            if (text.find_first_not_of(" \t") == std::string::npos || text[text.find_first_not_of(" \t")] == '#') continue;
            std::vector<std::string> cells = split(text);
            if (header_.empty()) {
                set_header(cells, suite);
                continue;
            }
            if (cells.size() != header_.size())
                throw error(std::to_string(cells.size()) + " cells where the header has " + std::to_string(header_.size()));
            suite.records.push_back(row(cells, suite));
        }
        if (header_.empty()) throw InputError("suite", path_, "a header row naming the columns (the file has none)");
        if (suite.records.empty()) throw InputError("suite", path_, "at least one record below the header");
        return suite;
    }

private:
    InputError error(const std::string& what) const {
        return InputError("suite", path_ + " line " + std::to_string(line_), what);
    }

    // RFC 4180 without line breaks in cells: commas separate, double quotes protect commas, and
    // "" inside quotes is one quote; blanks around an unquoted cell are padding.
    std::vector<std::string> split(const std::string& text) const {
        std::vector<std::string> cells(1);
        bool quoted = false, was_quoted = false;
        for (std::size_t i = 0; i < text.size(); ++i) {
            const char c = text[i];
            if (quoted) {
                if (c != '"')
                    cells.back() += c;
                else if (i + 1 < text.size() && text[i + 1] == '"')
                    cells.back() += text[++i];
                else
                    quoted = false;
            } else if (c == '"' && cells.back().find_first_not_of(" \t") == std::string::npos) {
                cells.back().clear();
                quoted = was_quoted = true;
            } else if (c == ',') {
                cells.emplace_back();
                was_quoted = false;
            } else if (!(was_quoted && (c == ' ' || c == '\t'))) {
                if (was_quoted) throw error("text after the closing quote of cell " + std::to_string(cells.size()));
                cells.back() += c;
            }
        }
        if (quoted) throw error("a quote that is not closed (cells cannot span lines)");
        for (std::string& cell : cells) {
            const auto first = cell.find_first_not_of(" \t");
            cell = first == std::string::npos ? "" : cell.substr(first, cell.find_last_not_of(" \t") - first + 1);
        }
        return cells;
    }

    void set_header(const std::vector<std::string>& cells, RecordSuite& suite) {
        header_ = cells;
        for (std::size_t c = 0; c < cells.size(); ++c) {
            if (cells[c].empty()) throw error("column " + std::to_string(c + 1) + " of the header has no name");
            if (!index_.emplace(cells[c], c).second) throw error("column '" + cells[c] + "' appears twice in the header");
            if (std::find(suite_reading_columns.begin(), suite_reading_columns.end(), cells[c]) == suite_reading_columns.end())
                suite.metadata_columns.push_back(cells[c]);
        }
        // A spreadsheet in a locale with decimal commas saves "CSV" with ';' between cells.
        if (cells.size() == 1 && cells[0].find(';') != std::string::npos)
            throw error("cells separated by ',' (this header is separated by ';', as a spreadsheet with decimal "
                        "commas saves CSV: save as 'CSV UTF-8 (comma delimited)' with '.' decimals)");
        for (const char* required : {"name", "file", "format"})
            if (!index_.count(required))
                throw error(std::string("a header with a '") + required + "' column (see docs/records.md)");
    }

    std::string cell(const std::vector<std::string>& cells, const std::string& column) const {
        const auto it = index_.find(column);
        return it == index_.end() ? "" : cells[it->second];
    }

    double number(const std::vector<std::string>& cells, const std::string& column, double fallback) const {
        const std::string text = cell(cells, column);
        double x = fallback;
        if (!text.empty() && (!detail::to_double(text, x) || !std::isfinite(x)))
            throw error(column + " '" + text + "' is not a finite number");
        return x;
    }

    int integer(const std::vector<std::string>& cells, const std::string& column, int lo) const {
        const double x = number(cells, column, 0.0);
        if (x != std::floor(x) || x < lo || x > 1e6)
            throw error(column + " '" + cell(cells, column) + "' is not a whole number >= " + std::to_string(lo));
        return static_cast<int>(x);
    }

    /// A column of the record's file: counted from 1, empty for the format's default (0).
    int column_number(const std::vector<std::string>& cells, const std::string& column) const {
        if (cell(cells, column).empty()) return 0;
        return integer(cells, column, 1);
    }

    std::string existing_file(const std::string& column, const std::string& name) const {
        if (name.empty()) throw error(column + " is empty (the record's file, relative to the suite file)");
        const fs::path p = fs::path(name).is_absolute() ? fs::path(name) : folder_ / name;
        if (!fs::is_regular_file(p)) throw error(column + " '" + name + "' does not exist (looked for " + p.string() + ")");
        return p.string();
    }

    SuiteRecord row(const std::vector<std::string>& cells, const RecordSuite& suite) {
        SuiteRecord r;
        r.line = line_;
        r.name = cell(cells, "name");
        if (r.name.empty() ||
            r.name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-.") != std::string::npos)
            throw error("name '" + r.name + "' must be letters, digits, '_', '-' or '.' (it names the record in the output)");
        if (!names_.insert(r.name).second) throw error("name '" + r.name + "' is already used on an earlier line");
        RecordSource& s = r.source;
        const std::string format = cell(cells, "format");
        try {
            s.format = parse_record_format("format", format);
        } catch (const InputError&) {
            throw error("format '" + format + "' is not " + record_formats_allowed);
        }
        s.units = cell(cells, "units");
        if (!(s.units.empty() && s.format == RecordFormat::at2)) {
            try {
                units_to_g("units", s.units);
            } catch (const InputError&) {
                throw error("units '" + s.units + "' is not " + record_units_allowed + " (only an at2 file may leave it empty)");
            }
        }
        s.dt_s = number(cells, "dt", 0.0);
        if (s.format == RecordFormat::accel_only && s.dt_s == 0.0)
            throw error("dt is needed for an accel_only record (it has no time column)");
        if (s.dt_s != 0.0 && !(s.dt_s >= record_dt_min_s && s.dt_s <= record_dt_max_s))
            throw error("dt " + format_number(s.dt_s) + " s is outside " + format_number(record_dt_min_s) + " to " +
                        format_number(record_dt_max_s) + " s");
        s.column = column_number(cells, "column");
        s.scale = number(cells, "scale", 1.0);
        if (s.scale == 0.0) throw error("scale 0 would erase the record");
        s.skip_lines = integer(cells, "skip_lines", 0);
        s.path = existing_file("file", cell(cells, "file"));
        const std::string vfile = cell(cells, "vertical_file");
        const int vcolumn = column_number(cells, "vertical_column");
        if (!vfile.empty() || vcolumn != 0)
            s.vertical = VerticalSource{vfile.empty() ? "" : existing_file("vertical_file", vfile), vcolumn};
        for (const std::string& m : suite.metadata_columns) r.metadata.push_back(cell(cells, m));
        return r;
    }

    std::string path_;
    fs::path folder_;
    int line_ = 0;
    std::vector<std::string> header_;
    std::map<std::string, std::size_t> index_;
    std::set<std::string> names_;
};

}  // namespace

RecordSuite read_record_suite(const std::string& path) { return SuiteReader(path).read(); }

Record read_suite_record(const RecordSuite& suite, const SuiteRecord& entry) {
    // read_record's fields (simulate's options without dashes) and the suite's columns for them.
    static const std::map<std::string, std::string> column_of{
        {"record", "file"},          {"record-format", "format"}, {"record-units", "units"},
        {"record-dt", "dt"},         {"record-column", "column"}, {"record-scale", "scale"},
        {"record-skip-lines", "skip_lines"}, {"record-vertical", "vertical_file"},
        {"record-vertical-column", "vertical_column"}};
    try {
        return read_record(entry.source);
    } catch (const InputError& e) {
        const auto it = column_of.find(e.field());
        const std::string column = it == column_of.end() ? e.field() : it->second;
        throw InputError("suite", suite.path + " line " + std::to_string(entry.line),
                         "column '" + column + "' = " + e.value() + ": " + e.allowed());
    }
}

}  // namespace rocksweep
