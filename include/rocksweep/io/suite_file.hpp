#pragma once
/// The record-suite HDF5 file: the records with their intensity measures and metadata, one
/// group per anchorage scenario holding the [record, alpha, radius, intensity] results, and, once
/// the sweep is complete, the overturning spectrum and the fragility curves of each scenario.
/// Layout: docs/suite.md; written while the suite runs by SuiteStream (suite_stream.hpp).
#include <string>
#include <vector>

#include "rocksweep/io/spectra_file.hpp"
#include "rocksweep/records/suite_products.hpp"

namespace rocksweep {

/// Throws InputError("suite", "SUITE line N", ...) for the first record whose name cannot name
/// its group /records/NAME: "." or "..", or a dataset of /records (pga_g, record, intensity, ...).
/// Checked before any work, and again when the file is laid out.
void check_record_names(const SuiteSpec& spec);

/// Reads back the results of a suite file for the same spec and settings (design --suite; a
/// resume of a file written whole before streaming). Throws InputError naming the file for a
/// different sweep (block, measure, axes, records or their measures, scenarios), or naming the
/// option whose setting differs.
SweepResults read_suite_results(const std::string& path, const SuiteSpec& spec, const IntegratorSettings& settings);

/// Makes the checks of read_suite_results without reading the results (a resume, before any
/// option is compared). Throws as read_suite_results.
void check_suite_file(const std::string& path, const SuiteSpec& spec, const IntegratorSettings& settings);

}  // namespace rocksweep
