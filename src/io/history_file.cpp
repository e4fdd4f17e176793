#include "rocksweep/io/history_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <system_error>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/physics/outcome.hpp"

namespace rocksweep {

namespace {

struct Column {
    const char* name;  // dataset name
    const char* units;
    const char* long_name;
    const char* csv_header;  // name with its unit, for the CSV header
    const std::vector<double>* values;
};

// The one list of columns, shared by the HDF5 and the CSV writers; `t` first.
std::vector<Column> columns(const History& h) {
    return {
        {"t", "s", "time", "t_s", &h.t},
        {"theta", "rad", "rotation; theta > 0 and theta < 0 rock on the two base corners", "theta_rad", &h.theta},
        {"theta_dot", "rad/s", "angular velocity", "theta_dot_rad_s", &h.theta_dot},
        {"k_left", "N/m", "working stiffness of the left spring (theta > 0), 0 once broken",
         "k_left_N_m", &h.k_left},
        {"k_right", "N/m", "working stiffness of the right spring (theta < 0), 0 once broken",
         "k_right_N_m", &h.k_right},
        {"ground_acc", "m/s^2", "horizontal ground acceleration", "ground_acc_m_s2", &h.ground_acc},
        {"w_excitation", "J", "cumulative work of the excitation on the block (Eq. 23)",
         "w_excitation_J", &h.w_excitation},
        {"w_anchorage", "J", "cumulative work of the anchorage on the block (Eq. 24)",
         "w_anchorage_J", &h.w_anchorage},
    };
}

void check_lengths(const std::vector<Column>& cols) {
    const std::size_t n = cols.front().values->size();
    for (const Column& c : cols)
        if (c.values->size() != n)
            throw std::invalid_argument(std::string("history column ") + c.name + " has " +
                                        std::to_string(c.values->size()) + " samples, t has " +
                                        std::to_string(n));
}

constexpr const char* work_sign_convention =
    "w_excitation and w_anchorage are cumulative work done on the block (Eq. 23-24, J); the "
    "anchorage work is negative while a spring is being stretched, W_a = -8 b^2 K sin(|theta|/2) "
    "sgn(theta) dtheta.";

// All objects opened here are closed on return, so the caller can close the file.
void write_h5_contents(const h5::File& f, const History& h, const std::vector<Column>& cols,
                       const std::vector<std::pair<std::string, std::string>>& string_attrs,
                       const std::vector<std::pair<std::string, double>>& number_attrs) {
    const CellResult& r = h.result;
    h5::write_attribute(f, "title", "rocksweep time history");
    h5::write_attribute(f, "Conventions", h5::cf_conventions);
    h5::write_attribute(f, "outcome", to_string(r.outcome));
    h5::write_attribute(f, "outcome_code", static_cast<std::int64_t>(r.outcome));
    h5::write_attribute(f, "impacts", r.impacts);
    h5::write_attribute(f, "impacts_total", r.impacts_total);
    h5::write_attribute(f, "t_overturn", r.t_overturn_s);
    h5::write_attribute(f, "max_rotation", r.max_rotation);
    h5::write_attribute(f, "mu_required", r.mu_required);
    h5::write_attribute(f, "pivot_uplift", std::int64_t{r.pivot_uplift});
    h5::write_attribute(f, "peak_force_ratio", r.peak_force_ratio);
    h5::write_attribute(f, "broken", r.broken);
    h5::write_attribute(f, "work_sign_convention", work_sign_convention);
    for (const auto& [name, value] : string_attrs) h5::write_attribute(f, name, value);
    for (const auto& [name, value] : number_attrs) h5::write_attribute(f, name, value);

    h5::Dataset t;
    for (const Column& c : cols) {
        h5::Dataset ds = h5::write_1d<double>(f, c.name, *c.values);
        h5::write_attribute(ds, "units", c.units);
        h5::write_attribute(ds, "long_name", c.long_name);
        if (!t.valid()) {
            h5::make_scale(ds, "t");
            t = std::move(ds);
        } else {
            h5::attach_scale(ds, t, 0);
        }
    }
    // The energy the adaptive law's switches injected (physics.md §4). HDF5 only: the CSV keeps
    // its columns. A History built without it (empty) has none to write.
    if (h.e_switch.size() == h.t.size() && t.valid()) {
        h5::Dataset ds = h5::write_1d<double>(f, "e_switch", h.e_switch);
        h5::write_attribute(ds, "units", "J");
        h5::write_attribute(ds, "long_name",
                            "cumulative energy put into the spring by the adaptive law's K_min -> K_max switches at nonzero elongation");
        h5::attach_scale(ds, t, 0);
        h5::write_attribute(f, "switch_energy", h.switch_energy_j);
    }
}

struct FileCloser {
    void operator()(std::FILE* f) const noexcept { std::fclose(f); }
};

[[noreturn]] void write_failed(const std::string& path, int err) {
    throw std::system_error(err, std::generic_category(), "writing " + path);
}

}  // namespace

void write_history_h5(const std::string& path, const History& h,
                      const std::vector<std::pair<std::string, std::string>>& string_attrs,
                      const std::vector<std::pair<std::string, double>>& number_attrs) {
    const std::vector<Column> cols = columns(h);
    check_lengths(cols);
    h5::publish_h5_atomically(path, [&](const h5::File& f) { write_h5_contents(f, h, cols, string_attrs, number_attrs); });
}

void write_history_csv(const std::string& path, const History& h) {
    const std::vector<Column> cols = columns(h);
    check_lengths(cols);
    h5::publish_atomically(path, [&](const std::string& tmp) {
        std::unique_ptr<std::FILE, FileCloser> out(std::fopen(tmp.c_str(), "w"));
        if (!out)
            throw InputError("output", path,
                             std::string("a writable location (") + std::strerror(errno) + ")");
        std::string line;
        for (const Column& c : cols) {
            if (!line.empty()) line += ',';
            line += c.csv_header;
        }
        line += '\n';
        if (std::fputs(line.c_str(), out.get()) < 0) write_failed(tmp, errno);

        char number[32];
        const std::size_t n = h.t.size();
        for (std::size_t i = 0; i < n; ++i) {
            line.clear();
            for (const Column& c : cols) {
                if (!line.empty()) line += ',';
                // %.17g round-trips every double; spell NaN the same on every libc.
                const double x = (*c.values)[i];
                if (std::isnan(x))
                    line += "nan";
                else {
                    std::snprintf(number, sizeof number, "%.17g", x);
                    line += number;
                }
            }
            line += '\n';
            if (std::fputs(line.c_str(), out.get()) < 0) write_failed(tmp, errno);
        }
        // fclose flushes: a full disk shows up here, not in fputs.
        if (std::fclose(out.release()) != 0) write_failed(tmp, errno);
    });
}

}  // namespace rocksweep
