// Reading a spectra file back: every check that makes it "the same sweep", then its columns.
#include <algorithm>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/grid_layout.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/results_checksum.hpp"
#include "rocksweep/io/spectra_file.hpp"
#include "spectra_layout.hpp"

namespace rocksweep {

using namespace spectra_detail;

namespace {

// ---------------------------------------------------------------------------------------
// Reading

[[noreturn]] void mismatch(const std::string& path, const std::string& what) {
    throw InputError("spectra file", path, "a file written for the same sweep (" + what + ")");
}

void compare_number(const std::string& path, const h5::Object& obj, const NamedNumber& n) {
    const double in_file = h5::read_double_attribute(obj, n.name);
    if (!same_number(in_file, n.value))
        mismatch(path, obj.name() + " attribute " + n.name + " is " + format_number(in_file) +
                           " in the file, " + format_number(n.value) + " in the config");
}

void compare_text(const std::string& path, const h5::Object& obj, const char* name,
                  const std::string& expected) {
    // A file from before --adaptive-law has no adaptive_law: it was computed with the paper's law.
    const bool before_law = std::string_view(name) == "adaptive_law" && !obj.has_attribute(name);
    const std::string in_file = before_law ? "paper" : h5::read_string_attribute(obj, name);
    if (in_file != expected)
        mismatch(path, obj.name() + " attribute " + name + " is '" + in_file + "' in the file, '" +
                           expected + "' in the config");
}

// Checks the shape of a result dataset and, given a column, reads it into its scenario's block.
template <h5::Element T>
void read_grid(const std::string& path, const h5::Group& g, const char* name, std::vector<T>* column,
               std::size_t scenario, std::span<const GridAxis> axes) {
    const std::vector<hsize_t> expected = grid_dims(axes);
    if (!column) {
        if (const std::vector<hsize_t> dims = g.open_dataset(name).dims(); dims != expected)
            mismatch(path, g.name() + "/" + name + " is " + dims_text(dims) + ", the config needs " + dims_text(expected));
        return;
    }
    const h5::ArrayN<T> a = h5::read_array<T>(g, name);
    if (a.dims != expected)
        mismatch(path, g.name() + "/" + name + " is " + dims_text(a.dims) + ", the config needs " +
                           dims_text(expected));
    std::copy(a.values.begin(), a.values.end(),
              column->begin() + static_cast<std::ptrdiff_t>(scenario * a.values.size()));
}

void read_contents(const std::string& path, const h5::File& f, const SweepSpec& spec,
                   const IntegratorSettings& settings, SweepResults* r) {
    for (const NamedNumber& n : root_numbers(spec)) compare_number(path, f, n);
    io::compare_settings(path, f, result_settings(spec, settings));
    const std::string spectrum = spectrum_axis_names(spec);
    if (const std::string in_file = f.has_attribute("spectrum_axes") ? h5::read_string_attribute(f, "spectrum_axes")
                                                                      : "amplitude_ratio, omega_ratio";
        in_file != spectrum)
        throw InputError("spectrum axes", spectrum,
                         in_file + ", as " + path + " was computed with (a file continues only on the grid it was started on)");
    const std::string names = parameter_axis_names(spec);
    if (const std::string in_file = f.has_attribute("parameter_axes") ? h5::read_string_attribute(f, "parameter_axes") : "";
        in_file != names)
        throw InputError("axis", names.empty() ? "(none)" : names,
                         "parameter axes " + (in_file.empty() ? std::string("none") : in_file) + ", as " + path +
                             " was computed with (a file continues only on the grid it was started on)");

    const h5::Group spectra = f.open_group("spectra");
    std::vector<std::string> in_file = spectra.children();
    std::vector<std::string> expected;
    for (const Scenario& s : spec.scenarios) expected.push_back(s.name);
    std::sort(expected.begin(), expected.end());
    if (in_file != expected) {
        auto join = [](const std::vector<std::string>& v) {
            std::string s;
            for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
            return s.empty() ? std::string("none") : s;
        };
        mismatch(path, "scenarios in the file: " + join(in_file) + "; in the config: " + join(expected));
    }

    const std::vector<GridAxis> axes = grid_axes(spec);
    if (r) r->resize(spec.cell_count());
    auto col = [r](auto SweepResults::*m) { return r ? &(r->*m) : nullptr; };
    for (std::size_t i = 0; i < spec.scenarios.size(); ++i) {
        const Scenario& s = spec.scenarios[i];
        const h5::Group g = spectra.open_group(s.name);
        for (const NamedText& t : scenario_texts(s)) compare_text(path, g, t.name, t.value);
        for (const NamedNumber& n : scenario_numbers(s)) compare_number(path, g, n);
        if (const std::string diff = axes_difference(g, axes); !diff.empty()) mismatch(path, g.name() + ": " + diff);
        read_grid(path, g, "outcome", col(&SweepResults::outcome), i, axes);
        read_grid(path, g, "max_rotation", col(&SweepResults::max_rotation), i, axes);
        read_grid(path, g, "impacts", col(&SweepResults::impacts), i, axes);
        read_grid(path, g, "t_overturn", col(&SweepResults::t_overturn), i, axes);
        read_grid(path, g, "peak_force_ratio", col(&SweepResults::peak_force_ratio), i, axes);
        read_grid(path, g, "broken", col(&SweepResults::broken), i, axes);
        read_grid(path, g, "impacts_total", col(&SweepResults::impacts_total), i, axes);
        read_grid(path, g, "mu_required", col(&SweepResults::mu_required), i, axes);
        read_grid(path, g, "pivot_uplift", col(&SweepResults::pivot_uplift), i, axes);
        read_grid(path, g, "done", col(&SweepResults::done), i, axes);
    }
}

}  // namespace

SweepResults read_spectra_results(const std::string& path, const SweepSpec& spec,
                                  const IntegratorSettings& settings) {
    SweepResults r;
    spectra_detail::open_checked(path, spec, settings, &r);
    return r;
}

std::vector<std::string> verify_results_checksums(const std::string& path, const SweepSpec& spec, const SweepResults& r) {
    std::vector<std::string> unverified;
    const h5::File f = h5::File::open_read_only(path);
    const h5::Group spectra = f.open_group("spectra");
    const std::size_t per = spec.cells_per_scenario();
    for (std::size_t s = 0; s < spec.scenarios.size(); ++s) {
        const std::string& name = spec.scenarios[s].name;
        const h5::Group g = spectra.open_group(name);
        const std::int64_t stored =
            g.has_attribute(results_checksum_attribute) ? h5::read_int64_attribute(g, results_checksum_attribute) : 0;
        if (stored == 0) {
            unverified.push_back(name);
            continue;
        }
        if (results_checksum(r, s * per, per) != stored)
            throw InputError("part file", path,
                             "a part whose results match the checksum it stored when its run finished (those of scenario " +
                                 name + " do not: they were changed after they were written)");
    }
    return unverified;
}

void check_spectra_file(const std::string& path, const SweepSpec& spec, const IntegratorSettings& settings) {
    spectra_detail::open_checked(path, spec, settings, nullptr).close();
}

std::string read_provenance_config(const std::string& path) {
    try {
        const h5::File f = h5::File::open_read_only(path);
        if (!f.exists("provenance")) return "";
        const h5::Group g = f.open_group("provenance");
        return g.has_attribute("config") ? h5::read_string_attribute(g, "config") : "";
    } catch (const Hdf5Error&) {
        return "";
    }
}

SweepSpec with_recorded_refinement(const std::string& path, SweepSpec spec) {
    try {
        const h5::File f = h5::File::open_read_only(path);
        if (!f.has_attribute("refine_stride") || !f.has_attribute("refine_axes")) return spec;
        spec.refine_stride = static_cast<std::size_t>(h5::read_double_attribute(f, "refine_stride"));
        spec.refine_axes = h5::read_string_attribute(f, "refine_axes");
    } catch (const Hdf5Error&) {
    }
    return spec;
}

h5::File spectra_detail::open_checked(const std::string& path, const SweepSpec& spec,
                                      const IntegratorSettings& settings, SweepResults* r) {
    // What the file is, in the user's words, before any HDF5 detail.
    auto not_spectra = [&](const std::string& what) {
        return InputError("output", path, "a rocksweep spectra file; it is " + what);
    };
    std::optional<h5::File> opened;  // the file, or a message about what it is
    try {
        opened.emplace(h5::File::open_read_only(path));
    } catch (const Hdf5Error&) {
        throw not_spectra("damaged or not an HDF5 file at all");
    }
    const h5::File& f = *opened;
    if (f.exists("theta") && f.exists("t")) throw not_spectra("a history written by rocksweep simulate");
    if (!f.has_attribute("format_version") || !f.exists("spectra"))
        throw not_spectra("an HDF5 file that rocksweep sweep did not write");
    if (const std::int64_t v = h5::read_int64_attribute(f, "format_version"); v != format_version)
        throw InputError("output", path,
                         "a spectra file of format version " + std::to_string(format_version) +
                             " to resume; it is of version " + std::to_string(v) +
                             (v < format_version ? " (an older layout, axes in /axes)" : " (a newer rocksweep's)") +
                             ", which this rocksweep does not continue: sweep again with --overwrite");
    try {
        read_contents(path, f, spec, settings, r);
        return std::move(*opened);
    } catch (const Hdf5Error& e) {
        // A missing attribute or dataset, or one HDF5 cannot read: not a file we wrote, or
        // one damaged since (HDF5's own text often says nothing more).
        throw InputError("spectra file", path,
                         std::string("a rocksweep spectra file; it is damaged or not one (") + e.what() + ")");
    }
}

}  // namespace rocksweep
