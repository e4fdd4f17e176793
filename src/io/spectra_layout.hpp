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

namespace rocksweep::spectra_detail {

// Bumped when the layout changes in a way a reader must know about. 2: the axes moved from
// /axes into every scenario group, where netCDF-4 readers look for dimensions. (The streaming
// writer's contiguous, uncompressed storage is not such a change: readers see the same datasets.)
constexpr std::int64_t format_version = 2;

// The axes of every scenario's grid, slowest first: they alone shape the layout.
inline std::vector<GridAxis> grid_axes(const SweepSpec& spec) {
    return {
        {"amplitude_ratio", "1", "a_p0 / (alpha g)", spec.amplitude_ratio.values()},
        {"omega_ratio", "1", "omega_p / p", spec.omega_ratio.values()},
    };
}

// Attributes that define the cells: written by write_spectra and compared by
// read_spectra_results, so the two can never disagree about what "the same sweep" means.
struct NamedNumber {
    const char* name;
    double value;
};

inline std::vector<NamedNumber> root_numbers(const SweepSpec& spec) {
    const Block& b = spec.block;
    return {
        {"half_width_m", b.half_width_m()},
        {"half_height_m", b.half_height_m()},
        {"radius_m", b.radius_m},
        {"alpha_rad", b.alpha_rad},
        {"p_rad_s", b.p()},
        {"e", b.e},
        {"inertia_ratio", b.inertia_ratio},
        {"mass_kg", b.mass_kg},
        {"gravity_m_s2", b.gravity},
        {"phase_rad", spec.phase},
        {"vertical_g", spec.vertical_g},
        {"vertical_phase_rad", spec.vertical_phase},
    };
}

inline std::vector<NamedNumber> scenario_numbers(const Scenario& s) {
    const Anchorage& a = s.anchorage;
    return {
        {"theta_f_ratio", s.theta_f_ratio}, {"kmin_ratio", s.kmin_ratio},
        {"k_max_N_per_m", a.k_max},         {"k_min_N_per_m", a.k_min},
        {"strength_N", a.strength_n},       {"theta_f_rad", a.theta_f_rad},
    };
}

struct NamedText {
    const char* name;
    std::string value;
};

inline std::vector<NamedText> scenario_texts(const Scenario& s) {
    return {{"anchorage", to_string(s.anchorage.kind)},
            {"break_rule", to_string(s.anchorage.break_rule)},
            {"adaptive_law", to_string(s.anchorage.law)}};
}

inline bool same_number(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// The settings that shape results without defining the cells: a resume must use the same
// ones, and an error names the option that differs.
struct Setting {
    const char* attribute;
    const char* option;        // as the user writes it, without "--"
    std::string text;          // what the user gave, for messages and string attributes
    double number = 0.0;       // for numeric attributes
    bool is_text = false;
};

inline std::vector<Setting> result_settings(const SweepSpec& spec, const IntegratorSettings& s) {
    auto num = [](const char* attr, const char* option, double x, std::string shown) {
        return Setting{attr, option, std::move(shown), x, false};
    };
    // The method is compared first; of the two step settings only the method's own shapes results.
    const bool paper = s.method == Method::paper;
    return {
        {"method", "method", to_string(s.method), 0.0, true},
        paper ? num("paper_dt_s", "paper-dt", s.paper_dt_s, format_number(s.paper_dt_s))
              : num("steps_per_period", "steps-per-period", s.steps_per_period, format_number(s.steps_per_period)),
        num("max_steps", "max-steps", static_cast<double>(s.max_steps), std::to_string(s.max_steps)),
        // 1: a safe block is decided by energy after the pulse; 0: --no-energy-stop.
        num("energy_stop", "no-energy-stop", s.energy_stop ? 1.0 : 0.0, s.energy_stop ? "not given" : "given"),
        num("impact_threshold", "impact-threshold", spec.impact_threshold, format_number(spec.impact_threshold)),
        {"equations", "equations", to_string(spec.equations), 0.0, true},
        {"pulse", "pulse", to_string(spec.pulse_family), 0.0, true},
        num("pulse_cycles", "cycles", spec.pulse_cycles, std::to_string(spec.pulse_cycles)),
    };
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
