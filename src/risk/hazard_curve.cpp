#include "rocksweep/risk/hazard_curve.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace rocksweep {

std::string hazard_measure_name(HazardMeasure m, double period_s) {
    switch (m) {
    case HazardMeasure::pga: return "PGA";
    case HazardMeasure::pgv: return "PGV";
    case HazardMeasure::sa: {
        std::ostringstream s;
        s << "SA(" << period_s << ")";
        return s.str();
    }
    }
    return "?";
}

const char* hazard_measure_units(HazardMeasure m) { return m == HazardMeasure::pgv ? "m/s" : "g"; }

HazardCurve::HazardCurve(HazardMeasure measure, double period_s, std::vector<double> intensity, std::vector<double> rate)
    : measure_(measure), period_s_(period_s), x_(std::move(intensity)), h_(std::move(rate)) {
    auto bad = [](std::size_t i, const std::string& what) {
        return std::invalid_argument("hazard curve point " + std::to_string(i + 1) + ": " + what);
    };
    if ((measure == HazardMeasure::sa) != (period_s > 0 && std::isfinite(period_s)))
        throw std::invalid_argument("hazard curve: a period > 0 for SA, and for SA only");
    if (x_.size() != h_.size()) throw std::invalid_argument("hazard curve: as many rates as intensities");
    if (x_.size() < 2) throw std::invalid_argument("hazard curve: at least two points (it has " + std::to_string(x_.size()) + ")");
    for (std::size_t i = 0; i < x_.size(); ++i) {
        if (!(x_[i] > 0 && std::isfinite(x_[i]))) throw bad(i, "intensity not positive and finite");
        if (!(h_[i] > 0 && std::isfinite(h_[i]))) throw bad(i, "annual rate not positive and finite");
        if (i > 0 && !(x_[i] > x_[i - 1])) throw bad(i, "intensities not strictly increasing");
        if (i > 0 && h_[i] > h_[i - 1]) throw bad(i, "annual rate rises with intensity (a rate of exceedance cannot)");
    }
    if (!(h_.back() < h_.front())) throw std::invalid_argument("hazard curve: the rate never falls");
    for (std::size_t i = 0; i + 1 < x_.size(); ++i) k_.push_back(-std::log(h_[i + 1] / h_[i]) / std::log(x_[i + 1] / x_[i]));
}

std::size_t HazardCurve::segment(double x) const {
    const auto it = std::upper_bound(x_.begin(), x_.end(), x);
    const std::size_t i = it == x_.begin() ? 0 : static_cast<std::size_t>(it - x_.begin()) - 1;
    return std::min(i, k_.size() - 1);
}

double HazardCurve::rate_at(double x) const {
    const std::size_t i = segment(x);
    return h_[i] * std::exp(-k_[i] * std::log(x / x_[i]));
}

double HazardCurve::slope_at(double x) const { return k_[segment(x)]; }

double HazardCurve::max_slope() const { return *std::max_element(k_.begin(), k_.end()); }

double rate_from_probability(double probability, double years) { return -std::log1p(-probability) / years; }

double probability_in(double rate, double years) { return -std::expm1(-rate * years); }

}  // namespace rocksweep
