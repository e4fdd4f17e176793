#include "rocksweep/records/suite_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/grid/block_family.hpp"
#include "rocksweep/physics/integrator.hpp"

namespace rocksweep {

namespace {

struct MeasureInfo {
    IntensityMeasure measure;
    const char* word;   // as the option takes it
    const char* name;   // dataset and attribute name
    const char* units;  // CF units
    const char* long_name;
};

constexpr MeasureInfo measures[] = {
    {IntensityMeasure::pga_g, "pga", "pga_g", "1", "target peak ground acceleration / standard gravity"},
    {IntensityMeasure::pgv_m_s, "pgv", "pgv_m_s", "m/s", "target peak ground velocity"},
    {IntensityMeasure::pga_ratio, "pga-ratio", "pga_ratio", "1", "target PGA / (g tan alpha)"},
    {IntensityMeasure::scale, "scale", "scale", "1", "scale factor applied to every record"},
};

const MeasureInfo& info(IntensityMeasure m) {
    for (const MeasureInfo& i : measures)
        if (i.measure == m) return i;
    return measures[0];  // not reached: every measure has its row
}

}  // namespace

IntensityMeasure parse_intensity_measure(const std::string& field, const std::string& text) {
    for (const MeasureInfo& i : measures)
        if (text == i.word) return i.measure;
    throw InputError(field, text, "one of pga, pgv, pga-ratio, scale");
}

std::string to_string(IntensityMeasure m) { return info(m).name; }
const char* intensity_units(IntensityMeasure m) { return info(m).units; }
const char* intensity_long_name(IntensityMeasure m) { return info(m).long_name; }

Block SuiteSpec::block_of(double alpha_rad, double radius_m) const { return reshaped_block(block, alpha_rad, radius_m); }

double SuiteSpec::scale_factor(std::size_t r, std::size_t alpha, std::size_t level) const {
    const double x = intensity.at(level);
    const IntensityMeasures& im = records.at(r).measures;
    switch (measure) {
        case IntensityMeasure::pga_g: return x / im.pga_g;
        case IntensityMeasure::pgv_m_s: return x / im.pgv_m_s;
        case IntensityMeasure::pga_ratio: return x / pga_over_g_tan_alpha(im.pga_g, alphas_rad.at(alpha), block.gravity);
        case IntensityMeasure::scale: return x;
    }
    return x;
}

SuiteSpec::Coordinates SuiteSpec::coordinates(std::size_t index) const {
    Coordinates c;
    c.level = index % intensity.points;
    index /= intensity.points;
    c.radius = index % radii_m.size();
    index /= radii_m.size();
    c.alpha = index % alphas_rad.size();
    index /= alphas_rad.size();
    c.record = index % records.size();
    c.scenario = index / records.size();
    return c;
}

std::size_t SuiteSpec::index(const Coordinates& c) const {
    return (((c.scenario * records.size() + c.record) * alphas_rad.size() + c.alpha) * radii_m.size() + c.radius) *
               intensity.points +
           c.level;
}

CellModel SuiteSpec::cell(std::size_t index, const Pulse* ground) const {
    const Coordinates at = coordinates(index);
    const Scenario& sc = scenarios.at(at.scenario);
    const Block b = block_of(alphas_rad[at.alpha], radii_m[at.radius]);
    // Every cell of a record shares its samples (both components); the level scales them per lane.
    const SuiteMember& rec = records[at.record];
    if (rec.motion >= 0 && !ground) throw std::logic_error("SuiteSpec::cell: a made motion needs its ground");
    Pulse pulse = ground ? *ground
                  : rec.pulse.record && b.gravity == block.gravity ? rec.pulse
                                                                   : to_pulse(rec.record, b.gravity);
    pulse.record_scale = scale_factor(at.record, at.alpha, at.level);
    return make_cell_model(b, anchorage_on(sc, block, b), pulse, equations, impact_threshold);
}

namespace {

// A level is reached by dividing by the motion's own measure: one without it (all zeros) cannot
// be scaled to any level.
void require_measure(IntensityMeasure measure, const SuiteMember& m, const std::string& where) {
    const double own = measure == IntensityMeasure::pgv_m_s ? m.measures.pgv_m_s : m.measures.pga_g;
    if (measure != IntensityMeasure::scale && !(own > 0.0))
        throw InputError("suite", where,
                         "records with a non-zero " + std::string(info(measure).name) + " to scale to a level (" +
                             m.entry.name + " has none)");
}

}  // namespace

SuiteSpec make_suite_spec(const std::string& suite_path, const Block& block, std::vector<Scenario> scenarios,
                          IntensityMeasure measure, Axis intensity, std::vector<double> radii_m,
                          std::vector<double> alphas_rad, std::shared_ptr<const MotionSource> motions) {
    SuiteSpec spec;
    spec.block = block;
    spec.suite_path = suite_path;
    if (!suite_path.empty()) {
        const RecordSuite suite = read_record_suite(suite_path);
        spec.metadata_columns = suite.metadata_columns;
        for (const SuiteRecord& entry : suite.records) {
            SuiteMember m{entry, read_suite_record(suite, entry), {}, {}, -1};
            m.measures = intensity_measures(m.record);
            m.pulse = to_pulse(m.record, block.gravity);
            require_measure(measure, m, suite_path + " line " + std::to_string(entry.line));
            spec.records.push_back(std::move(m));
        }
    }
    // Made motions: measured now, their samples dropped; the cells make them again.
    for (std::size_t i = 0; motions && i < motions->size(); ++i) {
        SuiteMember m;
        m.entry.name = motions->name(i);
        m.entry.metadata.assign(spec.metadata_columns.size(), "");
        m.record = motions->motion(i);
        m.measures = intensity_measures(m.record);
        m.record.ax_g = {};
        m.motion = static_cast<std::ptrdiff_t>(i);
        require_measure(measure, m, "synthetic motion " + std::to_string(i));
        spec.records.push_back(std::move(m));
    }
    spec.motions = std::move(motions);
    if (spec.records.empty()) throw InputError("suite", suite_path, "a suite with at least one record");
    spec.measure = measure;
    spec.intensity = intensity;
    if (radii_m.empty()) radii_m.push_back(block.radius_m);
    if (alphas_rad.empty()) alphas_rad.push_back(block.alpha_rad);
    spec.radii_m = std::move(radii_m);
    spec.alphas_rad = std::move(alphas_rad);
    spec.scenarios = std::move(scenarios);
    return spec;
}

void compute_suite_cells(const SuiteSpec& spec, const IntegratorSettings& settings, std::size_t first,
                         std::size_t count, CellResult* out, int lanes) {
    std::vector<CellModel> cells(count);
    std::size_t made = spec.records.size();  // the record whose motion `ground` holds
    Pulse ground;
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t r = spec.coordinates(first + i).record;
        const SuiteMember& m = spec.records[r];
        if (m.motion < 0) {
            cells[i] = spec.cell(first + i);
            continue;
        }
        if (r != made) {
            ground = to_pulse(spec.motions->motion(static_cast<std::size_t>(m.motion)), spec.block.gravity);
            made = r;
        }
        cells[i] = spec.cell(first + i, &ground);
    }
    integrate_cells(cells, std::span<CellResult>(out, count), settings, lanes);
}

}  // namespace rocksweep
