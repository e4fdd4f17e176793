#include "rocksweep/motion/floor_filter.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "rocksweep/core/errors.hpp"
#include "state_space.hpp"

namespace rocksweep::motion {

namespace {

void check(const FloorFilter& f) {
    if (f.modes.empty() || f.modes.size() > floor_modes_max)
        throw std::invalid_argument("FloorFilter: 1 to " + std::to_string(floor_modes_max) + " modes");
    for (const Mode& m : f.modes)
        if (!(m.oscillator.period_s >= floor_period_min_s && m.oscillator.period_s <= floor_period_max_s) ||
            !(m.oscillator.damping >= 0.0 && m.oscillator.damping < 1.0) ||
            !(std::abs(m.participation) <= floor_participation_max))
            throw std::invalid_argument("FloorFilter: a mode outside the bounds of floor_filter.hpp");
}

std::string trimmed(const std::string& s) {
    const auto first = s.find_first_not_of(" \t");
    return first == std::string::npos ? "" : s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> parts(1);
    for (char c : s) {
        if (c == sep) parts.emplace_back();
        else parts.back().push_back(c);
    }
    for (std::string& p : parts) p = trimmed(p);
    return parts;
}

// The shortest text that reads back as the same double.
std::string exact(double x) {
    char buf[32];
    return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

constexpr const char* form = "NAME: T zeta gphi; T zeta gphi > T zeta gphi (modes ';', chained structures '>'), or ground";

// The structure's modes as one state space: x = (q_1, q_1', q_2, q_2', ...), input a_g, output
// the floor's absolute acceleration a_g + sum Gamma phi q'' = (1 - sum Gamma phi) a_g - sum Gamma phi (c q' + k q).
detail::StateSpace state_space(const FloorFilter& f) {
    check(f);
    const Eigen::Index n = 2 * static_cast<Eigen::Index>(f.modes.size());
    detail::StateSpace s{Eigen::MatrixXd::Zero(n, n), Eigen::VectorXd::Zero(n), Eigen::RowVectorXd::Zero(n), 1.0};
    for (Eigen::Index i = 0; i < n / 2; ++i) {
        const Mode& m = f.modes[static_cast<std::size_t>(i)];
        const double w = m.oscillator.omega(), k = w * w, c = 2.0 * m.oscillator.damping * w;
        s.a(2 * i, 2 * i + 1) = 1.0;
        s.a(2 * i + 1, 2 * i) = -k;
        s.a(2 * i + 1, 2 * i + 1) = -c;
        s.b(2 * i + 1) = -1.0;
        s.c(2 * i) = -m.participation * k;
        s.c(2 * i + 1) = -m.participation * c;
        s.d -= m.participation;
    }
    return s;
}

}  // namespace

std::vector<double> filter_motion(const FloorFilter& filter, std::span<const double> a, double dt_s) {
    return detail::FirstOrderHold(state_space(filter), dt_s).response(a);
}

std::vector<double> floor_motion(const Floor& floor, std::span<const double> a, double dt_s) {
    if (floor.is_ground()) return {a.begin(), a.end()};
    // The chain as one system, so that it too is exact for the ground as read: the output of a
    // building is not linear between samples, and the plinth on it must not be fed as if it were.
    detail::StateSpace s = state_space(floor.stages.front());
    for (std::size_t k = 1; k < floor.stages.size(); ++k) s = detail::series(s, state_space(floor.stages[k]));
    return detail::FirstOrderHold(s, dt_s).response(a);
}

int floor_oversampling(const Floor& floor, double dt_s) {
    double shortest = INFINITY;
    for (const FloorFilter& f : floor.stages)
        for (const Mode& m : f.modes) shortest = std::min(shortest, m.oscillator.period_s);
    if (floor.is_ground()) return 1;
    // (2 pi h / T)^2 / 8 <= tolerance
    const double h_max = shortest * std::sqrt(8.0 * floor_interpolation_tolerance) / (2.0 * M_PI);
    return std::max(1, static_cast<int>(std::ceil(dt_s / h_max)));
}

std::vector<double> oversample(std::span<const double> a, int m) {
    std::vector<double> fine;
    fine.reserve((a.size() - 1) * static_cast<std::size_t>(m) + 1);
    for (std::size_t i = 0; i + 1 < a.size(); ++i)
        for (int j = 0; j < m; ++j) fine.push_back(a[i] + (a[i + 1] - a[i]) * j / m);
    fine.push_back(a.back());
    return fine;
}

Floor parse_floor(const std::string& field, const std::string& text) {
    Floor floor;
    const auto colon = text.find(':');
    floor.name = trimmed(text.substr(0, colon));
    if (floor.name.empty() ||
        floor.name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-.") != std::string::npos)
        throw InputError(field, text, std::string("a name of letters, digits, '_', '-' or '.' first: ") + form);
    if (colon == std::string::npos) {
        if (floor.name != "ground") throw InputError(field, text, std::string("modes after the name: ") + form);
        return floor;
    }
    if (floor.name == "ground") throw InputError(field, text, "another name: 'ground' is the unfiltered ground motion");
    for (const std::string& stage : split(text.substr(colon + 1), '>')) {
        FloorFilter f;
        for (const std::string& mode : split(stage, ';')) {
            std::istringstream in(mode);
            Mode m;
            std::string rest;
            if (!(in >> m.oscillator.period_s >> m.oscillator.damping >> m.participation) || (in >> rest))
                throw InputError(field, text, "three numbers per mode, '" + mode + "' is not: " + form);
            if (!(m.oscillator.period_s >= floor_period_min_s && m.oscillator.period_s <= floor_period_max_s))
                throw InputError(field, text, "periods " + format_short(floor_period_min_s) + " s <= T <= " +
                                                  format_short(floor_period_max_s) + " s (" + mode + ")");
            if (!(m.oscillator.damping >= 0.0 && m.oscillator.damping < 1.0))
                throw InputError(field, text, "damping ratios 0 <= zeta < 1 (" + mode + ")");
            if (!(std::abs(m.participation) <= floor_participation_max))
                throw InputError(field, text, "participations |Gamma phi| <= " + format_short(floor_participation_max) +
                                                  " (" + mode + ")");
            f.modes.push_back(m);
        }
        if (f.modes.size() > floor_modes_max)
            throw InputError(field, text, "at most " + std::to_string(floor_modes_max) + " modes per structure");
        floor.stages.push_back(f);
    }
    if (floor.stages.size() > floor_stages_max)
        throw InputError(field, text, "at most " + std::to_string(floor_stages_max) + " chained structures");
    return floor;
}

std::string to_string(const Floor& floor) {
    std::string s = floor.name;
    for (std::size_t k = 0; k < floor.stages.size(); ++k) {
        s += k == 0 ? ": " : " > ";
        for (std::size_t i = 0; i < floor.stages[k].modes.size(); ++i) {
            const Mode& m = floor.stages[k].modes[i];
            s += (i == 0 ? "" : "; ") + exact(m.oscillator.period_s) + " " + exact(m.oscillator.damping) + " " +
                 exact(m.participation);
        }
    }
    return s;
}

}  // namespace rocksweep::motion
