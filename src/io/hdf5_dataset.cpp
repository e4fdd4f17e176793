// Whole datasets written and read back: the element types and their explicit little-endian file
// types, chunking with shuffle + deflate, and reads that refuse a number of another kind. Apart
// because it is the one piece that moves bulk data (attributes are metadata, hdf5_attribute.cpp;
// datasets written behind HDF5's back are hdf5_inplace.cpp).
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "hdf5_detail.hpp"
#include "rocksweep/io/hdf5.hpp"

namespace rocksweep::h5 {

using detail::fail;
using detail::in_quotes;
using detail::Types;

namespace {

// Reading converts silently in HDF5 (a float read as uint8 would wrap); refuse anything that
// is not the same kind of number so a wrong file fails loudly.
template <Element T>
bool type_matches(hid_t type) {
    const H5T_class_t cls = H5Tget_class(type);
    if constexpr (std::same_as<T, double>) {
        return cls == H5T_FLOAT;
    } else {
        if (cls != H5T_INTEGER) return false;
        const bool is_signed = H5Tget_sign(type) == H5T_SGN_2;
        return H5Tget_size(type) == sizeof(T) && is_signed == std::is_signed_v<T>;
    }
}

// Halves the slowest-varying dimension that can still be halved until a chunk is at most
// ~128 KiB: the fastest dimension (contiguous in C order) is split only as a last resort.
std::vector<hsize_t> chunk_shape(std::span<const hsize_t> dims, std::size_t element_bytes) {
    constexpr std::size_t target = 128 * 1024;
    std::vector<hsize_t> chunk(dims.begin(), dims.end());
    auto bytes = [&] {
        std::size_t b = element_bytes;
        for (hsize_t c : chunk) b *= c;
        return b;
    };
    while (bytes() > target) {
        auto it = std::find_if(chunk.begin(), chunk.end(), [](hsize_t c) { return c > 1; });
        if (it == chunk.end()) break;
        *it = (*it + 1) / 2;
    }
    return chunk;
}

}  // namespace

template <Element T>
Dataset write_dataset(const Location& where, std::string_view name, std::span<const T> data,
                      std::span<const hsize_t> dims) {
    std::size_t count = 1;
    for (hsize_t d : dims) count *= d;
    const std::string n(name);
    if (count != data.size())
        throw std::invalid_argument("dataset " + n + ": shape holds " + std::to_string(count) +
                                    " elements but " + std::to_string(data.size()) + " were given");
    const std::string what = "writing dataset " + in_quotes(n) + " under " + in_quotes(where.name());

    const Dataspace space = Dataspace::simple(dims);
    PropertyList dcpl = PropertyList::create(H5P_DATASET_CREATE);
    check(H5Pset_obj_track_times(dcpl.id(), 0), what);
    if (count * sizeof(T) >= compress_min_bytes && !dims.empty()) {
        const std::vector<hsize_t> chunk = chunk_shape(dims, sizeof(T));
        check(H5Pset_chunk(dcpl.id(), static_cast<int>(chunk.size()), chunk.data()), what);
        check(H5Pset_shuffle(dcpl.id()), what);
        check(H5Pset_deflate(dcpl.id(), 4), what);
    }
    const hid_t d = H5Dcreate2(where.id(), n.c_str(), Types<T>::file(), space.id(), H5P_DEFAULT,
                               dcpl.id(), H5P_DEFAULT);
    if (d < 0) fail(what);
    Dataset ds(d);
    if (count > 0)
        check(H5Dwrite(ds.id(), Types<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), what);
    return ds;
}

template <Element T>
Dataset create_chunked_dataset(const Location& where, std::string_view name, std::span<const hsize_t> dims,
                               std::span<const hsize_t> chunk) {
    const std::string n(name);
    const std::string what = "creating dataset " + in_quotes(n) + " under " + in_quotes(where.name());
    const Dataspace space = Dataspace::simple(dims);
    PropertyList dcpl = PropertyList::create(H5P_DATASET_CREATE);
    check(H5Pset_obj_track_times(dcpl.id(), 0), what);
    check(H5Pset_chunk(dcpl.id(), static_cast<int>(chunk.size()), chunk.data()), what);
    check(H5Pset_shuffle(dcpl.id()), what);
    check(H5Pset_deflate(dcpl.id(), 4), what);
    const hid_t d = H5Dcreate2(where.id(), n.c_str(), Types<T>::file(), space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT);
    if (d < 0) fail(what);
    return Dataset(d);
}

template <Element T>
void write_rows(const Dataset& ds, hsize_t first, hsize_t rows, std::span<const T> data) {
    const std::string what = "writing rows of dataset " + in_quotes(ds.name());
    std::vector<hsize_t> dims = ds.dims(), start(dims.size(), 0);
    std::size_t per_row = 1;
    for (std::size_t d = 1; d < dims.size(); ++d) per_row *= dims[d];
    if (dims.empty() || first + rows > dims[0] || data.size() != rows * per_row)
        throw std::invalid_argument(what + ": " + std::to_string(data.size()) + " values for rows " + std::to_string(first) +
                                    " + " + std::to_string(rows));
    if (rows == 0) return;
    start[0] = first;
    dims[0] = rows;
    const Dataspace file_space(static_cast<hid_t>(check(H5Dget_space(ds.id()), what)));
    check(H5Sselect_hyperslab(file_space.id(), H5S_SELECT_SET, start.data(), nullptr, dims.data(), nullptr), what);
    const Dataspace memory_space = Dataspace::simple(dims);
    check(H5Dwrite(ds.id(), Types<T>::memory(), memory_space.id(), file_space.id(), H5P_DEFAULT, data.data()), what);
}

namespace {
constexpr std::size_t any_rank = SIZE_MAX;

template <Element T>
std::vector<T> read_all(const Dataset& ds, std::size_t rank, std::vector<hsize_t>& dims_out) {
    const std::string what = "reading dataset " + in_quotes(ds.name()) + " of " + in_quotes(ds.file_name());
    const Datatype type = ds.type();
    if (!type_matches<T>(type.id()))
        throw Hdf5Error(what + ": expected " + Types<T>::kind + " data");
    dims_out = ds.dims();
    if (rank != any_rank && dims_out.size() != rank)
        throw Hdf5Error(what + ": expected " + std::to_string(rank) + " dimension(s), found " +
                        std::to_string(dims_out.size()));
    std::size_t count = 1;
    for (hsize_t d : dims_out) count *= d;
    std::vector<T> values(count);
    if (count > 0)
        check(H5Dread(ds.id(), Types<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), what);
    return values;
}
}  // namespace

template <Element T>
std::vector<T> read_1d(const Location& where, std::string_view name) {
    std::vector<hsize_t> dims;
    return read_all<T>(where.open_dataset(name), 1, dims);
}

template <Element T>
Array2<T> read_2d(const Location& where, std::string_view name) {
    std::vector<hsize_t> dims;
    Array2<T> a;
    a.values = read_all<T>(where.open_dataset(name), 2, dims);
    a.rows = dims[0];
    a.cols = dims[1];
    return a;
}

template <Element T>
ArrayN<T> read_array(const Location& where, std::string_view name) {
    ArrayN<T> a;
    a.values = read_all<T>(where.open_dataset(name), any_rank, a.dims);
    return a;
}

template Dataset write_dataset<double>(const Location&, std::string_view, std::span<const double>,
                                       std::span<const hsize_t>);
template Dataset write_dataset<std::int32_t>(const Location&, std::string_view,
                                             std::span<const std::int32_t>, std::span<const hsize_t>);
template Dataset write_dataset<std::uint8_t>(const Location&, std::string_view,
                                             std::span<const std::uint8_t>, std::span<const hsize_t>);
template Dataset create_chunked_dataset<double>(const Location&, std::string_view, std::span<const hsize_t>,
                                                std::span<const hsize_t>);
template Dataset create_chunked_dataset<std::int32_t>(const Location&, std::string_view, std::span<const hsize_t>,
                                                      std::span<const hsize_t>);
template Dataset create_chunked_dataset<std::uint8_t>(const Location&, std::string_view, std::span<const hsize_t>,
                                                      std::span<const hsize_t>);
template void write_rows<double>(const Dataset&, hsize_t, hsize_t, std::span<const double>);
template void write_rows<std::int32_t>(const Dataset&, hsize_t, hsize_t, std::span<const std::int32_t>);
template void write_rows<std::uint8_t>(const Dataset&, hsize_t, hsize_t, std::span<const std::uint8_t>);
template std::vector<double> read_1d<double>(const Location&, std::string_view);
template std::vector<std::int32_t> read_1d<std::int32_t>(const Location&, std::string_view);
template std::vector<std::uint8_t> read_1d<std::uint8_t>(const Location&, std::string_view);
template ArrayN<double> read_array<double>(const Location&, std::string_view);
template ArrayN<std::int32_t> read_array<std::int32_t>(const Location&, std::string_view);
template ArrayN<std::uint8_t> read_array<std::uint8_t>(const Location&, std::string_view);
template Array2<double> read_2d<double>(const Location&, std::string_view);
template Array2<std::int32_t> read_2d<std::int32_t>(const Location&, std::string_view);
template Array2<std::uint8_t> read_2d<std::uint8_t>(const Location&, std::string_view);

}  // namespace rocksweep::h5
