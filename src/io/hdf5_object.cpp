// The objects inside a file: Object (names, for messages), Location (a file or group: its links)
// and Dataset's shape and type. Apart from the handles (hdf5_handle.cpp), which live outside any
// file, and from File itself (hdf5_file.cpp), which is about opening and closing one.
#include <algorithm>
#include <string>
#include <vector>

#include "hdf5_detail.hpp"
#include "rocksweep/io/hdf5.hpp"

namespace rocksweep::h5 {

using detail::fail;
using detail::in_quotes;

namespace {

// Best-effort text from an HDF5 name query (H5Iget_name, H5Fget_name); "?" if it fails.
template <class Query>
std::string name_from(Query query) {
    const ssize_t n = query(nullptr, 0);
    if (n < 0) {
        H5Eclear2(H5E_DEFAULT);
        return "?";
    }
    std::string s(static_cast<std::size_t>(n) + 1, '\0');
    query(s.data(), s.size());
    s.resize(static_cast<std::size_t>(n));
    return s;
}

std::string object_path(hid_t id) {
    return name_from([id](char* buf, std::size_t size) { return H5Iget_name(id, buf, size); });
}

std::string object_file(hid_t id) {
    return name_from([id](char* buf, std::size_t size) { return H5Fget_name(id, buf, size); });
}

herr_t collect_link(hid_t, const char* name, const H5L_info_t*, void* client) {
    static_cast<std::vector<std::string>*>(client)->emplace_back(name);
    return 0;
}

}  // namespace

std::string Object::name() const { return object_path(id()); }

std::string Object::file_name() const { return object_file(id()); }

bool Object::has_attribute(std::string_view attr) const {
    const std::string n(attr);
    return check(H5Aexists(id(), n.c_str()), "looking for attribute " + in_quotes(n)) > 0;
}

Group Location::create_group(std::string_view name) const {
    const std::string n(name);
    PropertyList gcpl = PropertyList::create(H5P_GROUP_CREATE);
    check(H5Pset_obj_track_times(gcpl.id(), 0), "creating group " + in_quotes(n));
    const hid_t g = H5Gcreate2(id(), n.c_str(), H5P_DEFAULT, gcpl.id(), H5P_DEFAULT);
    if (g < 0) fail("creating group " + in_quotes(n));  // the writer names the file
    return Group(g);
}

Group Location::open_group(std::string_view name) const {
    const std::string n(name);
    const hid_t g = H5Gopen2(id(), n.c_str(), H5P_DEFAULT);
    if (g < 0) fail("opening group " + in_quotes(n) + " in " + in_quotes(file_name()));
    return Group(g);
}

Dataset Location::open_dataset(std::string_view name) const {
    const std::string n(name);
    const hid_t d = H5Dopen2(id(), n.c_str(), H5P_DEFAULT);
    if (d < 0) fail("opening dataset " + in_quotes(n) + " under " + in_quotes(this->name()) + " in " +
                    in_quotes(file_name()));
    return Dataset(d);
}

bool Location::exists(std::string_view path) const {
    // H5Lexists fails (rather than answering false) when an intermediate group is missing,
    // so test the prefixes one component at a time.
    std::string prefix;
    std::size_t start = 0;
    while (start <= path.size()) {
        const std::size_t slash = std::min(path.find('/', start), path.size());
        if (slash > start) {
            if (!prefix.empty()) prefix += '/';
            prefix += path.substr(start, slash - start);
            if (check(H5Lexists(id(), prefix.c_str(), H5P_DEFAULT), "looking for " + in_quotes(prefix)) <= 0)
                return false;
        }
        start = slash + 1;
    }
    return !prefix.empty();
}

std::vector<std::string> Location::children() const {
    std::vector<std::string> names;
    hsize_t index = 0;
    check(H5Literate(id(), H5_INDEX_NAME, H5_ITER_INC, &index, collect_link, &names),
          "listing " + in_quotes(name()));
    return names;
}

Dataspace Dataset::space() const {
    const hid_t s = H5Dget_space(id());
    if (s < 0) fail("reading the shape of " + in_quotes(name()));
    return Dataspace(s);
}

Datatype Dataset::type() const {
    const hid_t t = H5Dget_type(id());
    if (t < 0) fail("reading the type of " + in_quotes(name()));
    return Datatype(t);
}

}  // namespace rocksweep::h5
