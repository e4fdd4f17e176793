#pragma once
/// Search for the best value of one design variable (an anchorage stiffness K, or K_min/K_max)
/// by successive bracketing on a logarithmic axis: a coarse set of points over the whole range,
/// then, round after round, new points in the two intervals beside the best one so far.
/// Knows nothing of what the criterion is: it proposes points and is told their values.
///
/// Why not golden section: the criterion is an area fraction counted on a finite grid of
/// pulses, a step function of the variable with plateaus and, in general, several local
/// maxima. Golden section needs a unimodal function and discards a side of the bracket for
/// good; bracketing keeps every point evaluated and always refines around the best of them.
#include <cstddef>
#include <utility>
#include <vector>

namespace rocksweep {

/// x is the search's own axis: log10 of the design variable.
struct SearchSettings {
    double lo = 0.0, hi = 1.0;          ///< x range, lo < hi
    std::size_t coarse_points = 9;      ///< first round: evenly spaced on [lo, hi], both ends included (>= 3)
    std::size_t points_per_side = 2;    ///< each later round: this many new points in each interval beside the best (>= 1)
    int max_rounds = 4;                 ///< rounds after the coarse one (>= 0)
    double tolerance = 0.01;            ///< an interval narrower than this (in x) is not split again (> 0)
};

struct SearchPoint {
    double x = 0.0;      ///< log10 of the variable
    double value = 0.0;  ///< the criterion, larger is better
};

/// The point to recommend among `points` sorted by x (non-empty): the highest value; among
/// equal highest values, the middle of the widest run (in x) of neighbouring points that all
/// hold it, since a variable there keeps its value when the real one is a little off.
std::size_t best_point(const std::vector<SearchPoint>& sorted);

/// The run of neighbours of `best` in `sorted` whose values are within `margin` of its value:
/// [first, last] indices, `best` included. A conservator's room to choose.
std::pair<std::size_t, std::size_t> near_best(const std::vector<SearchPoint>& sorted, std::size_t best, double margin);

class BracketSearch {
public:
    /// Throws std::invalid_argument for settings outside the ranges stated above.
    explicit BracketSearch(const SearchSettings& settings);

    /// The coarse round's points, ascending.
    std::vector<double> first_round() const;

    /// Points for round `round` (1 for the first after the coarse one) given every point
    /// evaluated so far, in any order; ascending, none already evaluated. Empty once `round`
    /// exceeds max_rounds or both intervals beside the best point are narrower than the
    /// tolerance: the search has ended.
    std::vector<double> next_round(int round, std::vector<SearchPoint> evaluated) const;

    const SearchSettings& settings() const { return s_; }

private:
    SearchSettings s_;
};

/// Sorts by x (stable for equal x).
void sort_by_x(std::vector<SearchPoint>& points);

}  // namespace rocksweep
