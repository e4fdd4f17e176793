#pragma once
/// Recorded ground motions: how to read one (RecordSource), what was read (Record), and the
/// Pulse the integrator runs on. The formats people download are read here with the standard
/// library only: PEER NGA .AT2, time/acceleration columns, acceleration columns with a given dt
/// (comma- or whitespace-separated). The unit is always explicit except in an .AT2, which
/// states it; it is never guessed. See docs/records.md.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rocksweep/physics/excitation.hpp"

namespace rocksweep {

/// Standard gravity [m/s^2]: what a record "in g" means, whatever g the block stands under.
inline constexpr double standard_gravity = 9.80665;

/// Physically sane records: strong-motion instruments sample at 50 Hz to a few kHz, and no
/// ground motion has been recorded above ~4 g, so a record outside these bounds is a wrong
/// unit, a wrong column or a broken file — refused rather than integrated (issue 7).
inline constexpr double record_dt_min_s = 1e-5;
inline constexpr double record_dt_max_s = 1.0;
inline constexpr double record_accel_max_g = 20.0;
/// The peak ground acceleration a strong-motion record has, as read in the unit given and before
/// any scale factor: a record outside it read in the wrong unit (El Centro's 0.35 g read as
/// cm/s^2 is 0.00036 g, and reads as "safe"). docs/records.md says why these bounds; a run that
/// means it accepts such a record with --record-any-pga.
inline constexpr double record_pga_min_g = 0.005;
inline constexpr double record_pga_max_g = 5.0;

enum class RecordFormat {
    time_accel,  ///< a time column [s] (column 1), then acceleration column(s)
    accel_only,  ///< acceleration column(s) only, the sampling interval given
    at2,         ///< PEER NGA .AT2: four header lines (unit on line 3, NPTS and DT on line 4), then samples
};

/// What parse_record_format and units_to_g accept, for messages that list it.
inline constexpr const char* record_formats_allowed = "time_accel, accel_only or at2";
inline constexpr const char* record_units_allowed = "g, m/s^2 or cm/s^2";

/// "time_accel", "accel_only" or "at2"; throws InputError(field, text, ...) for anything else.
RecordFormat parse_record_format(const std::string& field, const std::string& text);
std::string to_string(RecordFormat f);

/// Factor turning a sample in `units` into a fraction of standard gravity: "g", "m/s^2" or
/// "cm/s^2" (gal). Throws InputError(field, units, ...) for anything else.
double units_to_g(const std::string& field, const std::string& units);

/// The vertical component: a column of the same file (path empty) or a second file read with
/// the same format, unit and scale as the horizontal one.
struct VerticalSource {
    std::string path;  ///< "" = the horizontal file itself
    int column = 0;    ///< 1-based column counting every column of the file; 0 = the format's default
};

/// How to read one record: a plain value, filled from command-line options or a suite file.
struct RecordSource {
    std::string path;
    RecordFormat format = RecordFormat::time_accel;
    std::string units;   ///< "g", "m/s^2", "cm/s^2"; "" only for .AT2 (its header states it)
    double dt_s = 0.0;   ///< sampling interval: required for accel_only; 0 = from the file
    int column = 0;      ///< 1-based, counting the time column; 0 = default (2 for time_accel, 1 for accel_only)
    double scale = 1.0;  ///< applied to every sample (both components); finite and non-zero
    int skip_lines = 0;  ///< header lines to skip before the numbers (time_accel, accel_only)
    std::optional<VerticalSource> vertical;
};

/// A record as read: samples at t = i dt from t = 0, in units of standard gravity, scale applied.
struct Record {
    std::string path;           ///< the horizontal component's file
    std::string vertical_path;  ///< the vertical component's file ("" if none)
    RecordFormat format = RecordFormat::time_accel;
    std::string units;  ///< unit of the file's samples (given, or from the .AT2 header)
    double scale = 1.0;
    int column = 0;           ///< column read (1-based; 0 for .AT2)
    int vertical_column = 0;  ///< column of the vertical component (0 for .AT2 or none)
    std::size_t npts = 0;     ///< samples read from the file
    double dt_s = 0.0;
    bool zero_prepended = false;  ///< the file began at t = dt: a sample 0 was put at t = 0
    std::vector<double> ax_g;     ///< horizontal ground acceleration / standard g
    std::vector<double> ay_g;     ///< vertical, same times and length; empty if none

    double duration_s() const { return static_cast<double>(ax_g.size() - 1) * dt_s; }
};

/// The horizontal component's peak |a| in the file's unit as given, before the scale factor, in
/// standard g.
double pga_as_read_g(const Record& r);
/// Whether pga_as_read_g lies in [record_pga_min_g, record_pga_max_g].
bool plausible_pga(const Record& r);
/// What a run prints of a record before using it: "PGA 0.349 g (3.42 m/s^2) as read in g,
/// dt 0.02 s, 53.74 s, 2688 samples".
std::string record_facts(const Record& r);
/// Why a record with an implausible PGA is refused ("its peak ground acceleration as read in
/// cm/s^2, ... is ... g, outside ..."): the unit given, the PGA it implies and the band;
/// `accept` says how to accept it deliberately.
std::string implausible_pga(const Record& r, const std::string& accept);

/// Reads a record. Throws InputError naming the file and line and what was expected for a
/// malformed file (non-increasing or uneven times, ragged columns, text in a number, too few
/// samples, an .AT2 whose samples do not match its NPTS), a missing unit, and a physically
/// absurd record (dt outside [record_dt_min_s, record_dt_max_s], |a| > record_accel_max_g).
Record read_record(const RecordSource& source);

/// The ground of `record` as the integrator's Pulse, in units of the block's gravity `gravity`
/// [m/s^2]: the horizontal and, if read, the vertical samples (upward positive, the block's
/// weight m (g + a_v); docs/physics.md, "Recorded ground motions"), at scale 1. Throws
/// InputError("record-vertical", ...) if a vertical sample is -g or below (free fall).
Pulse to_pulse(const Record& record, double gravity);

/// `simulate --record`: a time/acceleration file in `units` ("g", "m/s^2" or "cm/s^2"), times
/// from 0 (or from dt), scaled by `scale`, for a block under `gravity` [m/s^2].
Pulse read_record(const std::string& path, const std::string& units, double scale, double gravity);

}  // namespace rocksweep
