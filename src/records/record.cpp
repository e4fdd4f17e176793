#include "rocksweep/records/record.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "record_text.hpp"
#include "rocksweep/core/errors.hpp"

namespace rocksweep {

namespace {

using detail::Samples;

std::string at(const std::string& path, int line) { return path + " line " + std::to_string(line); }

// A grid time may be off by what the file's rounding of its time column leaves (the Mexico City
// file prints 163.39999 for 163.42 - 0.02): 1 % of dt is far above that and far below a missing
// or doubled sample.
constexpr double time_tolerance = 0.01;

struct TimeGrid {
    double dt_s = 0.0;
    bool starts_at_dt = false;
};

// dt from the first and last times (the least rounding); every step must match the first one
// and every time its place on the grid, so that an error names the line where the grid breaks.
TimeGrid check_times(const std::string& field, const std::string& path, const Samples& t) {
    const std::size_t n = t.values.size();
    if (n < 2) throw InputError(field, path, "at least two samples (found " + std::to_string(n) + ")");
    const double first_step = t.values[1] - t.values[0];
    for (std::size_t i = 1; i < n; ++i) {
        const double ti = t.values[i], prev = t.values[i - 1];
        if (!(ti > prev))
            throw InputError(field, at(path, t.lines[i]),
                             "time " + format_number(ti) + " s is not after the previous " + format_number(prev) +
                                 " s (times must increase evenly)");
        if (std::abs(ti - prev - first_step) > time_tolerance * first_step)
            throw InputError(field, at(path, t.lines[i]),
                             "time " + format_number(ti) + " s is " + format_number(ti - prev) + " s after the previous " +
                                 format_number(prev) + " s where the first step is " + format_number(first_step) +
                                 " s (times must increase evenly)");
    }
    TimeGrid g;
    g.dt_s = (t.values[n - 1] - t.values[0]) / static_cast<double>(n - 1);
    for (std::size_t i = 0; i < n; ++i)
        if (std::abs(t.values[i] - t.values[0] - static_cast<double>(i) * g.dt_s) > time_tolerance * g.dt_s)
            throw InputError(field, at(path, t.lines[i]),
                             "time " + format_number(t.values[i]) + " s has drifted off the grid of step " +
                                 format_number(g.dt_s) + " s (times must increase evenly)");
    // A file may start at its first step rather than at 0 (its sample 0 at t = 0 omitted): the
    // ground is at rest before the first sample, so a zero is put at t = 0. Any other start would
    // mean missing motion, which we do not invent.
    const double t0 = t.values[0];
    g.starts_at_dt = std::abs(t0 - g.dt_s) <= time_tolerance * g.dt_s;
    if (!g.starts_at_dt && !(std::abs(t0) <= time_tolerance * g.dt_s))
        throw InputError(field, at(path, t.lines[0]),
                         "the first time " + format_number(t0) + " s is neither 0 nor the step " + format_number(g.dt_s) +
                             " s (a record starts with the ground at rest)");
    return g;
}

void check_dt(const std::string& field, const std::string& where, double dt_s) {
    if (!(dt_s >= record_dt_min_s && dt_s <= record_dt_max_s))
        throw InputError(field, where,
                         "a sampling interval of " + format_number(dt_s) + " s is outside " + format_number(record_dt_min_s) +
                             " s <= dt <= " + format_number(record_dt_max_s) +
                             " s (strong-motion records are sampled at 1 Hz to 100 kHz)");
}

// Samples in the file's unit -> fraction of standard gravity, refusing what no ground does.
std::vector<double> to_g(const std::string& field, const std::string& path, const Samples& s, double factor,
                         const std::string& units, double scale) {
    std::vector<double> out(s.values.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = s.values[i] * factor;
        if (!(std::abs(out[i]) <= record_accel_max_g))
            throw InputError(field, at(path, s.lines[i]),
                             "sample " + format_number(s.values[i]) + " " + units + " (scale " + format_number(scale) + ") is " +
                                 format_number(out[i]) + " g, beyond the physical bound |a| <= " +
                                 format_number(record_accel_max_g) + " g (wrong unit or column?)");
    }
    return out;
}

// The format's own column of acceleration when none is chosen; the time column cannot be one.
int acceleration_column(const std::string& field, RecordFormat f, int column) {
    const int chosen = column != 0 ? column : (f == RecordFormat::time_accel ? 2 : 1);
    if (f == RecordFormat::time_accel && chosen < 2)
        throw InputError(field, std::to_string(column), "2 or more: column 1 of a time_accel file is the time");
    return chosen;
}

// One component as read: its samples in the file's unit and its time grid.
struct Component {
    Samples accel;
    TimeGrid grid;
};

struct Components {
    Component horizontal;
    std::optional<Component> vertical;
};

const std::string vertical_field = "record-vertical";

std::vector<Component> read_text(const std::string& field, const std::string& path, const RecordSource& s,
                                 const std::vector<detail::Wanted>& columns) {
    const bool timed = s.format == RecordFormat::time_accel;
    std::vector<detail::Wanted> wanted = columns;
    if (timed) wanted.insert(wanted.begin(), {1, "record-column"});
    std::vector<Samples> read = detail::read_columns(field, path, s.skip_lines, wanted);
    TimeGrid grid;
    if (timed) {
        grid = check_times(field, path, read.front());
        if (s.dt_s != 0.0 && std::abs(s.dt_s - grid.dt_s) > time_tolerance * grid.dt_s)
            throw InputError("record-dt", format_number(s.dt_s),
                             "the step of " + path + "'s time column, " + format_number(grid.dt_s) + " s (or not given)");
        read.erase(read.begin());
    } else {
        grid.dt_s = s.dt_s;
        if (read.front().values.size() < 2)
            throw InputError(field, path, "at least two samples (found " + std::to_string(read.front().values.size()) + ")");
    }
    std::vector<Component> out;
    for (Samples& a : read) out.push_back({std::move(a), grid});
    return out;
}

// `units`: the unit expected (given by the user, or the horizontal's for the vertical), "" if
// none yet; set to the file's.
Component read_at2_component(const std::string& field, const std::string& path, const RecordSource& s, std::string& units) {
    detail::At2 a = detail::read_at2(field, path);
    if (!units.empty() && units != a.units) {
        if (field == vertical_field)
            throw InputError(field, path, "an .AT2 in " + units + " like the horizontal component (it states " + a.units + ")");
        throw InputError("record-units", units, "the unit " + path + " states, " + a.units + " (or none: an .AT2 gives its own)");
    }
    units = a.units;
    if (s.dt_s != 0.0 && s.dt_s != a.dt_s)
        throw InputError("record-dt", format_number(s.dt_s),
                         "the DT " + path + " states, " + format_number(a.dt_s) + " s (or none)");
    check_dt(field, at(path, 4), a.dt_s);
    return {std::move(a.samples), {a.dt_s, false}};
}

// An .AT2 and, optionally, a second .AT2 for the vertical; the unit comes from the header.
Components read_at2_components(const RecordSource& s, Record& r) {
    if (s.column != 0)
        throw InputError("record-column", std::to_string(s.column), "none for an .AT2 file (it has one component)");
    Components c{read_at2_component("record", s.path, s, r.units), std::nullopt};
    if (s.vertical) {
        if (s.vertical->path.empty() || s.vertical->column != 0)
            throw InputError(vertical_field, s.vertical->path.empty() ? "(a column)" : s.vertical->path,
                             "a second .AT2 file, without a column");
        r.vertical_path = s.vertical->path;
        c.vertical = read_at2_component(vertical_field, s.vertical->path, s, r.units);
    }
    return c;
}

// Columns of a text file; the vertical from another column of it or from a second file.
Components read_text_components(const RecordSource& s, Record& r) {
    units_to_g("record-units", s.units);  // refuse a missing unit before reading anything
    if (s.format == RecordFormat::accel_only) {
        if (s.dt_s == 0.0)
            throw InputError("record-dt", "(missing)",
                             "the sampling interval [s] of " + s.path + " (an accel_only file has no time column)");
        check_dt("record-dt", format_number(s.dt_s), s.dt_s);
    }
    r.column = acceleration_column("record-column", s.format, s.column);
    const bool same_file = s.vertical && s.vertical->path.empty();
    if (same_file && s.vertical->column == 0)
        throw InputError("record-vertical-column", "(missing)", "the column of " + s.path + " holding the vertical component");
    if (s.vertical) r.vertical_column = acceleration_column("record-vertical-column", s.format, s.vertical->column);
    if (same_file && r.vertical_column == r.column)
        throw InputError("record-vertical-column", std::to_string(r.vertical_column),
                         "a column other than the horizontal component's (" + std::to_string(r.column) + ") of " + s.path);
    std::vector<detail::Wanted> columns{{r.column, "record-column"}};
    const detail::Wanted vertical{r.vertical_column, "record-vertical-column"};
    if (same_file) columns.push_back(vertical);
    std::vector<Component> read = read_text("record", s.path, s, columns);
    if (s.format == RecordFormat::time_accel) check_dt("record", s.path, read[0].grid.dt_s);
    Components c{std::move(read[0]), std::nullopt};
    if (same_file)
        c.vertical = std::move(read[1]);
    else if (s.vertical)
        c.vertical = std::move(read_text(vertical_field, s.vertical->path, s, {vertical})[0]);
    if (s.vertical) r.vertical_path = same_file ? s.path : s.vertical->path;
    return c;
}

}  // namespace

RecordFormat parse_record_format(const std::string& field, const std::string& text) {
    if (text == "time_accel") return RecordFormat::time_accel;
    if (text == "accel_only") return RecordFormat::accel_only;
    if (text == "at2") return RecordFormat::at2;
    throw InputError(field, text, record_formats_allowed);
}

std::string to_string(RecordFormat f) {
    switch (f) {
        case RecordFormat::time_accel:
            return "time_accel";
        case RecordFormat::accel_only:
            return "accel_only";
        case RecordFormat::at2:
            return "at2";
    }
    return "?";
}

double units_to_g(const std::string& field, const std::string& units) {
    if (units == "g") return 1.0;
    if (units == "m/s^2") return 1.0 / standard_gravity;
    if (units == "cm/s^2") return 0.01 / standard_gravity;
    throw InputError(field, units.empty() ? "(missing)" : units,
                     std::string(record_units_allowed) + " (the unit of the record's samples; never guessed)");
}

Record read_record(const RecordSource& s) {
    if (!std::isfinite(s.scale) || s.scale == 0.0)
        throw InputError("record-scale", format_number(s.scale), "a finite, non-zero factor");
    if (s.skip_lines < 0) throw InputError("record-skip-lines", std::to_string(s.skip_lines), "0 or more");
    Record r;
    r.path = s.path;
    r.format = s.format;
    r.units = s.units;
    r.scale = s.scale;
    const Components c = s.format == RecordFormat::at2 ? read_at2_components(s, r) : read_text_components(s, r);
    const Component& h = c.horizontal;
    const double factor = units_to_g("record-units", r.units) * s.scale;
    r.dt_s = h.grid.dt_s;
    r.npts = h.accel.values.size();
    r.zero_prepended = h.grid.starts_at_dt;
    r.ax_g = to_g("record", s.path, h.accel, factor, r.units, s.scale);
    if (c.vertical) {
        const TimeGrid& vg = c.vertical->grid;
        if (std::abs(vg.dt_s - h.grid.dt_s) > time_tolerance * h.grid.dt_s || vg.starts_at_dt != h.grid.starts_at_dt)
            throw InputError(vertical_field, r.vertical_path,
                             "a component on the horizontal's grid (dt " + format_number(h.grid.dt_s) +
                                 " s from t = " + format_number(h.grid.starts_at_dt ? h.grid.dt_s : 0.0) + " s)");
        r.ay_g = to_g(vertical_field, r.vertical_path, c.vertical->accel, factor, r.units, s.scale);
    }
    if (r.zero_prepended) {
        r.ax_g.insert(r.ax_g.begin(), 0.0);
        if (c.vertical) r.ay_g.insert(r.ay_g.begin(), 0.0);
    }
    // Components of one record may end a few samples apart: the ground is at rest after either ends.
    if (c.vertical) {
        const std::size_t n = std::max(r.ax_g.size(), r.ay_g.size());
        r.ax_g.resize(n, 0.0);
        r.ay_g.resize(n, 0.0);
    }
    return r;
}

double pga_as_read_g(const Record& r) {
    double peak = 0.0;
    for (double a : r.ax_g) peak = std::max(peak, std::abs(a));
    return peak / std::abs(r.scale);
}

bool plausible_pga(const Record& r) {
    const double pga = pga_as_read_g(r);
    return pga >= record_pga_min_g && pga <= record_pga_max_g;
}

std::string record_facts(const Record& r) {
    const double pga = pga_as_read_g(r);
    return "PGA " + format_short(pga, 3) + " g (" + format_short(pga * standard_gravity, 3) + " m/s^2) as read in " + r.units +
           ", dt " + format_short(r.dt_s, 4) + " s, " + format_short(r.duration_s(), 4) + " s, " + std::to_string(r.npts) +
           " samples";
}

std::string implausible_pga(const Record& r, const std::string& accept) {
    const double pga = pga_as_read_g(r), in_unit = pga / units_to_g("record-units", r.units);
    return "its peak ground acceleration as read in " + r.units + ", " + format_short(in_unit, 3) + " " + r.units + ", is " +
           format_short(pga, 3) + " g (" + format_short(pga * standard_gravity, 3) + " m/s^2), outside the " +
           format_short(record_pga_min_g) + " to " + format_short(record_pga_max_g) +
           " g of a strong-motion record (docs/records.md): check its unit, or " + accept;
}

namespace {
// Samples in standard g -> fractions of the block's g.
std::shared_ptr<const std::vector<double>> in_block_g(const std::vector<double>& a_g, double gravity) {
    std::vector<double> a(a_g);
    for (double& x : a) x *= standard_gravity / gravity;
    return std::make_shared<const std::vector<double>>(std::move(a));
}
}  // namespace

Pulse to_pulse(const Record& r, double gravity) {
    Pulse p;
    p.kind = PulseKind::record;
    p.record = in_block_g(r.ax_g, gravity);
    p.record_dt_s = r.dt_s;
    if (!r.ay_g.empty()) {
        p.record_y = in_block_g(r.ay_g, gravity);
        // g + a_v <= 0: the ground falls away from the block, which no longer rests on it.
        for (std::size_t i = 0; i < p.record_y->size(); ++i)
            if (!((*p.record_y)[i] > -1.0))
                throw InputError("record-vertical", r.vertical_path,
                                 "a vertical acceleration above -g at every sample (sample " + std::to_string(i) + ", t = " +
                                     format_number(static_cast<double>(i) * r.dt_s) + " s, is " +
                                     format_number((*p.record_y)[i]) + " g: free fall, the block would leave the ground)");
    }
    return p;
}

Pulse read_record(const std::string& path, const std::string& units, double scale, double gravity) {
    RecordSource s;
    s.path = path;
    s.units = units;
    s.scale = scale;
    return to_pulse(read_record(s), gravity);
}

}  // namespace rocksweep
