// Creating, opening and closing an HDF5 file on disk: the file-wide settings (format version,
// close degree, no object times) that make our files readable everywhere and reproducible.
// Apart because these choices are about the file, not what goes in it; the in-memory and
// in-place variants live with their users' concepts (hdf5_publish.cpp, hdf5_inplace.cpp).
#include <string>

#include "hdf5_detail.hpp"
#include "rocksweep/io/hdf5.hpp"

namespace rocksweep::h5 {

using detail::fail;
using detail::in_quotes;

File File::create(const std::string& path) {
    silence_errors();
    return create_with(path, PropertyList::create(H5P_FILE_ACCESS));
}

File File::create_with(const std::string& path, const PropertyList& fapl) {
    // The 1.8 format: readable by every h5py and MATLAB in use, and it lets attributes larger
    // than 64 KiB (a long config text) move to dense storage instead of failing.
    check(H5Pset_libver_bounds(fapl.id(), H5F_LIBVER_V18, H5F_LIBVER_V18), "setting file format");
    // Refuse to close while objects are open instead of silently keeping the file open.
    check(H5Pset_fclose_degree(fapl.id(), H5F_CLOSE_SEMI), "setting close degree");
    // No modification times in object headers: two runs of the same sweep then give
    // byte-identical files apart from what they write differently.
    PropertyList fcpl = PropertyList::create(H5P_FILE_CREATE);
    check(H5Pset_obj_track_times(fcpl.id(), 0), "turning off object times");
    const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.id(), fapl.id());
    if (f < 0) fail("creating HDF5 file " + in_quotes(path));
    return File(f, path);
}

File File::open_read_only(const std::string& path) {
    silence_errors();
    PropertyList fapl = PropertyList::create(H5P_FILE_ACCESS);
    check(H5Pset_fclose_degree(fapl.id(), H5F_CLOSE_SEMI), "setting close degree");
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.id());
    if (f < 0) fail("opening HDF5 file " + in_quotes(path));
    return File(f, path);
}

void File::close() {
    if (!valid()) return;
    const unsigned open_kinds = H5F_OBJ_DATASET | H5F_OBJ_GROUP | H5F_OBJ_DATATYPE | H5F_OBJ_ATTR | H5F_OBJ_LOCAL;
    const ssize_t open = H5Fget_obj_count(id(), open_kinds);
    if (open < 0) fail("closing " + in_quotes(path_));
    if (open > 0)
        throw Hdf5Error("closing " + in_quotes(path_) + ": " + std::to_string(open) +
                        " object(s) opened from it are still open");
    if (H5Fclose(id()) < 0) {
        forget();
        fail("closing " + in_quotes(path_));
    }
    forget();
}

}  // namespace rocksweep::h5
