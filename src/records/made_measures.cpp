#include "rocksweep/records/made_measures.hpp"

#include <stdexcept>

#include "rocksweep/motion/response_spectrum.hpp"

namespace rocksweep {

namespace {

// Made motion i's member: made motions follow the file's records.
std::size_t member_of(const SuiteSpec& spec, std::size_t i) { return spec.records.size() - spec.motions->size() + i; }

// Numbers per made motion: the intensity fields, Sa, and on each floor its PFA and spectrum.
std::size_t full_width(const SuiteSpec& spec) {
    return std::size(intensity_fields) + 1 + spec.floors.size() * (1 + motion::floor_spectrum_periods().size());
}

// PGA, PGV, Sa and each floor's PFA.
std::size_t scaling_width(const SuiteSpec& spec) { return 3 + spec.floors.size(); }

void require_size(std::size_t got, std::size_t want, const char* what) {
    if (got != want) throw std::invalid_argument(std::string(what) + ": the numbers do not fit this suite's motions");
}

}  // namespace

std::vector<double> pack_made_measures(const SuiteSpec& spec, std::size_t first, std::size_t count) {
    std::vector<double> out;
    out.reserve(count * full_width(spec));
    for (std::size_t i = first; i < first + count; ++i) {
        const SuiteMember& m = spec.records.at(member_of(spec, i));
        for (const IntensityField& f : intensity_fields) out.push_back(m.measures.*f.value);
        out.push_back(m.sa_g);
        require_size(m.floors.size(), spec.floors.size(), "pack_made_measures");
        for (const FloorResponse& on : m.floors) {
            out.push_back(on.pfa_g);
            out.insert(out.end(), on.spectrum_g.begin(), on.spectrum_g.end());
        }
    }
    require_size(out.size(), count * full_width(spec), "pack_made_measures");
    return out;
}

void unpack_made_measures(SuiteSpec& spec, std::size_t first, std::span<const double> packed) {
    const std::size_t width = full_width(spec), periods = motion::floor_spectrum_periods().size();
    require_size(packed.size() % width, 0, "unpack_made_measures");
    const double* x = packed.data();
    for (std::size_t i = first; i < first + packed.size() / width; ++i) {
        SuiteMember& m = spec.records.at(member_of(spec, i));
        for (const IntensityField& f : intensity_fields) m.measures.*f.value = *x++;
        m.sa_g = *x++;
        m.floors.assign(spec.floors.size(), FloorResponse{});
        for (FloorResponse& on : m.floors) {
            on.pfa_g = *x++;
            on.spectrum_g.assign(x, x + periods);
            x += periods;
        }
    }
}

std::vector<double> pack_scaling_measures(const SuiteSpec& spec) {
    std::vector<double> out;
    out.reserve(spec.motions->size() * scaling_width(spec));
    for (std::size_t i = 0; i < spec.motions->size(); ++i) {
        const SuiteMember& m = spec.records[member_of(spec, i)];
        require_size(m.floors.size(), spec.floors.size(), "pack_scaling_measures");
        out.insert(out.end(), {m.measures.pga_g, m.measures.pgv_m_s, m.sa_g});
        for (const FloorResponse& on : m.floors) out.push_back(on.pfa_g);
    }
    return out;
}

void unpack_scaling_measures(SuiteSpec& spec, std::span<const double> packed) {
    require_size(packed.size(), spec.motions->size() * scaling_width(spec), "unpack_scaling_measures");
    const double* x = packed.data();
    for (std::size_t i = 0; i < spec.motions->size(); ++i) {
        SuiteMember& m = spec.records[member_of(spec, i)];
        m.measures.pga_g = *x++;
        m.measures.pgv_m_s = *x++;
        m.sa_g = *x++;
        m.floors.assign(spec.floors.size(), FloorResponse{});
        for (FloorResponse& on : m.floors) on.pfa_g = *x++;
    }
}

}  // namespace rocksweep
