#pragma once
/// The record-suite HDF5 file: the records with their intensity measures and metadata, one
/// group per anchorage scenario holding the [record, radius, intensity] results, and, once the
/// sweep is complete, the overturning spectrum and the fragility curves of each scenario.
/// Layout: docs/suite.md.
#include <string>
#include <vector>

#include "rocksweep/io/spectra_file.hpp"
#include "rocksweep/records/suite_products.hpp"

namespace rocksweep {

/// Throws InputError("suite", "SUITE line N", ...) for the first record whose name cannot name
/// its group /records/NAME: "." or "..", or a dataset of /records (pga_g, record, intensity, ...).
/// Checked before any work, and again by write_suite.
void check_record_names(const SuiteSpec& spec);

/// Writes the whole file to path + ".tmp", closes it and renames it onto `path` (as
/// write_spectra). `r` may be partial; the products are written only when every cell is done.
/// Throws as write_spectra.
void write_suite(const std::string& path, const SuiteSpec& spec, const SweepResults& r,
                 const std::vector<DamageState>& states, const Provenance& prov, const IntegratorSettings& settings);

/// Reads back the results of a file written by write_suite for the same spec and settings, to
/// resume it. Throws InputError naming the file for a different sweep (block, measure, axes,
/// records or their measures, scenarios), or naming the option whose setting differs.
SweepResults read_suite_results(const std::string& path, const SuiteSpec& spec, const IntegratorSettings& settings);

}  // namespace rocksweep
