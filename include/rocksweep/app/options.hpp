#pragma once
/// What the command line and config file say, as plain values, and how they become a model.
#include <cstdint>
#include <string>
#include <vector>

#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/physics/model.hpp"
#include "rocksweep/records/record.hpp"
#include "rocksweep/grid/sweep.hpp"

namespace rocksweep {

struct BlockOptions {
    double half_width_m = 0.30, half_height_m = 1.36, mass_kg = 3361.0;  // S. Matteo
    double radius_m = 0.0, alpha_rad = 0.0, inertia_ratio = 0.0, p = 0.0;  // equivalent block
    double gravity = 9.81;
    double restitution = 0.0;  ///< 0: Housner's value
    std::string equations = "nonlinear";
};

struct PulseOptions {
    std::string family = "one-sine";  ///< sweep --pulse (pulse_library.hpp)
    int cycles = 1;                   ///< n of n-sine and cycloidal-c
    double phase = 0.0, vertical_g = 0.0, vertical_phase = 0.0;
};

struct BaseOptions {
    double friction = 0.0;  ///< static friction coefficient mu_s; 0: not checked
};

struct AnchorageOptions {
    double strength_ratio = 0.4;  ///< F_u / (m g)
    std::string break_rule = "angle";
    std::string law = "paper";  ///< adaptive law: paper | passive
};

struct GridOptions {
    std::vector<double> omega_range{1.0, 10.0}, amplitude_range{1.0, 22.0};
    std::size_t omega_points = 181, amplitude_points = 211;
    std::vector<std::string> anchorages{"free", "constant", "adaptive"};
    std::vector<double> theta_f_ratios{1.0, 0.5, 1.0 / 3.0, 0.25};
    std::vector<double> kmin_ratios{0.5, 0.1};
    double adaptive_theta_f_ratio = 1.0;  ///< K_max's spring: theta_f / alpha
    std::vector<std::string> only;        ///< --scenario: run only these
    std::vector<std::string> axes;        ///< --axis: parameter axes, as written (grid/parameter_axis.hpp)
    std::vector<double> period_range, pga_range;  ///< the spectrum's axes in T_p [s] and a_p0 [g]; empty: ratios
    std::size_t period_points = 0, pga_points = 0;  ///< 0: as many as the ratio axis
};

struct NumericsOptions {
    std::string method = "events";
    double steps_per_period = 48.0, paper_dt_s = 0.0025, impact_threshold = 1e-3;
    double tolerance = 1e-8;  ///< under records: each step's local error (IntegratorSettings::tolerance); 0: fixed
    std::int64_t max_steps = 2'000'000;
    bool no_energy_stop = false;
    std::string record_steps = "samples";  ///< samples: each record sample ends a step; cross
    bool record_any_pga = false;           ///< accept a record whose PGA as read is implausible (record.hpp)
    int lanes = 8;
};

struct SingleOptions {
    std::string pulse = "sine", anchorage = "free";  ///< pulse: sine, constant or a sweep's family
    double omega_ratio = 4.0, amplitude_ratio = 2.7, duration_s = 0.0;
    double theta_f_ratio = 1.0, kmin_ratio = 0.5, stiffness = 0.0;
    double t_end_s = 0.0, output_dt_s = 0.01;
    std::string record, record_units;  ///< a recorded ground motion instead of a pulse
    double record_scale = 1.0;
    std::string record_format = "auto";  ///< auto: at2 for a .AT2 file, else time_accel
    double record_dt_s = 0.0;            ///< accel_only: the sampling interval [s]
    int record_column = 0;               ///< 1-based, the time column counted; 0: the format's default
    std::string record_vertical;         ///< the vertical component's file ("" with a column: --record's file)
    int record_vertical_column = 0;      ///< its column, 1-based as record_column; 0: none or the format's default
    std::string floor;                   ///< the floor the block stands on (motion/floor_filter.hpp); "": the ground
};

struct Options {
    BlockOptions block;
    PulseOptions pulse;
    BaseOptions base;
    AnchorageOptions anchorage;
    GridOptions grid;
    NumericsOptions numerics;
    SingleOptions single;
};

/// Throws InputError naming the option, the value and the allowed range.
Block make_block(const BlockOptions& o);
Equations parse_equations(const std::string& s);
/// The axis --NAME-range LO HI with --NAME-points points; throws InputError naming the option
/// for a reversed, empty, non-positive or one-point-with-two-ends grid.
Axis make_axis(const std::string& name, const std::vector<double>& range, std::size_t points);
IntegratorSettings make_settings(const NumericsOptions& o);
SweepSpec make_sweep_spec(const Options& o);
/// How `simulate --record ...` asks for its record to be read (record.hpp).
RecordSource record_source(const SingleOptions& s);
/// The single cell of `rocksweep simulate`; its record, if it has one, as read (on the ground,
/// before any --floor) into `record` (when given) for the caller to report. A record of
/// implausible PGA as read is refused (record.hpp) unless --record-any-pga.
CellModel make_single_cell(const Options& o, Record* record = nullptr);
/// Whether the option `name` (a config key: "mass", "omega-ratio") defined the run of `command`
/// ("sweep" or "simulate") with options `o`, and so belongs in its /provenance/config: not how
/// the run was started (output, resume, quiet), not what this run ignored (a record-driven
/// history's pulse, a free block's anchorage strength, a sweep's theta-f-ratios without
/// 'constant'). Options it does not know of are kept.
bool defines_run(const std::string& command, const std::string& name, const Options& o);
/// Default record length of a history: the pulse and ten rocking periods 2 pi / p after it.
double default_t_end(const CellModel& m);

}  // namespace rocksweep
