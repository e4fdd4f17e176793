#pragma once
/// The work list of a sweep: scenarios x parameter axes x amplitude x frequency, one cell per index.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rocksweep/grid/anchorage_setting.hpp"
#include "rocksweep/grid/parameter_axis.hpp"

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/block.hpp"
#include "rocksweep/physics/model.hpp"
#include "rocksweep/physics/outcome.hpp"
#include "rocksweep/physics/pulse_library.hpp"

namespace rocksweep {

/// Points evenly spaced on [lo, hi], both ends included (lo alone when points == 1).
struct Axis {
    double lo = 1.0, hi = 1.0;
    std::size_t points = 1;
    double at(std::size_t i) const;
    std::vector<double> values() const;
};

/// One anchorage configuration of the sweep.
struct Scenario {
    std::string name;          ///< HDF5 group name under /spectra
    Anchorage anchorage;
    double theta_f_ratio = 0;  ///< theta_f / alpha of the (K_max) spring; 0 for free
    double kmin_ratio = 1;     ///< K_min / K_max; 1 unless adaptive
};

/// What the two axes a spectrum is drawn on hold: the paper's ratios (the default; a spectrum
/// then holds for every block of the same shape), or the pulse's own period and peak.
enum class FrequencyAxis { omega_ratio, period_s };    ///< omega_p / p, or T_p = 2 pi / omega_p [s]
enum class AmplitudeAxis { amplitude_ratio, pga_g };   ///< a_p0 / (alpha g), or a_p0 / g

/// Everything that defines the cells of a sweep.
struct SweepSpec {
    Block block{};
    Equations equations = Equations::nonlinear;
    double impact_threshold = 1e-3;  ///< fraction of p alpha
    PulseFamily pulse_family = PulseFamily::one_sine;
    int pulse_cycles = 1;            ///< n of n-sine and cycloidal-c
    double phase = 0.0;              ///< psi [rad] (one-sine, n-sine)
    double vertical_g = 0.0;         ///< a_v0 / g (one-sine, n-sine)
    double vertical_phase = 0.0;     ///< psi_v [rad]
    double friction = 0.0;           ///< mu_s of the base, to flag cells that would slide; 0: unchecked
    Axis omega_ratio;                ///< omega_p / p (a rectangle lasts pi / omega_p); T_p [s] with period_s
    Axis amplitude_ratio;            ///< a_p / (alpha g), a_p the peak ground acceleration; a_p / g with pga_g
    FrequencyAxis frequency_axis = FrequencyAxis::omega_ratio;
    AmplitudeAxis amplitude_axis = AmplitudeAxis::amplitude_ratio;
    std::vector<Scenario> scenarios;
    std::vector<ParameterAxis> axes;  ///< parameter axes, slowest first; each value a spectrum more
    // Which cells are computed: all, or those boundary refinement (--refine) picks, the rest
    // inferred. A file records both, and --resume continues it only with the same.
    std::size_t refine_stride = 0;   ///< spacing of refinement's first pass; 0: every cell computed
    std::string refine_axes;         ///< the pair it refines over, "NAME NAME" as axis_names(); "" without

    PulseShape pulse_shape() const { return {pulse_family, pulse_cycles, phase, vertical_g, vertical_phase}; }
    /// Cells of one spectrum: the plane a_p0/(alpha g) x omega_p/p that refinement works on.
    std::size_t plane_cells() const { return omega_ratio.points * amplitude_ratio.points; }
    /// Spectra per scenario: the product of the parameter axes' sizes (1 without any).
    std::size_t planes_per_scenario() const;
    std::size_t cells_per_scenario() const { return planes_per_scenario() * plane_cells(); }
    std::size_t cell_count() const { return cells_per_scenario() * scenarios.size(); }
    /// index = (scenario * n_planes + plane) * (n_amp n_omega) + i_amp * n_omega + i_omega, the
    /// plane counting the parameter axes in C order (the first varies slowest).
    CellModel cell(std::size_t index) const;
    /// The grid's axes within a scenario, in C order, by the names files and options use
    /// ("phase_rad", ..., "amplitude_ratio" or "pga_g", "omega_ratio" or "period_s"), and their sizes.
    std::vector<std::string> axis_names() const;
    std::vector<std::size_t> axis_sizes() const;

    /// What the parameter axes set in the cells of one plane (of every scenario).
    struct Plane {
        Block block;                          ///< reshaped by radius_m / alpha_rad, e by restitution
        PulseShape shape;                     ///< phase and vertical pulse
        AnchorageSetting anchorage;            ///< what the axes set of every anchorage
        bool reshaped = false;                 ///< block differs from the configured one in R or alpha
        std::vector<std::size_t> at;           ///< index on each parameter axis
    };
    /// Throws InputError (neutral block.* ids) when a combination makes no block (say e above
    /// Housner's value of a reshaped block).
    Plane plane(std::size_t plane_index) const;
};

/// Result columns of a sweep, indexed like SweepSpec::cell.
struct SweepResults {
    std::vector<std::uint8_t> outcome;
    std::vector<double> max_rotation;
    std::vector<std::int32_t> impacts;
    std::vector<std::int32_t> impacts_total;
    std::vector<double> t_overturn;
    std::vector<double> peak_force_ratio;
    std::vector<std::uint8_t> broken;
    std::vector<double> mu_required;
    std::vector<std::uint8_t> pivot_uplift;
    std::vector<std::uint8_t> sensitive;  ///< CellResult::sensitive (written by suite files only)
    std::vector<std::uint8_t> done;  ///< 0 pending, 1 computed, 2 outcome inferred (refine.hpp)

    void resize(std::size_t n);
    /// Bytes one cell takes across the columns above: what rank 0 holds per cell of a sweep.
    static constexpr std::size_t bytes_per_cell() {
        return sizeof(std::uint8_t) * 5 + sizeof(double) * 4 + sizeof(std::int32_t) * 2;
    }
    std::size_t size() const { return outcome.size(); }
    void store(std::size_t index, const CellResult& r);
    std::size_t done_count() const;
};

/// Computes cells [first, first + count) of `spec` into `out`.
struct IntegratorSettings;
void compute_cells(const SweepSpec& spec, const IntegratorSettings& settings, std::size_t first,
                   std::size_t count, CellResult* out, int lanes = 8);

}  // namespace rocksweep
