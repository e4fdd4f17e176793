#include "rocksweep/io/grid_layout.hpp"

#include <cmath>
#include <stdexcept>

#include "rocksweep/core/errors.hpp"

namespace rocksweep {

std::vector<hsize_t> grid_dims(std::span<const GridAxis> axes) {
    std::vector<hsize_t> dims;
    for (const GridAxis& a : axes) dims.push_back(a.values.size());
    return dims;
}

std::string dims_text(std::span<const hsize_t> dims) {
    std::string s;
    for (hsize_t d : dims) s += (s.empty() ? "" : " x ") + std::to_string(d);
    return s.empty() ? std::string("a scalar") : s;
}

GridGroup::GridGroup(const h5::Group& group, std::span<const GridAxis> axes) : group_(group), axes_(axes) {
    for (const GridAxis& a : axes) {
        h5::Dataset ds = h5::write_1d<double>(group, a.name, a.values);
        h5::write_attribute(ds, "units", a.units);
        h5::write_attribute(ds, "long_name", a.long_name);
        if (!a.flag_meanings.empty()) {
            h5::write_attribute(ds, "flag_values", std::span<const double>(a.values));
            h5::write_attribute(ds, "flag_meanings", a.flag_meanings);
        }
        h5::make_scale(ds, a.name);
        scales_.push_back(std::move(ds));
    }
}

std::size_t GridGroup::cell_count() const {
    std::size_t n = 1;
    for (const GridAxis& a : axes_) n *= a.values.size();
    return n;
}

template <h5::Element T>
h5::Dataset GridGroup::write_axes(std::string_view name, std::span<const T> values,
                                  const std::vector<std::size_t>& which) const {
    std::vector<hsize_t> dims;
    for (std::size_t a : which) dims.push_back(axes_[a].values.size());
    h5::Dataset ds = h5::write_dataset<T>(group_, name, values, dims);
    attach(ds, which);
    return ds;
}

void GridGroup::attach(const h5::Dataset& ds, const std::vector<std::size_t>& which) const {
    std::string names;
    for (unsigned d = 0; d < which.size(); ++d) {
        h5::attach_scale(ds, scales_[which[d]], d);
        names += (names.empty() ? "" : ", ") + axes_[which[d]].name;
    }
    // The order in words, for readers that show neither scales nor netCDF dimensions.
    h5::write_attribute(ds, "dimensions", names);
}

template <h5::Element T>
h5::Dataset GridGroup::create(std::string_view name, std::span<const hsize_t> chunk) const {
    std::vector<std::size_t> all(axes_.size());
    for (std::size_t a = 0; a < all.size(); ++a) all[a] = a;
    const std::vector<hsize_t> dims = grid_dims(axes_);
    h5::Dataset ds = chunk.empty() ? h5::create_fixed_dataset<T>(group_, name, dims)
                                   : h5::create_chunked_dataset<T>(group_, name, dims, chunk);
    attach(ds, all);
    return ds;
}

template <h5::Element T>
h5::Dataset GridGroup::write(std::string_view name, std::span<const T> values) const {
    std::vector<std::size_t> all(axes_.size());
    for (std::size_t a = 0; a < all.size(); ++a) all[a] = a;
    return write_axes(name, values, all);
}

template <h5::Element T>
h5::Dataset GridGroup::write_on(std::string_view name, std::span<const T> values,
                                std::initializer_list<std::string_view> axis_names) const {
    std::vector<std::size_t> which;
    for (std::string_view n : axis_names) {
        std::size_t a = 0;
        while (a < axes_.size() && axes_[a].name != n) ++a;
        if (a == axes_.size()) throw std::invalid_argument("GridGroup::write_on: no axis " + std::string(n));
        which.push_back(a);
    }
    return write_axes(name, values, which);
}

#define ROCKSWEEP_GRID_WRITERS(T)                                                                              \
    template h5::Dataset GridGroup::write<T>(std::string_view, std::span<const T>) const;                      \
    template h5::Dataset GridGroup::write_on<T>(std::string_view, std::span<const T>,                          \
                                                std::initializer_list<std::string_view>) const;            \
    template h5::Dataset GridGroup::create<T>(std::string_view, std::span<const hsize_t>) const;
ROCKSWEEP_GRID_WRITERS(double)
ROCKSWEEP_GRID_WRITERS(std::int32_t)
ROCKSWEEP_GRID_WRITERS(std::uint8_t)
#undef ROCKSWEEP_GRID_WRITERS

std::string axes_difference(const h5::Group& group, std::span<const GridAxis> axes) {
    for (const GridAxis& a : axes) {
        const std::vector<double> in_file = h5::read_1d<double>(group, a.name);
        if (in_file.size() != a.values.size())
            return a.name + " has " + std::to_string(in_file.size()) + " points in the file, " +
                   std::to_string(a.values.size()) + " in the config";
        for (std::size_t i = 0; i < in_file.size(); ++i) {
            const double x = in_file[i], y = a.values[i];
            if (x != y && !(std::isnan(x) && std::isnan(y)))
                return a.name + "[" + std::to_string(i) + "] is " + format_number(x) + " in the file, " +
                       format_number(y) + " in the config";
        }
    }
    return "";
}

}  // namespace rocksweep
