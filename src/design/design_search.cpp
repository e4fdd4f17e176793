#include "rocksweep/design/design_search.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rocksweep {

void sort_by_x(std::vector<SearchPoint>& points) {
    std::stable_sort(points.begin(), points.end(), [](const SearchPoint& a, const SearchPoint& b) { return a.x < b.x; });
}

std::size_t best_point(const std::vector<SearchPoint>& sorted) {
    if (sorted.empty()) throw std::invalid_argument("best_point: no points");
    double top = sorted[0].value;
    for (const SearchPoint& p : sorted) top = std::max(top, p.value);
    std::size_t best = 0;
    double widest = -1.0;
    for (std::size_t i = 0; i < sorted.size();) {
        if (sorted[i].value != top) { ++i; continue; }
        std::size_t j = i;
        while (j + 1 < sorted.size() && sorted[j + 1].value == top) ++j;
        const double width = sorted[j].x - sorted[i].x;
        if (width > widest) {
            widest = width;
            // The point nearest the run's middle in x; the lower one of two equally near.
            const double mid = 0.5 * (sorted[i].x + sorted[j].x);
            best = i;
            for (std::size_t k = i; k <= j; ++k)
                if (std::abs(sorted[k].x - mid) < std::abs(sorted[best].x - mid)) best = k;
        }
        i = j + 1;
    }
    return best;
}

std::pair<std::size_t, std::size_t> near_best(const std::vector<SearchPoint>& sorted, std::size_t best, double margin) {
    if (best >= sorted.size()) throw std::invalid_argument("near_best: no such point");
    const double floor = sorted[best].value - margin;
    std::size_t lo = best, hi = best;
    while (lo > 0 && sorted[lo - 1].value >= floor) --lo;
    while (hi + 1 < sorted.size() && sorted[hi + 1].value >= floor) ++hi;
    return {lo, hi};
}

BracketSearch::BracketSearch(const SearchSettings& settings) : s_(settings) {
    if (!(std::isfinite(s_.lo) && std::isfinite(s_.hi) && s_.lo < s_.hi))
        throw std::invalid_argument("BracketSearch: the range must be finite with lo < hi");
    if (s_.coarse_points < 3) throw std::invalid_argument("BracketSearch: at least 3 coarse points");
    if (s_.points_per_side < 1) throw std::invalid_argument("BracketSearch: at least 1 point per side");
    if (s_.max_rounds < 0) throw std::invalid_argument("BracketSearch: max_rounds must be >= 0");
    if (!(s_.tolerance > 0.0)) throw std::invalid_argument("BracketSearch: the tolerance must be > 0");
}

std::vector<double> BracketSearch::first_round() const {
    std::vector<double> x(s_.coarse_points);
    const double n = static_cast<double>(s_.coarse_points - 1);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = s_.lo + (s_.hi - s_.lo) * static_cast<double>(i) / n;
    x.back() = s_.hi;  // exactly the end the user gave
    return x;
}

std::vector<double> BracketSearch::next_round(int round, std::vector<SearchPoint> evaluated) const {
    if (round < 1 || round > s_.max_rounds || evaluated.empty()) return {};
    sort_by_x(evaluated);
    const std::size_t b = best_point(evaluated);
    std::vector<double> fresh;
    auto split = [&](double a, double c) {
        if (!(c - a > s_.tolerance)) return;
        const double parts = static_cast<double>(s_.points_per_side + 1);
        for (std::size_t j = 1; j <= s_.points_per_side; ++j) fresh.push_back(a + (c - a) * static_cast<double>(j) / parts);
    };
    if (b > 0) split(evaluated[b - 1].x, evaluated[b].x);
    if (b + 1 < evaluated.size()) split(evaluated[b].x, evaluated[b + 1].x);
    return fresh;
}

}  // namespace rocksweep
