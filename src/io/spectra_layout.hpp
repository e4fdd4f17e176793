#pragma once
// Internal to rocksweep_io: what the whole-file writer (spectra_file.cpp) and the streaming
// writer (spectra_stream.cpp) share, and the reader (spectra_read.cpp) checks: one layout.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/grid_layout.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/spectra_file.hpp"
#include "result_columns.hpp"

namespace rocksweep::spectra_detail {

// Bumped when the layout changes in a way a reader must know about. 2: the axes moved from
// /axes into every scenario group, where netCDF-4 readers look for dimensions. (The streaming
// writer's contiguous, uncompressed storage is not such a change: readers see the same datasets.)
constexpr std::int64_t format_version = 2;

// The axes of every scenario's grid, slowest first: they alone shape the layout. The parameter
// axes come first, so that each of their points holds one contiguous spectrum.
inline std::vector<GridAxis> grid_axes(const SweepSpec& spec) {
    const std::vector<std::string> names = spec.axis_names();  // C order, the spectrum's two last
    std::vector<GridAxis> axes;
    for (std::size_t k = 0; k < spec.axes.size(); ++k) {
        const ParameterInfo& i = parameter_info(spec.axes[k].parameter);
        axes.push_back({names[k], i.units, i.long_name, spec.axes[k].values, flag_meanings(spec.axes[k])});
    }
    const bool pga = spec.amplitude_axis == AmplitudeAxis::pga_g, period = spec.frequency_axis == FrequencyAxis::period_s;
    axes.push_back({names[names.size() - 2], "1", pga ? "peak ground acceleration a_p0 / g" : "a_p0 / (alpha g)",
                    spec.amplitude_ratio.values()});
    axes.push_back({names.back(), period ? "s" : "1", period ? "pulse period T_p = 2 pi / omega_p" : "omega_p / p",
                    spec.omega_ratio.values()});
    return axes;
}

// The root attribute `spectrum_axes`: the two axes a spectrum is drawn on, by name. A file
// without it (written before physical units existed) has the ratios.
inline std::string spectrum_axis_names(const SweepSpec& spec) {
    const std::vector<std::string> names = spec.axis_names();
    return names[names.size() - 2] + ", " + names.back();
}

// The root attribute `parameter_axes`: their names in order, "" for the plain 2-D spectra. A
// file without it (written before parameter axes existed) has none.
inline std::string parameter_axis_names(const SweepSpec& spec) {
    std::string s;
    for (const ParameterAxis& a : spec.axes) s += (s.empty() ? "" : ", ") + std::string(parameter_info(a.parameter).name);
    return s;
}

// Attributes that define the cells (the block's and the pulse's) and the settings that shape
// results: written by write_spectra and compared by read_spectra_results, from the lists every
// result file shares (result_columns.hpp) and the pulse's own.
using io::NamedNumber;
using io::NamedText;
using io::Setting;
using io::scenario_numbers;
using io::scenario_texts;

inline std::vector<NamedNumber> root_numbers(const SweepSpec& spec) {
    std::vector<NamedNumber> n = io::block_numbers(spec.block);
    n.push_back({"phase_rad", spec.phase});
    n.push_back({"vertical_g", spec.vertical_g});
    n.push_back({"vertical_phase_rad", spec.vertical_phase});
    return n;
}

inline bool same_number(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

inline std::vector<Setting> result_settings(const SweepSpec& spec, const IntegratorSettings& s) {
    std::vector<Setting> all = io::numerics_settings(s, spec.impact_threshold, spec.equations);
    all.push_back({"pulse", "pulse", to_string(spec.pulse_family), 0.0, true});
    all.push_back({"pulse_cycles", "cycles", std::to_string(spec.pulse_cycles), static_cast<double>(spec.pulse_cycles), false});
    // Files from before refinement was recorded: unknown, not checked.
    const std::string stride = spec.refine_stride == 0 ? "not given" : std::to_string(spec.refine_stride);
    all.push_back({"refine_stride", "refine", stride, static_cast<double>(spec.refine_stride), false, ""});
    all.push_back({"refine_axes", "refine-axes", spec.refine_axes, 0.0, true, ""});
    return all;
}

/// Writes the whole layout into `f`. With `r` the result datasets hold its columns (compressed
/// where large); without, they are created by h5::create_fixed_dataset: contiguous, allocated,
/// unwritten, for the streaming writer to fill in place. Objects opened here are closed on return.
void write_contents(const h5::File& f, const SweepSpec& spec, const SweepResults* r, const Provenance& prov,
                    const IntegratorSettings& settings);

/// Opens `path` read-only and makes every check read_spectra_results makes (same exceptions);
/// reads the results into `*r` when `r` is given. Returns the open file.
h5::File open_checked(const std::string& path, const SweepSpec& spec, const IntegratorSettings& settings,
                      SweepResults* r);

}  // namespace rocksweep::spectra_detail
