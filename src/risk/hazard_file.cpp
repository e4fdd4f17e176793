// Hazard curves from text: the plain CSV and OpenQuake's export, both turned into annual rates
// against intensities in rocksweep's units. Every complaint names the file and line.
#include "rocksweep/risk/hazard_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <vector>

#include "rocksweep/core/errors.hpp"

namespace rocksweep {

namespace {

constexpr double standard_gravity = 9.80665;  // m/s^2 per g

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r\"");
    if (a == std::string::npos) return "";
    const auto b = s.find_last_not_of(" \t\r\"");
    return s.substr(a, b - a + 1);
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (;;) {
        const auto comma = line.find(',', start);
        out.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos) return out;
        start = comma + 1;
    }
}

bool number(const std::string& text, double& x) {
    const std::string t = !text.empty() && text[0] == '+' ? text.substr(1) : text;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
    return ec == std::errc() && end == t.data() + t.size() && !t.empty();
}

struct Measure {
    HazardMeasure measure;
    double period_s = 0;
};

/// "PGA", "PGV", "SA(0.5)" (case ignored); throws with `where`.
Measure parse_measure(const std::string& name, const std::string& field, const std::string& where) {
    static const std::regex sa(R"(SA\(\s*([0-9.eE+-]+)\s*\))", std::regex::icase);
    std::smatch m;
    std::string upper = name;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (upper == "PGA") return {HazardMeasure::pga};
    if (upper == "PGV") return {HazardMeasure::pgv};
    double t = 0;
    if (std::regex_match(name, m, sa) && number(m[1], t) && t > 0 && std::isfinite(t)) return {HazardMeasure::sa, t};
    throw InputError(field, where + ": measure " + name, "PGA, PGV or SA(T) with the period T > 0 in seconds");
}

/// The factor from `unit` to rocksweep's unit of the measure (g, or m/s for PGV).
double unit_factor(HazardMeasure m, const std::string& unit, const std::string& field, const std::string& where) {
    if (m == HazardMeasure::pgv) {
        if (unit == "m/s") return 1.0;
        if (unit == "cm/s") return 0.01;
        throw InputError(field, where + ": unit " + unit + " for PGV", "m/s or cm/s");
    }
    if (unit == "g") return 1.0;
    if (unit == "m/s2" || unit == "m/s^2") return 1.0 / standard_gravity;
    if (unit == "cm/s2" || unit == "cm/s^2") return 1.0 / (100 * standard_gravity);
    throw InputError(field, where + ": unit " + unit + " for an acceleration", "g, m/s^2 or cm/s^2");
}

/// What a file says beside its points.
struct Meta {
    std::string format;
    double years = 0;
    std::string site;
    std::size_t dropped_low = 0, dropped_high = 0;
};

/// Drops the trailing zero rates and the leading infinite ones (counted), then builds the curve.
HazardFile finish(const std::string& field, const std::string& path, Measure m, std::vector<double> x,
                  std::vector<double> rate, std::vector<int> lines, Meta partial) {
    while (!rate.empty() && rate.back() == 0) {
        rate.pop_back(), x.pop_back(), lines.pop_back();
        ++partial.dropped_high;
    }
    std::size_t first = 0;
    while (first < rate.size() && std::isinf(rate[first])) ++first;
    partial.dropped_low = first;
    for (std::size_t i = first; i < rate.size(); ++i) {
        const std::string where = path + " line " + std::to_string(lines[i]);
        if (!(rate[i] > 0 && std::isfinite(rate[i])))
            throw InputError(field, where + ": rate " + format_short(rate[i]),
                             "positive finite annual rates (0 only at the high end of the curve)");
        if (i > first && !(x[i] > x[i - 1]))
            throw InputError(field, where + ": intensity " + format_short(x[i]), "intensities strictly increasing");
        if (i > first && rate[i] > rate[i - 1])
            throw InputError(field, where + ": rate " + format_short(rate[i]) + " above the previous " + format_short(rate[i - 1]),
                             "a rate of exceedance that does not rise with intensity");
    }
    x.erase(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(first));
    rate.erase(rate.begin(), rate.begin() + static_cast<std::ptrdiff_t>(first));
    try {
        HazardFile out(HazardCurve(m.measure, m.period_s, std::move(x), std::move(rate)));
        out.format = partial.format;
        out.investigation_time_years = partial.years;
        out.site = partial.site;
        out.dropped_low = partial.dropped_low;
        out.dropped_high = partial.dropped_high;
        return out;
    } catch (const std::invalid_argument& e) {
        throw InputError(field, path, std::string("a usable hazard curve (") + e.what() + ")");
    }
}

