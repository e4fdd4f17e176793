// Datasets whose bytes are written in place by the caller (pwrite at a known offset) rather than
// through HDF5: the streaming spectra writer updates a file this way, so that a checkpoint never
// changes HDF5 metadata and a kill at any instant leaves a file every reader opens.
#include <bit>
#include <string>

#include "hdf5_detail.hpp"
#include "rocksweep/io/hdf5.hpp"

namespace rocksweep::h5 {

using detail::in_quotes;

namespace {

// Raw bytes written behind HDF5's back are the host's: the file types are little-endian.
static_assert(std::endian::native == std::endian::little, "in-place writes assume a little-endian host");

template <class V>
void update_scalar(const Object& obj, std::string_view name, hid_t memory_type, const V& value) {
    const std::string n(name);
    const std::string what = "updating attribute " + in_quotes(n) + " of " + in_quotes(obj.name());
    const Attribute a(static_cast<hid_t>(check(H5Aopen(obj.id(), n.c_str(), H5P_DEFAULT), what)));
    check(H5Awrite(a.id(), memory_type, &value), what);
}

}  // namespace

File File::open_for_update(const std::string& path) {
    silence_errors();
    PropertyList fapl = PropertyList::create(H5P_FILE_ACCESS);
    check(H5Pset_fclose_degree(fapl.id(), H5F_CLOSE_SEMI), "setting close degree");
    // A reader's shared lock must not fail the writer: what the writer changes here are values
    // of fixed size in place, which a reader sees either before or after.
    check(H5Pset_file_locking(fapl.id(), false, true), "turning off file locking");
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, fapl.id());
    check(f, "opening HDF5 file " + in_quotes(path) + " for writing");
    return File(f, path);
}

template <Element T>
Dataset create_fixed_dataset(const Location& where, std::string_view name, std::span<const hsize_t> dims) {
    const std::string n(name);
    const std::string what = "creating dataset " + in_quotes(n) + " under " + in_quotes(where.name());
    const Dataspace space = Dataspace::simple(dims);
    PropertyList dcpl = PropertyList::create(H5P_DATASET_CREATE);
    check(H5Pset_obj_track_times(dcpl.id(), 0), what);
    check(H5Pset_layout(dcpl.id(), H5D_CONTIGUOUS), what);
    // Allocated now, so that no later write moves metadata; never filled, so that a grid of 1e9
    // cells costs no write at creation (a sparse hole on disk).
    check(H5Pset_alloc_time(dcpl.id(), H5D_ALLOC_TIME_EARLY), what);
    check(H5Pset_fill_time(dcpl.id(), H5D_FILL_TIME_NEVER), what);
    const hid_t d = H5Dcreate2(where.id(), n.c_str(), detail::Types<T>::file(), space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT);
    check(d, what);
    return Dataset(d);
}

template Dataset create_fixed_dataset<double>(const Location&, std::string_view, std::span<const hsize_t>);
template Dataset create_fixed_dataset<std::int32_t>(const Location&, std::string_view, std::span<const hsize_t>);
template Dataset create_fixed_dataset<std::uint8_t>(const Location&, std::string_view, std::span<const hsize_t>);

RawPlacement raw_placement(const Dataset& ds) {
    const std::string what = "locating the data of " + in_quotes(ds.name());
    const PropertyList dcpl(static_cast<hid_t>(check(H5Dget_create_plist(ds.id()), what)));
    if (H5Pget_layout(dcpl.id()) != H5D_CONTIGUOUS) throw Hdf5Error(what + ": not a contiguous dataset");
    const haddr_t offset = H5Dget_offset(ds.id());
    if (offset == HADDR_UNDEF) throw Hdf5Error(what + ": its storage is not allocated");
    const Datatype type = ds.type();
    if (check(H5Tget_order(type.id()), what) != H5T_ORDER_LE && H5Tget_size(type.id()) > 1)
        throw Hdf5Error(what + ": not little-endian");
    return {static_cast<std::uint64_t>(offset), H5Tget_size(type.id())};
}

void update_attribute(const Object& obj, std::string_view name, double value) {
    update_scalar(obj, name, H5T_NATIVE_DOUBLE, value);
}

void update_attribute(const Object& obj, std::string_view name, std::int64_t value) {
    update_scalar(obj, name, H5T_NATIVE_INT64, value);
}

}  // namespace rocksweep::h5
