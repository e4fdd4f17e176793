#pragma once
// Private to the record readers: the text of record files, turned into numbers that remember
// the file line they came from, so that every later check can name the line.
#include <string>
#include <string_view>
#include <vector>

namespace rocksweep::detail {

/// True if the whole of `text` is one number (strict: no blanks, no trailing text; a leading
/// '+' allowed). It may be inf or nan: callers decide.
bool to_double(std::string_view text, double& x);

/// Values of one column with, for each, the 1-based line of the file it was read from.
struct Samples {
    std::vector<double> values;
    std::vector<int> lines;
};

/// A column to read (1-based) and the option that chose it, which an error about it names.
struct Wanted {
    int column;
    std::string option;
};

/// Reads the columns `wanted` of a text table: fields separated by commas or by whitespace,
/// every data line with the same number of fields, every field a finite number. Blank lines
/// and lines starting with '#' or '%' are skipped, and the first `skip_lines` lines. `field`
/// names the option in errors about the file.
std::vector<Samples> read_columns(const std::string& field, const std::string& path, int skip_lines,
                                  const std::vector<Wanted>& wanted);

/// A PEER NGA .AT2 file: unit and sampling interval from its header.
struct At2 {
    std::string units;  ///< as units_to_g spells it ("g", "cm/s^2", "m/s^2")
    double dt_s = 0.0;
    Samples samples;
};

/// Reads an .AT2 file: line 3 "... ACCELERATION ... IN UNITS OF G", line 4 either
/// "NPTS=  2000, DT=   0.020 SEC" (NGA-West2) or "2000  0.0200  NPTS, DT" (older NGA), then
/// the samples, any number a line; their count must equal NPTS.
At2 read_at2(const std::string& field, const std::string& path);

}  // namespace rocksweep::detail
