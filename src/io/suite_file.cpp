#include "rocksweep/io/suite_file.hpp"

#include <algorithm>
#include <charconv>
#include <optional>
#include <set>

#include "result_columns.hpp"
#include "suite_layout.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/grid_layout.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/motion/response_spectrum.hpp"

namespace rocksweep {

using suite_detail::write_measure_on;

namespace {

constexpr std::int64_t format_version = 4;  // 2: the alpha_rad axis; 3: median -> median_intensity; 4: floors and Sa
constexpr const char* kind = "suite";

GridAxis record_axis(const SuiteSpec& spec) {
    std::vector<double> index(spec.records.size());
    for (std::size_t i = 0; i < index.size(); ++i) index[i] = static_cast<double>(i);
    return {"record", "1", "record (names: flag_meanings of /records/record)", index};
}
GridAxis alpha_axis(const SuiteSpec& spec) {
    return {"alpha_rad", "rad", "slenderness angle alpha = atan(b/h) of the block", spec.alphas_rad};
}
GridAxis radius_axis(const SuiteSpec& spec) {
    return {"radius_m", "m", "block size R (corner to centre of mass)", spec.radii_m};
}
GridAxis intensity_axis(const SuiteSpec& spec) {
    return {"intensity", intensity_units(spec.measure), intensity_long_name(spec.measure), spec.intensity.values()};
}

std::string record_names(const SuiteSpec& spec) {
    std::string names;
    for (const SuiteMember& m : spec.records) names += (names.empty() ? "" : " ") + m.entry.name;
    return names;
}

// The shortest text that reads back as the same double: a resume compares it exactly.
std::string shortest(double x) {
    char buf[32];
    return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

std::string floor_texts(const SuiteSpec& spec) {
    std::string texts;
    for (const motion::Floor& f : spec.floors) texts += (texts.empty() ? "" : "\n") + motion::to_string(f);
    return texts;
}

/// What defines the cells beyond the block and the numerics: compared on resume.
std::vector<io::NamedText> root_texts(const SuiteSpec& spec) {
    return {{"intensity_measure", to_string(spec.measure)},
            {"records", record_names(spec)},
            {"floors", floor_texts(spec)},
            {"sa_oscillator", "T = " + shortest(spec.sa.period_s) + " s, zeta = " + shortest(spec.sa.damping)}};
}

/// The suite's settings beyond the integrator's: compared on resume, naming the option.
std::vector<io::Setting> suite_settings(const SuiteSpec& spec, const IntegratorSettings& settings) {
    std::vector<io::Setting> all = io::numerics_settings(settings, spec.impact_threshold, spec.equations);
    // Files from before --check-sensitivity were not checked.
    all.push_back({"check_sensitivity", "check-sensitivity", spec.sensitivity.on ? "on" : "off", 0.0, true, "off"});
    return all;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Each floor's motion, per record and as the suite's median: what the blocks there stood on.
void write_floors(const h5::File& f, const SuiteSpec& spec) {
    const h5::Group floors = f.create_group("floors");
    h5::write_attribute(floors, "spectrum_damping", 0.05);
    const std::vector<double> periods = motion::floor_spectrum_periods();
    const std::size_t n = spec.records.size(), alphas = spec.alphas_rad.size(), levels = spec.intensity.points;
    for (std::size_t k = 0; k < spec.floors.size(); ++k) {
        const h5::Group g = floors.create_group(spec.floors[k].name);
        h5::write_attribute(g, "floor", motion::to_string(spec.floors[k]));
        const GridAxis axes[] = {record_axis(spec), alpha_axis(spec), intensity_axis(spec),
                                 {"period_s", "s", "natural period of the 5 %-damped oscillator", periods}};
        const GridGroup grid(g, axes);
        std::vector<double> pfa, ratio, spectrum, median_spectrum, scale;
        for (const SuiteMember& m : spec.records) {
            pfa.push_back(m.floors[k].pfa_g);
            ratio.push_back(m.floors[k].pfa_g / m.measures.pga_g);
            spectrum.insert(spectrum.end(), m.floors[k].spectrum_g.begin(), m.floors[k].spectrum_g.end());
        }
        for (std::size_t t = 0; t < periods.size(); ++t) {
            std::vector<double> at;
            for (const SuiteMember& m : spec.records) at.push_back(m.floors[k].spectrum_g[t]);
            median_spectrum.push_back(median(at));
        }
        for (std::size_t r = 0; r < n; ++r)
            for (std::size_t a = 0; a < alphas; ++a)
                for (std::size_t l = 0; l < levels; ++l) scale.push_back(spec.scale_factor(r, a, l, k));
        write_measure_on(grid, "pfa_g", pfa, {"record"}, "1", "peak floor acceleration of the record as read / standard gravity");
        write_measure_on(grid, "pfa_over_pga", ratio, {"record"}, "1", "peak floor acceleration / peak ground acceleration");
        write_measure_on(grid, "spectrum_g", spectrum, {"record", "period_s"}, "1",
                         "5 %-damped pseudo-acceleration spectrum of the floor motion / standard gravity");
        write_measure_on(grid, "median_spectrum_g", median_spectrum, {"period_s"}, "1",
                         "median over the records of spectrum_g / standard gravity");
        h5::write_attribute(g, "median_pfa_g", median(pfa));
        h5::write_attribute(g, "median_pfa_over_pga", median(ratio));
        write_measure_on(grid, "scale_factor", scale, {"record", "alpha_rad", "intensity"}, "1",
                         "factor each record is multiplied by at each level, for the blocks on this floor");
    }
}

/// Datasets of /records: a record of one of these names would collide with them.
std::set<std::string> records_datasets() {
    std::set<std::string> names{"record", "alpha_rad", "intensity", "scale_factor", "pga_scaled_g", "sa_g"};
    for (const IntensityField& f : intensity_fields) names.insert(f.name);
    return names;
}

std::string reserved_record_names() {
    std::string out;
    for (const std::string& n : records_datasets()) out += n + ", ";
    return out + "names of dots only";
}

void write_records(const h5::File& f, const SuiteSpec& spec) {
    const h5::Group g = f.create_group("records");
    const GridAxis axes[] = {record_axis(spec), alpha_axis(spec), intensity_axis(spec)};
    const GridGroup grid(g, axes);
    const h5::Dataset record = g.open_dataset("record");
    h5::write_attribute(record, "flag_values", std::span<const double>(axes[0].values));
    h5::write_attribute(record, "flag_meanings", record_names(spec));
    const std::size_t n = spec.records.size(), alphas = spec.alphas_rad.size(), levels = spec.intensity.points;
    for (const IntensityField& field : intensity_fields) {
        std::vector<double> v;
        for (const SuiteMember& m : spec.records) v.push_back(m.measures.*field.value);
        const h5::Dataset ds = grid.write_on<double>(field.name, v, {"record"});
        h5::write_attribute(ds, "units", field.units);
        h5::write_attribute(ds, "long_name", field.long_name);
    }
    std::vector<double> sa;
    for (const SuiteMember& m : spec.records) sa.push_back(m.sa_g);
    const h5::Dataset sa_ds = grid.write_on<double>("sa_g", sa, {"record"});
    h5::write_attribute(sa_ds, "units", "1");
    h5::write_attribute(sa_ds, "long_name", "spectral pseudo-acceleration Sa(T, zeta) of the record as read / standard gravity");
    h5::write_attribute(sa_ds, "period_s", spec.sa.period_s);
    h5::write_attribute(sa_ds, "damping", spec.sa.damping);
    std::vector<double> scale, pga;
    for (std::size_t r = 0; r < n; ++r)
        for (std::size_t a = 0; a < alphas; ++a)
            for (std::size_t l = 0; l < levels; ++l) {
                scale.push_back(spec.scale_factor(r, a, l));
                pga.push_back(scale.back() * spec.records[r].measures.pga_g);
            }
    h5::write_attribute(grid.write<double>("scale_factor", scale), "long_name", "factor each record is multiplied by at each level");
    const h5::Dataset ds = grid.write<double>("pga_scaled_g", pga);
    h5::write_attribute(ds, "units", "1");
    h5::write_attribute(ds, "long_name", "peak ground acceleration of the scaled record / standard gravity");
    for (const SuiteMember& m : spec.records) {
        const h5::Group rg = g.create_group(m.entry.name);
        h5::write_attribute(rg, "file", m.record.path);
        h5::write_attribute(rg, "format", to_string(m.record.format));
        h5::write_attribute(rg, "units", m.record.units);
        h5::write_attribute(rg, "dt_s", m.record.dt_s);
        h5::write_attribute(rg, "column", m.record.column);
        h5::write_attribute(rg, "scale", m.record.scale);
        h5::write_attribute(rg, "suite_line", m.entry.line);
        for (std::size_t c = 0; c < spec.metadata_columns.size(); ++c)
            h5::write_attribute(rg, spec.metadata_columns[c], m.entry.metadata.at(c));
    }
}

}  // namespace

void suite_detail::write_measure_on(const GridGroup& grid, const char* name, const std::vector<double>& v,
                      std::initializer_list<std::string_view> axes, const char* units, const char* long_name) {
    const h5::Dataset ds = grid.write_on<double>(name, v, axes);
    h5::write_attribute(ds, "units", units);
    h5::write_attribute(ds, "long_name", long_name);
}

std::vector<GridAxis> suite_detail::result_axes(const SuiteSpec& spec) {
    return {record_axis(spec), alpha_axis(spec), radius_axis(spec), intensity_axis(spec)};
}

void suite_detail::write_contents(const h5::File& f, const SuiteSpec& spec, bool finished,
                                  std::span<const hsize_t> chunk, std::size_t n_done, const Provenance& prov, const IntegratorSettings& settings,
                                  const CheckpointStats& saves) {
    check_record_names(spec);
    h5::write_attribute(f, "title", "rocksweep record-suite sweep");
    h5::write_attribute(f, "Conventions", h5::cf_conventions);
    h5::write_attribute(f, "format_version", format_version);
    h5::write_attribute(f, "kind", kind);
    io::write_numbers(f, io::block_numbers(spec.block));
    io::write_settings(f, suite_settings(spec, settings));
    for (const io::NamedText& t : root_texts(spec)) h5::write_attribute(f, t.name, t.value);
    h5::write_attribute(f, "intensity_units", intensity_units(spec.measure));
    h5::write_attribute(f, "intensity_long_name", intensity_long_name(spec.measure));
    // A hazard curve of SA(T) must match T (rocksweep risk, docs/risk.md).
    if (spec.measure == IntensityMeasure::sa_g) h5::write_attribute(f, "intensity_period_s", spec.sa.period_s);
    h5::write_attribute(f, "suite_file", spec.suite_path);
    // Synthetic motions are not stored: what makes them is (docs/synthetic.md).
    if (spec.motions) h5::write_attribute(f, "synthetic_motions", spec.motions->describe());
    h5::write_attribute(f, "rocksweep_version", prov.version);
    // `complete`: every cell done and the products written (a streaming file, even with every
    // cell done, has none yet: docs/streaming.md).
    h5::write_attribute(f, "n_cells", static_cast<std::int64_t>(spec.cell_count()));
    h5::write_attribute(f, "n_done", static_cast<std::int64_t>(n_done));
    h5::write_attribute(f, "complete", std::int64_t{finished && n_done == spec.cell_count() ? 1 : 0});
    write_records(f, spec);
    write_floors(f, spec);

    const std::vector<GridAxis> axes = result_axes(spec);
    const h5::Group suite = f.create_group("suite");
    for (std::size_t s = 0; s < spec.scenarios.size(); ++s) {
        const h5::Group g = suite.create_group(spec.scenarios[s].name);
        io::write_scenario_attributes(g, s, spec.scenarios[s]);
        h5::write_attribute(g, "floor", spec.floors[spec.floor_of(s)].name);
        const GridGroup grid(g, axes);
        io::write_result_columns(grid, chunk, spec.sensitivity.on);
    }
    const h5::Group g = io::write_provenance(f, prov, settings);
    // What saving cost the run (a streaming file's are updated in place when it stops).
    h5::write_attribute(g, "checkpoint_s", saves.seconds);
    h5::write_attribute(g, "checkpoints", static_cast<std::int64_t>(saves.checkpoints));
}

namespace {

void read_contents(const std::string& path, const h5::File& f, const SuiteSpec& spec, const IntegratorSettings& settings,
                   SweepResults* r) {
    const io::Mismatch mismatch = [&](const std::string& what) {
        throw InputError("suite file", path, "a file written for the same suite sweep (" + what + ")");
    };
    io::compare_numbers(f, io::block_numbers(spec.block), mismatch);
    io::compare_settings(path, f, suite_settings(spec, settings));
    io::compare_texts(f, root_texts(spec), mismatch);
    const h5::Group records = f.open_group("records");
    const GridAxis record_axes[] = {record_axis(spec), alpha_axis(spec), intensity_axis(spec)};
    if (const std::string diff = axes_difference(records, record_axes); !diff.empty()) mismatch("/records: " + diff);
    // A record file edited since the run would give other results under the same name; a made
    // motion other than the file's comes from other synthetic options.
    const std::vector<double> pga = h5::read_1d<double>(records, "pga_g");
    for (std::size_t i = 0; i < spec.records.size(); ++i)
        if (pga.at(i) != spec.records[i].measures.pga_g)
            mismatch((spec.records[i].motion >= 0 ? "synthetic motion " : "record ") + spec.records[i].entry.name +
                     " has PGA " + format_number(pga[i]) + " g in the file, " + format_number(spec.records[i].measures.pga_g) +
                     (spec.records[i].motion >= 0 ? " g now: the synthetic options (--seed, the model, the records fitted) differ"
                                                  : " g now: its file changed"));

    const h5::Group suite = f.open_group("suite");
    std::vector<std::string> expected;
    for (const Scenario& s : spec.scenarios) expected.push_back(s.name);
    std::sort(expected.begin(), expected.end());
    if (suite.children() != expected) mismatch("its scenarios differ from the config's");
    const std::vector<GridAxis> axes = suite_detail::result_axes(spec);
    const std::vector<hsize_t> dims = grid_dims(axes);
    if (r) r->resize(spec.cell_count());
    for (std::size_t s = 0; s < spec.scenarios.size(); ++s) {
        const h5::Group g = suite.open_group(spec.scenarios[s].name);
        io::compare_texts(g, io::scenario_texts(spec.scenarios[s]), mismatch);
        const io::NamedText floor[] = {{"floor", spec.floors[spec.floor_of(s)].name}};
        io::compare_texts(g, floor, mismatch);
        io::compare_numbers(g, io::scenario_numbers(spec.scenarios[s]), mismatch);
        if (const std::string diff = axes_difference(g, axes); !diff.empty()) mismatch(g.name() + ": " + diff);
        if (r) {
            io::read_result_columns(g, axes, *r, s * spec.cells_per_scenario(), mismatch);
            if (spec.sensitivity.on) io::read_sensitive_column(g, axes, *r, s * spec.cells_per_scenario(), mismatch);
            continue;
        }
        SweepResults none;  // the shapes alone, without reading the results
        io::for_each_result_column(none, spec.sensitivity.on, [&](const char* name, auto&) {
            if (const std::vector<hsize_t> in_file = g.open_dataset(name).dims(); in_file != dims)
                mismatch(g.name() + "/" + name + " is " + dims_text(in_file) + ", the config needs " + dims_text(dims));
        });
    }
}

}  // namespace

void check_record_names(const SuiteSpec& spec) {
    const std::set<std::string> taken = records_datasets();
    for (const SuiteMember& m : spec.records) {
        const std::string& name = m.entry.name;
        std::string why;
        // "." and ".." are not names of an HDF5 link: "/records/." is /records itself.
        if (name.find_first_not_of('.') == std::string::npos) why = "a name of dots only is no HDF5 group name";
        else if (taken.count(name)) why = "it is the name of a dataset of /records beside the records' groups";
        if (!why.empty())
            throw InputError("suite", spec.suite_path + " line " + std::to_string(m.entry.line),
                             "record name '" + name + "' cannot name its group /records/" + name + " of the output (" + why +
                                 "); reserved: " + reserved_record_names());
    }
}

h5::File suite_detail::open_checked(const std::string& path, const SuiteSpec& spec, const IntegratorSettings& settings,
                                   SweepResults* r) {
    auto not_suite = [&](const std::string& what) {
        return InputError("output", path, "a rocksweep suite file to resume; it is " + what);
    };
    std::optional<h5::File> opened;
    try {
        opened.emplace(h5::File::open_read_only(path));
    } catch (const Hdf5Error&) {
        throw not_suite("not an HDF5 file");
    }
    const h5::File& f = *opened;
    if (!f.has_attribute("kind") || h5::read_string_attribute(f, "kind") != kind || !f.exists("suite"))
        throw not_suite("an HDF5 file that rocksweep suite did not write");
    if (const std::int64_t v = h5::read_int64_attribute(f, "format_version"); v != format_version)
        throw not_suite("of format version " + std::to_string(v) + ", which this rocksweep does not continue");
    try {
        read_contents(path, f, spec, settings, r);
    } catch (const Hdf5Error& e) {
        throw InputError("suite file", path, std::string("a rocksweep suite file (") + e.what() + ")");
    }
    return std::move(*opened);
}

SweepResults read_suite_results(const std::string& path, const SuiteSpec& spec, const IntegratorSettings& settings) {
    SweepResults r;
    suite_detail::open_checked(path, spec, settings, &r).close();
    return r;
}

void check_suite_file(const std::string& path, const SuiteSpec& spec, const IntegratorSettings& settings) {
    suite_detail::open_checked(path, spec, settings, nullptr).close();
}

}  // namespace rocksweep
