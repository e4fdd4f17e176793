#include "rocksweep/records/suite_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/grid/block_family.hpp"
#include "rocksweep/motion/response_spectrum.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/records/made_measures.hpp"

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
    {IntensityMeasure::sa_g, "sa", "sa_g", "1", "target spectral pseudo-acceleration Sa(T, zeta) of the ground / standard gravity"},
    {IntensityMeasure::pfa_g, "pfa", "pfa_g", "1", "target peak floor acceleration / standard gravity"},
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
    throw InputError(field, text, "one of pga, pgv, pga-ratio, scale, sa, pfa");
}

std::string to_string(IntensityMeasure m) { return info(m).name; }
const char* intensity_units(IntensityMeasure m) { return info(m).units; }
const char* intensity_long_name(IntensityMeasure m) { return info(m).long_name; }

Block SuiteSpec::block_of(double alpha_rad, double radius_m) const { return reshaped_block(block, alpha_rad, radius_m); }

double SuiteSpec::scale_factor(std::size_t r, std::size_t alpha, std::size_t level, std::size_t floor) const {
    const double x = intensity.at(level);
    const IntensityMeasures& im = records.at(r).measures;
    switch (measure) {
        case IntensityMeasure::sa_g: return x / records[r].sa_g;
        case IntensityMeasure::pfa_g: return x / records[r].floors.at(floor).pfa_g;
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
    const std::size_t floor = floor_of(at.scenario);
    const FloorResponse& on = rec.floors.at(floor);
    Pulse pulse = ground ? *ground
                  : on.pulse.record && b.gravity == block.gravity ? on.pulse
                                                                  : to_pulse(on_floor(rec.record, floors[floor]), b.gravity);
    pulse.record_scale = scale_factor(at.record, at.alpha, at.level, floor);
    return make_cell_model(b, anchorage_on(sc, block, b), pulse, equations, impact_threshold);
}

Record on_floor(const Record& ground, const motion::Floor& floor) {
    Record on = ground;
    if (floor.is_ground()) return on;
    const int m = motion::floor_oversampling(floor, ground.dt_s);
    on.dt_s = ground.dt_s / m;
    on.ax_g = motion::floor_motion(floor, motion::oversample(ground.ax_g, m), on.dt_s);
    if (!ground.ay_g.empty()) on.ay_g = motion::oversample(ground.ay_g, m);
    return on;
}

namespace {

// A motion's measures on the ground and on every floor of `spec`; the floors' samples are kept
// (as pulses every cell shares) only when `keep`: a made motion's are made again in the cells.
void measure_member(SuiteMember& m, const SuiteSpec& spec, bool keep) {
    m.measures = intensity_measures(m.record);
    if (keep) m.pulse = to_pulse(m.record, spec.block.gravity);
    m.sa_g = motion::spectral_acceleration(m.record.ax_g, m.record.dt_s, spec.sa);
    const std::vector<double> periods = motion::floor_spectrum_periods();
    for (const motion::Floor& floor : spec.floors) {
        const Record r = on_floor(m.record, floor);
        FloorResponse on;
        if (keep) on.pulse = floor.is_ground() ? m.pulse : to_pulse(r, spec.block.gravity);
        for (double x : r.ax_g) on.pfa_g = std::max(on.pfa_g, std::abs(x));
        on.spectrum_g = motion::response_spectrum(r.ax_g, r.dt_s, periods, 0.05);
        m.floors.push_back(std::move(on));
    }
}

// A level is reached by dividing by the motion's own measure: one without it (all zeros) cannot
// be scaled to any level.
void require_measure(IntensityMeasure measure, const SuiteMember& m, const std::string& where) {
    double own = measure == IntensityMeasure::pgv_m_s ? m.measures.pgv_m_s
                 : measure == IntensityMeasure::sa_g  ? m.sa_g
                                                      : m.measures.pga_g;
    if (measure == IntensityMeasure::pfa_g)
        for (const FloorResponse& on : m.floors) own = std::min(own, on.pfa_g);
    if (measure != IntensityMeasure::scale && !(own > 0.0))
        throw InputError("suite", where,
                         "records with a non-zero " + std::string(info(measure).name) + " to scale to a level (" +
                             m.entry.name + " has none)");
}

}  // namespace

void measure_made_motions(SuiteSpec& spec, std::size_t first, std::size_t count) {
    const std::size_t made = spec.records.size() - spec.motions->size();  // made motions follow the file's records
    for (std::size_t i = first; i < first + count; ++i) {
        SuiteMember& m = spec.records.at(made + i);
        m.record = spec.motions->motion(i);
        m.floors.clear();
        measure_member(m, spec, false);
        m.record.ax_g = std::vector<double>();  // frees the samples: `= {}` would keep their capacity
    }
}

void check_made_measures(const SuiteSpec& spec) {
    for (const SuiteMember& m : spec.records)
        if (m.motion >= 0) require_measure(spec.measure, m, "synthetic motion " + std::to_string(m.motion));
}

SuiteSpec make_suite_spec(const std::string& suite_path, const Block& block, std::vector<Scenario> scenarios,
                          IntensityMeasure measure, Axis intensity, std::vector<double> radii_m,
                          std::vector<double> alphas_rad, SuiteMotions motions) {
    SuiteSpec spec;
    spec.block = block;
    spec.suite_path = suite_path;
    spec.sa = motions.sa;
    spec.floors = motions.floors.empty() ? std::vector<motion::Floor>{motion::Floor{}} : motions.floors;
    for (std::size_t i = 0; i < spec.floors.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (spec.floors[i].name == spec.floors[j].name)
                throw InputError("floor", spec.floors[i].name, "distinct names (a floor is listed twice)");
    if (!suite_path.empty()) {
        const RecordSuite suite = read_record_suite(suite_path);
        spec.metadata_columns = suite.metadata_columns;
        for (const SuiteRecord& entry : suite.records) {
            SuiteMember m{entry, read_suite_record(suite, entry), {}, {}, -1, 0.0, {}};
            measure_member(m, spec, true);
            require_measure(measure, m, suite_path + " line " + std::to_string(entry.line));
            spec.records.push_back(std::move(m));
        }
    }
    // Made motions: measured (now, or in shares: made_measures.hpp) on the ground and every
    // floor, as a read record is; their samples dropped, the cells make them again
    // (compute_suite_cells).
    const std::shared_ptr<const MotionSource>& made = motions.made;
    for (std::size_t i = 0; made && i < made->size(); ++i) {
        SuiteMember m;
        m.entry.name = made->name(i);
        m.entry.metadata.assign(spec.metadata_columns.size(), "");
        m.record = made->described(i);
        m.motion = static_cast<std::ptrdiff_t>(i);
        spec.records.push_back(std::move(m));
    }
    spec.motions = std::move(motions.made);
    if (spec.records.empty()) throw InputError("suite", suite_path, "a suite with at least one record");
    spec.measure = measure;
    if (spec.motions && motions.measures == SuiteMotions::Measures::all) {
        measure_made_motions(spec, 0, spec.motions->size());
        check_made_measures(spec);
    }
    spec.intensity = intensity;
    if (radii_m.empty()) radii_m.push_back(block.radius_m);
    if (alphas_rad.empty()) alphas_rad.push_back(block.alpha_rad);
    spec.radii_m = std::move(radii_m);
    spec.alphas_rad = std::move(alphas_rad);
    // Every scenario on every floor; on the ground alone, the scenarios keep their names.
    const bool ground_only = spec.floors.size() == 1 && spec.floors[0].is_ground();
    for (std::size_t f = 0; f < spec.floors.size(); ++f)
        for (Scenario sc : scenarios) {
            if (!ground_only) sc.name += "@" + spec.floors[f].name;
            spec.scenarios.push_back(std::move(sc));
            spec.scenario_floor.push_back(f);
        }
    return spec;
}

void compute_suite_cells(const SuiteSpec& spec, const IntegratorSettings& settings, std::size_t first,
                         std::size_t count, CellResult* out, int lanes) {
    std::vector<CellModel> cells(count);
    // The made motion `ground` holds, on its floor: cells of one scenario and record are
    // consecutive, so each is made (and filtered) once per run of them. The same function of
    // (motion, floor) as make_suite_spec measured, so a level reaches its target exactly.
    std::size_t made = spec.records.size(), made_floor = 0;
    Pulse ground;
    for (std::size_t i = 0; i < count; ++i) {
        const SuiteSpec::Coordinates at = spec.coordinates(first + i);
        const SuiteMember& m = spec.records[at.record];
        if (m.motion < 0) {
            cells[i] = spec.cell(first + i);
            continue;
        }
        const std::size_t floor = spec.floor_of(at.scenario);
        if (at.record != made || floor != made_floor) {
            const Record motion = spec.motions->motion(static_cast<std::size_t>(m.motion));
            ground = to_pulse(on_floor(motion, spec.floors.at(floor)), spec.block.gravity);
            made = at.record;
            made_floor = floor;
        }
        cells[i] = spec.cell(first + i, &ground);
    }
    if (!spec.sensitivity.on) {
        integrate_cells(cells, std::span<CellResult>(out, count), settings, lanes);
        return;
    }
    std::vector<CellModel> perturbed = cells;
    for (CellModel& c : perturbed) c.pulse.record_scale *= 1.0 + SensitivityCheck::scale_step;
    integrate_cells(cells, std::span<CellResult>(out, count), settings, lanes);
    std::vector<CellResult> again(count);
    integrate_cells(perturbed, again, SensitivityCheck::tighter(settings), lanes);
    for (std::size_t i = 0; i < count; ++i) out[i].sensitive = spec.sensitivity.differ(out[i], again[i]) ? 1 : 0;
}

IntegratorSettings SensitivityCheck::tighter(IntegratorSettings s) {
    if (s.tolerance > 0.0) s.tolerance /= tolerance_divisor;
    else if (s.method == Method::events) s.steps_per_period *= std::sqrt(std::sqrt(tolerance_divisor));
    else s.paper_dt_s /= std::sqrt(std::sqrt(tolerance_divisor));
    return s;
}

bool SensitivityCheck::differ(const CellResult& a, const CellResult& b) const {
    if (a.outcome != b.outcome) return true;
    for (double ratio : damage_ratios)
        if ((a.max_rotation >= ratio) != (b.max_rotation >= ratio)) return true;
    return false;
}

}  // namespace rocksweep
