#pragma once
/// The overturning-spectra HDF5 file: one group per scenario, one [n_amp, n_omega] dataset per
/// result column, the group's own copy of the axes as dimension scales (so that netCDF-4 readers
/// find them). Layout: docs/hdf5.md.
#include <string>

#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/grid/sweep.hpp"

namespace rocksweep {

/// What produced a file. Everything here may differ between two runs of the same config, so
/// it is written only under /provenance (h5diff of the rest is identical across runs).
struct Provenance {
    std::string version;      ///< rocksweep version
    std::string config_text;  ///< the effective config, as a config file
    std::string created_utc;  ///< ISO 8601, e.g. 2024-05-01T12:00:00Z
    int ranks = 1;            ///< MPI ranks
    double wall_s = 0.0;      ///< wall-clock time of the run [s]
};

/// Writes the whole file to path + ".tmp", closes it and renames it onto `path`: `path` is
/// never partial, and holds the previous file if this throws. `r` may be partial (its `done`
/// column says which cells hold results). The integrator settings that shape results
/// (method, steps per period, paper dt, step cap, energy stop) are root attributes beside the
/// spec's; `settings.stop_requested` and the like are not.
/// Throws std::invalid_argument if r's columns do not all have spec.cell_count() entries,
/// InputError for a scenario name that cannot be a group name (empty, ".", containing '/',
/// or repeated) and for an output location that cannot be written, std::runtime_error
/// ("cannot write PATH: ...") for a failed write (e.g. a full disk).
void write_spectra(const std::string& path, const SweepSpec& spec, const SweepResults& r,
                   const Provenance& prov, const IntegratorSettings& settings);

/// Reads back the result columns (and `done`) of a file written by write_spectra for the same
/// spec and settings, e.g. to resume a partial run. Throws InputError naming the file if it
/// cannot be opened or if its axes, scenarios (names and anchorage parameters), block, pulse
/// settings or dataset shapes differ from `spec`; InputError naming the option (e.g.
/// "--max-steps = 100 is invalid: 2000000, as PATH was computed with ...") if a setting that
/// shapes results differs (method, steps-per-period, paper-dt, max-steps, no-energy-stop,
/// impact-threshold, equations).
SweepResults read_spectra_results(const std::string& path, const SweepSpec& spec,
                                  const IntegratorSettings& settings);

/// Compares each scenario's results in `r` (read from `path`) with the checksum the file stored
/// when its run finished (results_checksum.hpp). Throws InputError("part file", path, ...)
/// naming the first scenario that differs; returns the names of the scenarios that have none
/// (a file from before checksums, or a run killed before it finished).
std::vector<std::string> verify_results_checksums(const std::string& path, const SweepSpec& spec, const SweepResults& r);

/// The checks of read_spectra_results alone, the results left unread.
void check_spectra_file(const std::string& path, const SweepSpec& spec, const IntegratorSettings& settings);

/// The effective config a results file (spectra or suite) records in /provenance/config, "" if
/// it records none or cannot be read (its readers report that).
std::string read_provenance_config(const std::string& path);

/// `spec` with the refinement the spectra file at `path` records (refine_stride, refine_axes):
/// what a reader that was not told it (merge) takes from its first file, and then checks the
/// others against. `spec` unchanged if the file records none or is not a spectra file (reading
/// it then says why).
SweepSpec with_recorded_refinement(const std::string& path, SweepSpec spec);

}  // namespace rocksweep