HazardFile read_plain(const std::string& field, const std::string& path, const std::vector<std::string>& text) {
    static const std::regex head(R"(\s*([A-Za-z]+(\([^)]*\))?)\s*\[([^\]]+)\]\s*)");
    static const std::regex rate_head(R"(.*\[\s*1/yr\s*\]\s*)");
    std::size_t i = 0;
    while (i < text.size() && (trim(text[i]).empty() || trim(text[i])[0] == '#')) ++i;
    if (i == text.size()) throw InputError(field, path, "a hazard curve: a header line, then intensity,rate lines");
    const std::string where = path + " line " + std::to_string(i + 1);
    const std::vector<std::string> h = split(text[i]);
    std::smatch mh;
    if (h.size() != 2 || !std::regex_match(h[0], mh, head) || !std::regex_match(h[1], rate_head))
        throw InputError(field, where + ": " + text[i],
                         "a header of two columns: the measure and its unit, then the rate, e.g. \"PGA [g],annual_rate [1/yr]\"");
    const Measure m = parse_measure(mh[1], field, where);
    const double factor = unit_factor(m.measure, trim(mh[3]), field, where);
    std::vector<double> x, rate;
    std::vector<int> lines;
    for (++i; i < text.size(); ++i) {
        const std::string t = trim(text[i]);
        if (t.empty() || t[0] == '#') continue;
        const std::vector<std::string> f = split(t);
        double a = 0, b = 0;
        if (f.size() != 2 || !number(f[0], a) || !number(f[1], b) || !std::isfinite(a) || !std::isfinite(b))
            throw InputError(field, path + " line " + std::to_string(i + 1) + ": " + t, "two finite numbers: intensity,rate");
        x.push_back(a * factor);
        rate.push_back(b);
        lines.push_back(static_cast<int>(i + 1));
        if (b < 0)
            throw InputError(field, path + " line " + std::to_string(i + 1) + ": rate " + f[1], "annual rates >= 0");
    }
    const Meta partial{"plain", 0, "", 0, 0};
    return finish(field, path, m, std::move(x), std::move(rate), std::move(lines), partial);
}

HazardFile read_openquake(const std::string& field, const std::string& path, const std::vector<std::string>& text, int site) {
    static const std::regex time(R"(investigation_time\s*=\s*'?([0-9.eE+-]+))");
    static const std::regex imt(R"(imt\s*=\s*['"]([^'"]+)['"])");
    const std::string where1 = path + " line 1";
    std::smatch mt, mi;
    double years = 0;
    if (!std::regex_search(text[0], mt, time) || !number(mt[1], years) || !(years > 0 && std::isfinite(years)))
        throw InputError(field, where1, "OpenQuake's first line with investigation_time=T, T > 0 in years");
    if (!std::regex_search(text[0], mi, imt)) throw InputError(field, where1, "OpenQuake's first line with imt='PGA' (or PGV, SA(T))");
    const Measure m = parse_measure(mi[1], field, where1);
    if (text.size() < 3) throw InputError(field, path, "OpenQuake's header line lon,lat,depth,poe-... and at least one site");
    const std::vector<std::string> h = split(text[1]);
    std::size_t first = 0;
    while (first < h.size() && h[first].rfind("poe-", 0) != 0) ++first;
    std::vector<double> iml;
    for (std::size_t c = first; c < h.size(); ++c) {
        double v = 0;
        if (h[c].rfind("poe-", 0) != 0 || !number(h[c].substr(4), v))
            throw InputError(field, path + " line 2: column " + h[c], "OpenQuake's columns poe-<intensity> after the site's");
        // OpenQuake writes PGA and SA in g, PGV in cm/s.
        iml.push_back(v * (m.measure == HazardMeasure::pgv ? 0.01 : 1.0));
    }
    if (first < 2 || iml.size() < 2) throw InputError(field, path + " line 2", "OpenQuake's header lon,lat[,depth],poe-<x1>,poe-<x2>,...");
    std::vector<std::size_t> rows;
    for (std::size_t i = 2; i < text.size(); ++i)
        if (!trim(text[i]).empty()) rows.push_back(i);
    if (site < 0 && rows.size() != 1)
        throw InputError("hazard-site", "unset", "a row of " + path + " (0 .. " + std::to_string(rows.size() - 1) + "): it holds " +
                                                     std::to_string(rows.size()) + " sites");
    if (site >= 0 && static_cast<std::size_t>(site) >= rows.size())
        throw InputError("hazard-site", std::to_string(site), "0 .. " + std::to_string(rows.size() - 1) + " (the sites of " + path + ")");
    const std::size_t line = rows[site < 0 ? 0 : static_cast<std::size_t>(site)];
    const std::vector<std::string> f = split(text[line]);
    const std::string where = path + " line " + std::to_string(line + 1);
    if (f.size() != h.size()) throw InputError(field, where, std::to_string(h.size()) + " fields, as the header");
    Meta partial{"openquake", years, "", 0, 0};
    for (std::size_t c = 0; c < first; ++c) partial.site += (c ? " " : "") + f[c];
    std::vector<double> rate;
    std::vector<int> lines;
    for (std::size_t c = first; c < f.size(); ++c) {
        double p = 0;
        if (!number(f[c], p) || !(p >= 0 && p <= 1))
            throw InputError(field, where + ": " + h[c] + " = " + f[c], "a probability of exceedance in [0, 1]");
        rate.push_back(rate_from_probability(p, years));
        lines.push_back(static_cast<int>(line + 1));
    }
    return finish(field, path, m, std::move(iml), std::move(rate), std::move(lines), partial);
}

}  // namespace

HazardFile read_hazard_file(const std::string& field, const std::string& path, int site) {
    std::ifstream in(path);
    if (!in) throw InputError(field, path, "a readable hazard curve file");
    std::vector<std::string> text;
    for (std::string line; std::getline(in, line);) text.push_back(line);
    if (text.empty()) throw InputError(field, path, "a hazard curve; the file is empty");
    if (trim(text[0]).rfind('#', 0) == 0 && text[0].find("investigation_time") != std::string::npos)
        return read_openquake(field, path, text, site);
    if (trim(text[0]).rfind('#', 0) == 0 && text.size() > 1 && text[1].rfind("lon,lat", 0) == 0)
        throw InputError(field, path + " line 1", "OpenQuake's first line with investigation_time=T (years); it has none");
    if (site >= 0) throw InputError("hazard-site", std::to_string(site), "an OpenQuake file to pick a site of; " + path + " is a plain curve");
    return read_plain(field, path, text);
}

}  // namespace rocksweep
