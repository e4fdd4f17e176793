#pragma once
/// Result arrays over a list of axes, laid out in one HDF5 group so that netCDF-4 readers
/// (ncdump, xarray, Octave's and MATLAB's ncread) find their dimensions: netCDF looks for a
/// variable's dimensions among the dimension scales of its own group and its ancestors, so each
/// axis is a 1-D dimension scale inside the group, attached to every array of the group.
///
/// The list of axes alone drives the layout: a grid of N axes needs no new code here.
/// Only rocksweep_io includes this header.
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "rocksweep/io/hdf5.hpp"

namespace rocksweep {

/// One axis of a result grid. Arrays list their axes in C order: the first varies slowest.
struct GridAxis {
    std::string name;       ///< dataset and netCDF dimension name, e.g. "omega_ratio"
    std::string units;      ///< CF units ("1" for a ratio)
    std::string long_name;  ///< the quantity in words
    std::vector<double> values;
    std::string flag_meanings = "";  ///< a categorical axis: its codes' names (CF flag_values / flag_meanings)
};

/// The axes as written into one group: their scales, ready to be attached. Keeps references
/// to the group and the axes it was built from: both must outlive it.
class GridGroup {
public:
    /// Writes each axis into `group` as a float64 dimension scale named after it, with `units`
    /// and `long_name` attributes. Throws Hdf5Error.
    GridGroup(const h5::Group& group, std::span<const GridAxis> axes);

    /// Cells in one array: the product of the axis sizes.
    std::size_t cell_count() const;

    /// Writes `values` (C order over the axes) as dataset `name`, every dimension attached to
    /// its axis, and a `dimensions` attribute naming the axes ("amplitude_ratio, omega_ratio").
    /// Throws std::invalid_argument if values.size() != cell_count(), Hdf5Error.
    template <h5::Element T>
    h5::Dataset write(std::string_view name, std::span<const T> values) const;

    /// The same over some of the axes only, named in C order (e.g. {"record", "radius_m"} of a
    /// group over record, radius_m and intensity): a summary beside the full grid.
    /// Throws std::invalid_argument for a name that is not an axis of the group.
    template <h5::Element T>
    h5::Dataset write_on(std::string_view name, std::span<const T> values,
                         std::initializer_list<std::string_view> axis_names) const;

    /// An empty dataset over every axis, attached and described like write()'s, for a writer to
    /// fill: without `chunk`, contiguous and allocated but never filled (h5::create_fixed_dataset,
    /// filled in place); with it, chunked so, shuffled and deflated (h5::create_chunked_dataset,
    /// filled by h5::write_rows). Throws Hdf5Error.
    template <h5::Element T>
    h5::Dataset create(std::string_view name, std::span<const hsize_t> chunk = {}) const;

private:
    void attach(const h5::Dataset& ds, const std::vector<std::size_t>& which) const;
    template <h5::Element T>
    h5::Dataset write_axes(std::string_view name, std::span<const T> values, const std::vector<std::size_t>& which) const;

    const h5::Group& group_;
    std::span<const GridAxis> axes_;
    std::vector<h5::Dataset> scales_;
};

/// The dataset shape of a grid over `axes`.
std::vector<hsize_t> grid_dims(std::span<const GridAxis> axes);

/// "" if `group` holds every axis of `axes` with exactly the same values (NaN equal to NaN);
/// otherwise the first difference in words, e.g. "omega_ratio has 5 points in the file, 4 in
/// the config". Throws Hdf5Error if an axis is missing or not 1-D float64.
std::string axes_difference(const h5::Group& group, std::span<const GridAxis> axes);

/// Dims as text for messages: "30 x 40".
std::string dims_text(std::span<const hsize_t> dims);

}  // namespace rocksweep
