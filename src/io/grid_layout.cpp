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
h5::Dataset GridGroup::write(std::string_view name, std::span<const T> values) const {
    const std::vector<hsize_t> dims = grid_dims(axes_);
    h5::Dataset ds = h5::write_dataset<T>(group_, name, values, dims);
    std::string names;
    for (unsigned d = 0; d < scales_.size(); ++d) {
        h5::attach_scale(ds, scales_[d], d);
        names += (names.empty() ? "" : ", ") + axes_[d].name;
    }
    // The order in words, for readers that show neither scales nor netCDF dimensions.
    h5::write_attribute(ds, "dimensions", names);
    return ds;
}

template h5::Dataset GridGroup::write<double>(std::string_view, std::span<const double>) const;
template h5::Dataset GridGroup::write<std::int32_t>(std::string_view, std::span<const std::int32_t>) const;
template h5::Dataset GridGroup::write<std::uint8_t>(std::string_view, std::span<const std::uint8_t>) const;

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
