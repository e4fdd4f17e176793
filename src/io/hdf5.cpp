#include "rocksweep/io/hdf5.hpp"

#include <fcntl.h>
#include <hdf5_hl.h>
#include <unistd.h>

#include <algorithm>
#include <initializer_list>
#include <cstdlib>
#include <cstring>
#include <cerrno>
#include <filesystem>
#include <system_error>
#include <type_traits>
#include <utility>

#include "rocksweep/core/errors.hpp"

namespace rocksweep::h5 {

namespace {

// Collects the `desc` of every entry of HDF5's error stack, outermost (the API call) first,
// so the innermost and most specific reason (often with errno) ends the message.
herr_t collect_error(unsigned, const H5E_error2_t* err, void* client) {
    auto* lines = static_cast<std::vector<std::string>*>(client);
    std::string line = err->desc ? err->desc : "";
    // Some entries embed a ctime() timestamp with its own newline: noise in a one-line message.
    if (const auto t = line.find("time = "); t != std::string::npos) {
        const auto end = line.find(", ", t);
        line.erase(t, end == std::string::npos ? std::string::npos : end + 2 - t);
    }
    std::replace(line.begin(), line.end(), '\n', ' ');
    if (line.empty() && err->func_name) line = std::string("failure in ") + err->func_name;
    if (!line.empty() && (lines->empty() || lines->back() != line)) lines->push_back(line);
    return 0;
}

std::string error_stack_text() {
    std::vector<std::string> lines;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect_error, &lines);
    H5Eclear2(H5E_DEFAULT);
    if (lines.empty()) return "HDF5 reported a failure without a message";
    std::string text;
    for (const auto& l : lines) {
        if (!text.empty()) text += "; ";
        text += l;
    }
    return text;
}

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

[[noreturn]] void fail(std::string_view context) {
    const int err = errno;  // before the stack walk can change it
    throw Hdf5Error(std::string(context) + ": " + error_stack_text(), err);
}

std::string in_quotes(std::string_view s) {
    std::string q;
    q.reserve(s.size() + 2);
    q += '\'';
    q += s;
    q += '\'';
    return q;
}

template <Element T>
struct Types;
template <>
struct Types<double> {
    static hid_t memory() { return H5T_NATIVE_DOUBLE; }
    static hid_t file() { return H5T_IEEE_F64LE; }
    static constexpr const char* kind = "float64";
};
template <>
struct Types<std::int32_t> {
    static hid_t memory() { return H5T_NATIVE_INT32; }
    static hid_t file() { return H5T_STD_I32LE; }
    static constexpr const char* kind = "int32";
};
template <>
struct Types<std::uint8_t> {
    static hid_t memory() { return H5T_NATIVE_UINT8; }
    static hid_t file() { return H5T_STD_U8LE; }
    static constexpr const char* kind = "uint8";
};

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

void silence_errors() noexcept { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

std::int64_t check(std::int64_t status, std::string_view context) {
    if (status < 0) fail(context);
    return status;
}

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

// ---------------------------------------------------------------------------------------
// Object, Location, Dataset, File

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

namespace {
herr_t collect_link(hid_t, const char* name, const H5L_info_t*, void* client) {
    static_cast<std::vector<std::string>*>(client)->emplace_back(name);
    return 0;
}
}  // namespace

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

// ---------------------------------------------------------------------------------------
// Datasets

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
template std::vector<double> read_1d<double>(const Location&, std::string_view);
template std::vector<std::int32_t> read_1d<std::int32_t>(const Location&, std::string_view);
template std::vector<std::uint8_t> read_1d<std::uint8_t>(const Location&, std::string_view);
template ArrayN<double> read_array<double>(const Location&, std::string_view);
template ArrayN<std::int32_t> read_array<std::int32_t>(const Location&, std::string_view);
template ArrayN<std::uint8_t> read_array<std::uint8_t>(const Location&, std::string_view);
template Array2<double> read_2d<double>(const Location&, std::string_view);
template Array2<std::int32_t> read_2d<std::int32_t>(const Location&, std::string_view);
template Array2<std::uint8_t> read_2d<std::uint8_t>(const Location&, std::string_view);

// ---------------------------------------------------------------------------------------
// Attributes

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

// ---------------------------------------------------------------------------------------
// Dimension scales

void make_scale(const Dataset& scale, std::string_view scale_name) {
    const std::string n(scale_name);
    check(H5DSset_scale(scale.id(), n.c_str()), "making " + in_quotes(scale.name()) + " a dimension scale");
}

void attach_scale(const Dataset& data, const Dataset& scale, unsigned dim) {
    check(H5DSattach_scale(data.id(), scale.id(), dim),
          "attaching " + in_quotes(scale.name()) + " to dimension " + std::to_string(dim) + " of " +
              in_quotes(data.name()));
}

bool is_attached(const Dataset& data, const Dataset& scale, unsigned dim) {
    return check(H5DSis_attached(data.id(), scale.id(), dim),
                 "checking the scale of dimension " + std::to_string(dim) + " of " +
                     in_quotes(data.name())) > 0;
}

void set_dimension_label(const Dataset& data, unsigned dim, std::string_view label) {
    const std::string l(label);
    check(H5DSset_label(data.id(), dim, l.c_str()),
          "labelling dimension " + std::to_string(dim) + " of " + in_quotes(data.name()));
}

}  // namespace rocksweep::h5
