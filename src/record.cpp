#include "rocksweep/record.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "rocksweep/errors.hpp"

namespace rocksweep {

Pulse read_record(const std::string& path, const std::string& units, double scale, double gravity) {
    double to_g;  // sample * to_g = acceleration / (the block's g)
    if (units == "g") to_g = 9.80665 / gravity;
    else if (units == "m/s^2") to_g = 1.0 / gravity;
    else throw InputError("record-units", units, "g or m/s^2 (the unit of the record's second column)");
    std::ifstream in(path);
    if (!in) throw InputError("record", path, "a readable two-column text file");
    std::vector<double> t, a;
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
        std::istringstream ls(line);
        double ti, ai;
        std::string rest;
        if (!(ls >> ti >> ai) || (ls >> rest) || !std::isfinite(ti) || !std::isfinite(ai))
            throw InputError("record", path + " line " + std::to_string(n), "two finite numbers per line: time [s] and acceleration");
        t.push_back(ti);
        a.push_back(ai * scale * to_g);
    }
    if (a.size() < 2) throw InputError("record", path, "at least two samples");
    if (std::abs(t[0]) > 1e-9) throw InputError("record", path, "samples starting at t = 0 (first is " + format_number(t[0]) + " s)");
    const double dt = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
    for (std::size_t i = 1; i < t.size(); ++i)
        if (!(std::abs(t[i] - t[i - 1] - dt) <= 1e-6 * dt + 1e-9))
            throw InputError("record", path + " line near t = " + format_number(t[i]), "evenly spaced samples (dt = " + format_number(dt) + " s)");
    Pulse p;
    p.kind = PulseKind::record;
    p.record = std::make_shared<const std::vector<double>>(std::move(a));
    p.record_dt_s = dt;
    return p;
}

}  // namespace rocksweep
