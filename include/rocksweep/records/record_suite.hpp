#pragma once
/// A suite of records: a CSV file (header row, one record a row) listing each record's name,
/// file and how to read it, plus any metadata columns of the user's (event, station, magnitude,
/// distance, Vs30, ...) kept as text to travel into the output beside the results.
/// Format and rules: docs/records.md.
#include <string>
#include <vector>

#include "rocksweep/records/record.hpp"

namespace rocksweep {

/// The columns that say how to read a record; every other column is metadata.
/// name, file and format are required; the rest may be absent or left empty.
inline const std::vector<std::string> suite_reading_columns = {
    "name", "file", "format", "units", "dt", "column", "scale", "vertical_file", "vertical_column", "skip_lines"};

struct SuiteRecord {
    std::string name;                   ///< unique in the suite; letters, digits, '_', '-', '.'
    RecordSource source;                ///< files resolved against the suite file's folder
    std::vector<std::string> metadata;  ///< one per RecordSuite::metadata_columns, as written
    int line = 0;                       ///< its line in the suite file
};

struct RecordSuite {
    std::string path;
    std::vector<std::string> metadata_columns;  ///< the user's own columns, in file order
    std::vector<SuiteRecord> records;
};

/// Reads and checks a suite file: a header with name, file and format; names unique; files
/// present; formats and units known (units may be empty only for at2); dt given for accel_only
/// and within the sane range; numbers well formed. Does not read the records themselves
/// (read_record does, with its own checks). Throws InputError("suite", "PATH line N", ...).
RecordSuite read_record_suite(const std::string& path);

/// read_record of one line of `suite`, its errors told in the suite file's terms: an InputError
/// of read_record (named after simulate's options, "record-units") is thrown again as
/// InputError("suite", "PATH line N", "column 'units' = VALUE: ...").
Record read_suite_record(const RecordSuite& suite, const SuiteRecord& entry);

}  // namespace rocksweep
