// Owning one HDF5 id: the move-only Handle, and the handle kinds that hold a value rather than
// links (dataspace, datatype, property list). Apart from the objects of a file (hdf5_object.cpp)
// because these live outside any file and every other piece builds on them.
#include <algorithm>
#include <string>
#include <utility>

#include "hdf5_detail.hpp"
#include "rocksweep/io/hdf5.hpp"

namespace rocksweep::h5 {

using detail::fail;

// ---------------------------------------------------------------------------------------
// Handle

Handle::Handle(Handle&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)), close_(std::exchange(other.close_, nullptr)) {}

Handle& Handle::operator=(Handle&& other) noexcept {
    if (this != &other) {
        release();
        id_ = std::exchange(other.id_, H5I_INVALID_HID);
        close_ = std::exchange(other.close_, nullptr);
    }
    return *this;
}

Handle::~Handle() { release(); }

void Handle::release() noexcept {
    if (id_ >= 0 && close_) {
        if (close_(id_) < 0) H5Eclear2(H5E_DEFAULT);  // nothing useful to do in a destructor
    }
    id_ = H5I_INVALID_HID;
}

void Handle::close() {
    if (id_ < 0 || !close_) return;
    // No name in the message: asking HDF5 for the name of an object whose close just failed
    // reads freed memory. HDF5 does not reuse ids, so the destructor's second attempt on an id
    // that did go away only returns an error.
    if (close_(id_) < 0) fail("closing an HDF5 object");
    id_ = H5I_INVALID_HID;
}

// ---------------------------------------------------------------------------------------
// Dataspace, Datatype, PropertyList

Dataspace Dataspace::scalar() {
    const hid_t id = H5Screate(H5S_SCALAR);
    if (id < 0) fail("creating a scalar dataspace");
    return Dataspace(id);
}

Dataspace Dataspace::simple(std::span<const hsize_t> dims) {
    const hid_t id = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
    if (id < 0) fail("creating a dataspace of rank " + std::to_string(dims.size()));
    return Dataspace(id);
}

std::vector<hsize_t> Dataspace::dims() const {
    const int rank = static_cast<int>(check(H5Sget_simple_extent_ndims(id()), "reading a rank"));
    std::vector<hsize_t> d(static_cast<std::size_t>(rank));
    if (rank > 0) check(H5Sget_simple_extent_dims(id(), d.data(), nullptr), "reading a shape");
    return d;
}

std::size_t Dataspace::element_count() const {
    return static_cast<std::size_t>(check(H5Sget_simple_extent_npoints(id()), "counting elements"));
}

Datatype Datatype::fixed_string_for(std::string_view text) {
    if (text.find('\0') != std::string_view::npos)
        throw Hdf5Error("a string for HDF5 contains a NUL byte (it would be cut there)");
    const bool ascii = std::all_of(text.begin(), text.end(),
                                   [](char c) { return static_cast<unsigned char>(c) < 0x80; });
    Datatype t(H5Tcopy(H5T_C_S1));
    if (!t.valid()) fail("copying the C string type");
    // Fixed-length, not variable-length: Octave's netcdf package cannot read NC_STRING
    // attributes (its ncinfo fails on a group holding one). No terminator stored: netCDF
    // reads a fixed-length string as NC_CHAR of its full size, so a stored NUL would reach
    // Octave's and MATLAB's ncreadatt as a trailing char(0). HDF5 has no zero-size string
    // type: "" is one NUL of padding, which every reader strips.
    check(H5Tset_size(t.id(), std::max<std::size_t>(text.size(), 1)), "sizing a string type");
    check(H5Tset_strpad(t.id(), H5T_STR_NULLPAD), "setting string padding");
    check(H5Tset_cset(t.id(), ascii ? H5T_CSET_ASCII : H5T_CSET_UTF8), "setting string charset");
    return t;
}

PropertyList PropertyList::create(hid_t cls) {
    const hid_t id = H5Pcreate(cls);
    if (id < 0) fail("creating a property list");
    return PropertyList(id);
}

}  // namespace rocksweep::h5
