// Attributes: scalar and 1-D numbers and fixed-length strings written (replacing one of the same
// name), and scalar ones read back with their kind checked. Apart from datasets because they are
// the files' metadata, with their own string rules for netCDF, Octave and MATLAB readers.
#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <string>

#include "hdf5_detail.hpp"
#include "rocksweep/io/hdf5.hpp"

namespace rocksweep::h5 {

using detail::fail;
using detail::in_quotes;

namespace {

Attribute create_attribute(const Object& obj, std::string_view name, hid_t file_type,
                           const Dataspace& space) {
    const std::string n(name);
    const std::string where = "attribute " + in_quotes(n) + " of " + in_quotes(obj.name());
    if (check(H5Aexists(obj.id(), n.c_str()), "checking " + where) > 0)
        check(H5Adelete(obj.id(), n.c_str()), "replacing " + where);
    const hid_t id = H5Acreate2(obj.id(), n.c_str(), file_type, space.id(), H5P_DEFAULT, H5P_DEFAULT);
    if (id < 0) fail("creating " + where);
    return Attribute(id);
}

Attribute open_attribute(const Object& obj, std::string_view name) {
    const std::string n(name);
    const hid_t id = H5Aopen(obj.id(), n.c_str(), H5P_DEFAULT);
    if (id < 0) fail("opening attribute " + in_quotes(n) + " of " + in_quotes(obj.name()));
    return Attribute(id);
}

template <class T>
void write_array_attribute(const Object& obj, std::string_view name, std::span<const T> values,
                           hid_t file_type, hid_t memory_type) {
    const hsize_t dims[1] = {values.size()};
    const Dataspace space = Dataspace::simple(dims);
    const Attribute a = create_attribute(obj, name, file_type, space);
    check(H5Awrite(a.id(), memory_type, values.data()),
          "writing attribute " + in_quotes(name) + " of " + in_quotes(obj.name()));
}

void require_scalar(const Attribute& a, std::string_view what) {
    const Dataspace space(H5Aget_space(a.id()));
    if (!space.valid()) fail(std::string("reading the shape of ") + std::string(what));
    if (space.element_count() != 1)
        throw Hdf5Error(std::string(what) + ": expected a single value, found " +
                        std::to_string(space.element_count()));
}

}  // namespace

void write_attribute(const Object& obj, std::string_view name, double value) {
    const Attribute a = create_attribute(obj, name, H5T_IEEE_F64LE, Dataspace::scalar());
    check(H5Awrite(a.id(), H5T_NATIVE_DOUBLE, &value), "writing attribute " + in_quotes(name));
}

void write_attribute(const Object& obj, std::string_view name, std::int64_t value) {
    const Attribute a = create_attribute(obj, name, H5T_STD_I64LE, Dataspace::scalar());
    check(H5Awrite(a.id(), H5T_NATIVE_INT64, &value), "writing attribute " + in_quotes(name));
}

void write_attribute(const Object& obj, std::string_view name, std::string_view value) {
    const Datatype type = Datatype::fixed_string_for(value);
    const Attribute a = create_attribute(obj, name, type.id(), Dataspace::scalar());
    const std::string buffer(value);  // c_str() supplies the padding byte of ""
    check(H5Awrite(a.id(), type.id(), buffer.c_str()), "writing attribute " + in_quotes(name));
}

void write_attribute(const Object& obj, std::string_view name, std::span<const double> values) {
    write_array_attribute(obj, name, values, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
}

void write_attribute(const Object& obj, std::string_view name,
                     std::span<const std::uint8_t> values) {
    write_array_attribute(obj, name, values, H5T_STD_U8LE, H5T_NATIVE_UINT8);
}

namespace {

/// A scalar attribute opened for reading, its file type, and its name for messages.
struct ScalarAttribute {
    std::string what;
    Attribute a;
    Datatype type;
};

/// Opens attribute `name` of `obj`; throws "...: `not_this`" unless its type class is one of
/// `classes`, then requires it scalar (in that order, as the readers always checked).
ScalarAttribute open_scalar_attribute(const Object& obj, std::string_view name,
                                      std::initializer_list<H5T_class_t> classes, const char* not_this) {
    ScalarAttribute r{"attribute " + in_quotes(name) + " of " + in_quotes(obj.name()), open_attribute(obj, name), {}};
    r.type = Datatype(H5Aget_type(r.a.id()));
    if (!r.type.valid()) fail("reading the type of " + r.what);
    const H5T_class_t cls = H5Tget_class(r.type.id());
    if (std::find(classes.begin(), classes.end(), cls) == classes.end()) throw Hdf5Error(r.what + ": " + not_this);
    require_scalar(r.a, r.what);
    return r;
}

}  // namespace

double read_double_attribute(const Object& obj, std::string_view name) {
    const ScalarAttribute s = open_scalar_attribute(obj, name, {H5T_FLOAT, H5T_INTEGER}, "not a number");
    double value = 0.0;
    check(H5Aread(s.a.id(), H5T_NATIVE_DOUBLE, &value), "reading " + s.what);
    return value;
}

std::int64_t read_int64_attribute(const Object& obj, std::string_view name) {
    const ScalarAttribute s = open_scalar_attribute(obj, name, {H5T_INTEGER}, "not an integer");
    std::int64_t value = 0;
    check(H5Aread(s.a.id(), H5T_NATIVE_INT64, &value), "reading " + s.what);
    return value;
}

std::string read_string_attribute(const Object& obj, std::string_view name) {
    const ScalarAttribute opened = open_scalar_attribute(obj, name, {H5T_STRING}, "not a string");
    const std::string& what = opened.what;
    const Attribute& a = opened.a;
    const Datatype& type = opened.type;

    const htri_t variable = check(H5Tis_variable_str(type.id()), "reading " + what);
    if (variable > 0) {
        // Variable-length (what h5py writes by default): HDF5 allocates, we free.
        Datatype memory(H5Tcopy(H5T_C_S1));
        if (!memory.valid()) fail("reading " + what);
        check(H5Tset_size(memory.id(), H5T_VARIABLE), "reading " + what);
        check(H5Tset_cset(memory.id(), H5Tget_cset(type.id())), "reading " + what);
        char* p = nullptr;
        check(H5Aread(a.id(), memory.id(), &p), "reading " + what);
        std::string s = p ? p : "";
        H5free_memory(p);
        return s;
    }
    const std::size_t size = H5Tget_size(type.id());
    std::string s(size, '\0');
    if (size > 0) check(H5Aread(a.id(), type.id(), s.data()), "reading " + what);
    if (const auto nul = s.find('\0'); nul != std::string::npos) s.resize(nul);
    if (H5Tget_strpad(type.id()) == H5T_STR_SPACEPAD) {
        const auto last = s.find_last_not_of(' ');
        s.resize(last == std::string::npos ? 0 : last + 1);
    }
    return s;
}

}  // namespace rocksweep::h5
