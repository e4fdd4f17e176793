#pragma once
/// The motion a block on a floor of a linear building sees: the ground passed through the
/// building's modes, and through a base-isolated plinth or display case standing on that floor
/// (the same kind of filter, chained). The block does not act back on the structure (one-way
/// coupling; docs/physics.md, "Floor motions", gives the mass ratio below which that holds).
#include <span>
#include <string>
#include <vector>

#include "rocksweep/motion/oscillator.hpp"

namespace rocksweep::motion {

/// One mode of a structure as the floor sees it.
struct Mode {
    Oscillator oscillator;       ///< the mode's period T_n [s] and damping ratio zeta_n
    double participation = 1.0;  ///< Gamma_n phi_n at the floor (1 for a single oscillator)
};

/// A linear structure between its base and a floor, by its modes: the floor's absolute
/// acceleration is a_g + sum_n Gamma_n phi_n q_n'', q_n'' + 2 zeta_n w_n q_n' + w_n^2 q_n = -a_g.
/// A truncated set of modes, whose participations need not sum to 1, leaves the rest of the
/// ground rigidly carried (the a_g term).
struct FloorFilter {
    std::vector<Mode> modes;
};

/// A named floor: the filters from the ground up, first the building, then (optionally) a
/// plinth on it. No filter: the ground itself.
struct Floor {
    std::string name = "ground";
    std::vector<FloorFilter> stages;
    bool is_ground() const { return stages.empty(); }
};

/// Bounds that refuse what is not a building, a plinth or a display case (and typing errors).
inline constexpr double floor_period_min_s = 1e-3, floor_period_max_s = 100.0;
inline constexpr double floor_participation_max = 10.0;
inline constexpr std::size_t floor_modes_max = 20, floor_stages_max = 4;

/// The absolute acceleration of the floor at the samples of a base acceleration `a` given at
/// t = i dt from rest and linear between samples; exact at the samples (oscillator.hpp), in the
/// unit of `a`. Throws std::invalid_argument for a filter outside the bounds above.
std::vector<double> filter_motion(const FloorFilter& filter, std::span<const double> a, double dt_s);

/// The floor's motion: `a` through every stage in turn, the chain discretised as one system so
/// that it is exact at the samples too (a stage's output is not linear between samples).
std::vector<double> floor_motion(const Floor& floor, std::span<const double> a, double dt_s);

/// A floor's motion is smooth between the record's samples, and the block reads it linear
/// between the samples it is given: with samples h apart, a component of period T is read off by
/// up to (2 pi h / T)^2 / 8 of its amplitude. The floor is computed on samples fine enough that
/// this stays below `floor_interpolation_tolerance` at the shortest period of its modes
/// (docs/physics.md, "Floor motions", gives the measurement that chose it).
inline constexpr double floor_interpolation_tolerance = 1e-3;

/// How many floor samples per record step `dt_s` that takes: 1 for the ground.
int floor_oversampling(const Floor& floor, double dt_s);

/// `a` (samples dt apart, linear between them) at m samples per step: the same motion, exactly.
std::vector<double> oversample(std::span<const double> a, int m);

/// A floor as written on the command line or in a config:
///   "NAME"                                  the ground (no filter; the name must be "ground")
///   "NAME: T zeta gphi; T zeta gphi > T zeta gphi"
/// modes of one structure separated by ';', chained structures by '>' (the building first),
/// each mode as period [s], damping ratio and participation Gamma phi. Throws
/// InputError(field, text, ...) naming what is wrong and the allowed range.
Floor parse_floor(const std::string& field, const std::string& text);

/// The canonical text of `floor` (parse_floor(to_string(f)) == f, numbers in full precision):
/// what files store and resume compares.
std::string to_string(const Floor& floor);

}  // namespace rocksweep::motion
