#pragma once
/// A small RAII layer over the HDF5 C API: one move-only owner per handle kind, every call
/// checked, failures thrown as Hdf5Error carrying HDF5's own error text.
///
/// Only rocksweep_io includes this header; the physics never sees HDF5.
///
/// One source file per concept, in src/io/: hdf5_error.cpp (check, silence_errors),
/// hdf5_handle.cpp (Handle, Dataspace, Datatype, PropertyList), hdf5_object.cpp (Object,
/// Location, Dataset), hdf5_file.cpp (File), hdf5_dataset.cpp, hdf5_inplace.cpp,
/// hdf5_attribute.cpp, hdf5_scale.cpp and hdf5_publish.cpp (the sections below).
#include <hdf5.h>

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace rocksweep {

/// A failed HDF5 call. what() = "<what we were doing>: <HDF5's error stack, innermost last>".
class Hdf5Error : public std::runtime_error {
public:
    explicit Hdf5Error(const std::string& what, int sys_errno = 0)
        : std::runtime_error(what), sys_errno_(sys_errno) {}
    /// errno as the failed call left it (e.g. ENOSPC from a write), 0 when none was set.
    int sys_errno() const noexcept { return sys_errno_; }

private:
    int sys_errno_ = 0;
};

namespace h5 {

/// Turns off HDF5's automatic printing of error stacks (we report them in Hdf5Error instead).
/// Idempotent; File::create / File::open call it, so callers rarely need to.
void silence_errors() noexcept;

/// Throws Hdf5Error("<context>: <HDF5 error stack>") if `status` is negative; returns it otherwise.
/// Clears HDF5's error stack either way.
std::int64_t check(std::int64_t status, std::string_view context);

/// Owns one hid_t and releases it with the close function it was given. Move-only.
/// The destructor never throws (a failed close there is ignored); close() reports it.
class Handle {
public:
    using CloseFn = herr_t (*)(hid_t);

    Handle() noexcept = default;
    Handle(hid_t id, CloseFn close) noexcept : id_(id), close_(close) {}
    Handle(Handle&& other) noexcept;
    Handle& operator=(Handle&& other) noexcept;
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle();

    hid_t id() const noexcept { return id_; }
    bool valid() const noexcept { return id_ >= 0; }
    /// Releases the handle now. Throws Hdf5Error if HDF5 reports a failure; the handle then
    /// keeps its id and the destructor tries once more.
    void close();

protected:
    /// Gives the id up without closing it (HDF5 has already disposed of it, or it is unsafe to
    /// touch again).
    void forget() noexcept { id_ = H5I_INVALID_HID; }

private:
    void release() noexcept;
    hid_t id_ = H5I_INVALID_HID;
    CloseFn close_ = nullptr;
};

/// A dataspace (shape). `dims` in C order, slowest-varying first.
class Dataspace : public Handle {
public:
    Dataspace() = default;
    explicit Dataspace(hid_t id) noexcept : Handle(id, H5Sclose) {}
    static Dataspace scalar();
    static Dataspace simple(std::span<const hsize_t> dims);
    std::vector<hsize_t> dims() const;
    std::size_t element_count() const;
};

/// An owned datatype (copies of predefined types, string types).
class Datatype : public Handle {
public:
    Datatype() = default;
    explicit Datatype(hid_t id) noexcept : Handle(id, H5Tclose) {}
    /// Fixed-length string type of exactly text.size() bytes (1 for ""), null-padded, no
    /// terminator stored: netCDF tools read it as text without a trailing NUL. ASCII character
    /// set unless `text` has bytes >= 0x80 (then UTF-8). Throws Hdf5Error if `text` has a NUL.
    static Datatype fixed_string_for(std::string_view text);
};

/// A property list (dataset creation, file access, ...).
class PropertyList : public Handle {
public:
    PropertyList() = default;
    explicit PropertyList(hid_t id) noexcept : Handle(id, H5Pclose) {}
    /// A new list of class `cls`, e.g. H5P_DATASET_CREATE.
    static PropertyList create(hid_t cls);
};

class Attribute : public Handle {
public:
    Attribute() = default;
    explicit Attribute(hid_t id) noexcept : Handle(id, H5Aclose) {}
};

/// Anything that carries attributes: a file (its root group), a group or a dataset.
class Object : public Handle {
public:
    using Handle::Handle;
    /// HDF5 path of the object inside its file (for messages), e.g. "/spectra/free".
    std::string name() const;
    /// Name of the file the object lives in (for messages).
    std::string file_name() const;
    bool has_attribute(std::string_view attr) const;
};

class Dataset;
class Group;

/// The bytes of a file made by File::create_in_memory, filled when it is closed.
struct MemoryImage {
    std::vector<unsigned char> bytes;
    std::size_t driver_size = 0;  ///< bookkeeping: the size of the driver's buffer
};

/// A file or a group: something that holds links to groups and datasets.
class Location : public Object {
public:
    using Object::Object;
    Group create_group(std::string_view name) const;
    Group open_group(std::string_view name) const;
    Dataset open_dataset(std::string_view name) const;
    /// True if every component of the relative path `path` exists (no error when a parent
    /// is missing, unlike H5Lexists).
    bool exists(std::string_view path) const;
    /// Names of the links directly under this location, in name order.
    std::vector<std::string> children() const;
};

class Group : public Location {
public:
    Group() = default;
    explicit Group(hid_t id) noexcept : Location(id, H5Gclose) {}
};

class Dataset : public Object {
public:
    Dataset() = default;
    explicit Dataset(hid_t id) noexcept : Object(id, H5Dclose) {}
    Dataspace space() const;
    Datatype type() const;
    std::vector<hsize_t> dims() const { return space().dims(); }
};

/// An open HDF5 file. Closing it closes the root group; objects opened from it must be closed
/// first (the file is opened with H5F_CLOSE_SEMI, so close() throws if any are left open).
class File : public Location {
public:
    File() = default;
    /// Creates (truncates) `path` for writing, in the HDF5 1.8 file format so that older h5py
    /// and MATLAB releases read it. Throws Hdf5Error naming the path.
    static File create(const std::string& path);
    /// Opens an existing file read-only. Throws Hdf5Error naming the path.
    static File open_read_only(const std::string& path);
    /// Opens an existing file for writing without taking HDF5's file lock, so that a reader
    /// holding the file open (h5py, ncdump) does not make a writer fail. Meant for in-place
    /// updates that do not move metadata (update_attribute). Throws Hdf5Error naming the path.
    static File open_for_update(const std::string& path);
    /// Creates a file held in memory only (HDF5's core driver, no backing store): `name` is
    /// for messages; nothing reaches the disk. When it is closed, its final bytes (what the
    /// file on disk would hold, then zero padding; its size is what H5Fget_file_image reports
    /// before the close) land in `image.bytes`; `image` must outlive the file. Throws Hdf5Error.
    static File create_in_memory(const std::string& name, MemoryImage& image);

    /// The path it was created or opened with (messages are built from it, never by asking
    /// HDF5 about a file that may be failing).
    const std::string& path() const noexcept { return path_; }

    /// Flushes and closes the file. Throws Hdf5Error naming path():
    /// - if objects opened from it are still open: the file stays open and the destructor
    ///   closes it once they are gone;
    /// - if the flush fails (e.g. no space left on device): the id is given up, since HDF5
    ///   leaves a file whose close failed in a state that must not be touched again.
    void close();

private:
    static File create_with(const std::string& path, const PropertyList& fapl);
    File(hid_t id, std::string path) noexcept : Location(id, H5Fclose), path_(std::move(path)) {}
    std::string path_;
};

// ---------------------------------------------------------------------------------------
// Datasets (hdf5_dataset.cpp)

/// Element types the helpers write and read, with their explicit little-endian file types:
/// double -> H5T_IEEE_F64LE, int32 -> H5T_STD_I32LE, uint8 -> H5T_STD_U8LE.
template <class T>
concept Element =
    std::same_as<T, double> || std::same_as<T, std::int32_t> || std::same_as<T, std::uint8_t>;

/// Datasets at least this large (bytes) are written chunked with shuffle + deflate level 4;
/// smaller ones contiguous (compression would only add overhead).
inline constexpr std::size_t compress_min_bytes = 4096;

/// Creates dataset `name` under `where` holding `data` in C order with shape `dims`
/// (product of dims == data.size(), else std::invalid_argument). Throws Hdf5Error.
template <Element T>
Dataset write_dataset(const Location& where, std::string_view name, std::span<const T> data,
                      std::span<const hsize_t> dims);

/// 1-D dataset of data.size() elements.
template <Element T>
Dataset write_1d(const Location& where, std::string_view name, std::span<const T> data) {
    const hsize_t dims[1] = {data.size()};
    return write_dataset<T>(where, name, data, dims);
}

/// 2-D dataset [rows][cols], C order (the row index varies slowest).
template <Element T>
Dataset write_2d(const Location& where, std::string_view name, std::span<const T> data,
                 std::size_t rows, std::size_t cols) {
    const hsize_t dims[2] = {rows, cols};
    return write_dataset<T>(where, name, data, dims);
}

/// Creates an empty dataset `name` of shape `dims`, chunked by `chunk` (one entry per dimension)
/// with shuffle + deflate level 4, for write_rows to fill a slab at a time: a writer that never
/// holds the whole array. Throws Hdf5Error.
template <Element T>
Dataset create_chunked_dataset(const Location& where, std::string_view name, std::span<const hsize_t> dims,
                               std::span<const hsize_t> chunk);

/// Writes rows [first, first + rows) of the slowest dimension of `ds` from `data` (C order,
/// rows times the other dimensions' sizes; else std::invalid_argument). Throws Hdf5Error.
template <Element T>
void write_rows(const Dataset& ds, hsize_t first, hsize_t rows, std::span<const T> data);

/// A 2-D array read back, C order: values[i * cols + j].
template <class T>
struct Array2 {
    std::size_t rows = 0, cols = 0;
    std::vector<T> values;
};

/// An array of any rank read back, C order.
template <class T>
struct ArrayN {
    std::vector<hsize_t> dims;
    std::vector<T> values;
};

/// Reads a whole dataset of any rank. Throws Hdf5Error if it is missing or its type is not of
/// T's kind (float for double; integer of the same size and signedness otherwise).
template <Element T>
ArrayN<T> read_array(const Location& where, std::string_view name);

/// Reads a whole 1-D dataset. Throws Hdf5Error if it is missing, not 1-D, or its type is not
/// of T's kind (float for double; integer of the same size and signedness otherwise).
template <Element T>
std::vector<T> read_1d(const Location& where, std::string_view name);

/// Reads a whole 2-D dataset. Same checks as read_1d.
template <Element T>
Array2<T> read_2d(const Location& where, std::string_view name);

// ---------------------------------------------------------------------------------------
// Datasets written in place, behind HDF5's back (hdf5_inplace.cpp)

/// Creates dataset `name` of shape `dims`: contiguous, uncompressed, its storage allocated at
/// creation and never filled by HDF5 (on disk a hole, read as zeros until written). Its bytes
/// can then be written with pwrite at raw_data_offset() while no HDF5 handle is open: such a
/// write changes no metadata, so a kill in the middle leaves a valid file. Throws Hdf5Error.
template <Element T>
Dataset create_fixed_dataset(const Location& where, std::string_view name, std::span<const hsize_t> dims);

/// Byte offset in its file of the raw data of a dataset made by create_fixed_dataset, and the
/// size of one element. Throws Hdf5Error if the dataset is not contiguous with allocated storage
/// (e.g. written by write_dataset), or its type is not little-endian.
struct RawPlacement {
    std::uint64_t offset = 0;
    std::size_t element_bytes = 0;
};
RawPlacement raw_placement(const Dataset& ds);

/// Overwrites the value of an existing scalar numeric attribute in place (same type, same size:
/// no metadata moves, unlike write_attribute, which deletes and recreates). Throws Hdf5Error.
void update_attribute(const Object& obj, std::string_view name, double value);
void update_attribute(const Object& obj, std::string_view name, std::int64_t value);

// ---------------------------------------------------------------------------------------
// Attributes (hdf5_attribute.cpp; scalar unless stated; an existing one of the same name is replaced)

/// The root attribute `Conventions` of every file rocksweep writes: the files give each variable
/// units and long_name, coded ones flag_values / flag_meanings, and dimension scales as
/// coordinates, as the CF conventions ask; netCDF tools read the version from here.
inline constexpr const char* cf_conventions = "CF-1.8";

void write_attribute(const Object& obj, std::string_view name, double value);
void write_attribute(const Object& obj, std::string_view name, std::int64_t value);
/// Any other integer is stored as int64 (H5T_STD_I64LE). Throws std::out_of_range if it does
/// not fit.
template <std::integral I>
    requires(!std::same_as<I, bool> && !std::same_as<I, std::int64_t>)
void write_attribute(const Object& obj, std::string_view name, I value) {
    if constexpr (std::is_unsigned_v<I> && sizeof(I) >= sizeof(std::int64_t)) {
        if (value > static_cast<I>(INT64_MAX))
            throw std::out_of_range("attribute " + std::string(name) + " does not fit in int64");
    }
    write_attribute(obj, name, static_cast<std::int64_t>(value));
}
/// Fixed-length string (see Datatype::fixed_string_for). Throws Hdf5Error
/// if `value` contains a NUL byte.
void write_attribute(const Object& obj, std::string_view name, std::string_view value);
inline void write_attribute(const Object& obj, std::string_view name, const char* value) {
    write_attribute(obj, name, std::string_view(value));
}
inline void write_attribute(const Object& obj, std::string_view name, const std::string& value) {
    write_attribute(obj, name, std::string_view(value));
}
/// 1-D array attributes.
void write_attribute(const Object& obj, std::string_view name, std::span<const double> values);
void write_attribute(const Object& obj, std::string_view name,
                     std::span<const std::uint8_t> values);

/// Reads a scalar numeric attribute (any integer or float type) as double. Throws Hdf5Error.
double read_double_attribute(const Object& obj, std::string_view name);
/// Reads a scalar integer attribute as int64. Throws Hdf5Error (also for a float attribute).
std::int64_t read_int64_attribute(const Object& obj, std::string_view name);
/// Reads a scalar string attribute, fixed- or variable-length; padding and the terminator
/// are dropped. Throws Hdf5Error.
std::string read_string_attribute(const Object& obj, std::string_view name);

// ---------------------------------------------------------------------------------------
// Dimension scales (H5DS, hdf5_hl; hdf5_scale.cpp)

/// Makes the 1-D dataset `scale` a dimension scale called `scale_name`.
void make_scale(const Dataset& scale, std::string_view scale_name);
/// Attaches `scale` to dimension `dim` (0 = slowest) of `data`.
void attach_scale(const Dataset& data, const Dataset& scale, unsigned dim);
/// True if `scale` is attached to dimension `dim` of `data`.
bool is_attached(const Dataset& data, const Dataset& scale, unsigned dim);
/// Labels dimension `dim` of `data` (shown by h5py's ds.dims[i].label and h5dump). The labels
/// are variable-length strings, on which Octave's netcdf package (ncinfo) fails, so the
/// spectra and history files carry none.
void set_dimension_label(const Dataset& data, unsigned dim, std::string_view label);

// ---------------------------------------------------------------------------------------
// Publishing a file (not HDF5-specific; the CSV writer uses it too; hdf5_publish.cpp)

/// Calls write(path + ".tmp") and, once it returns, renames the tmp file onto `path`, so a
/// reader never sees a half-written `path`. If `write` throws, the tmp file is removed and
/// `path` is untouched: InputError and std::invalid_argument propagate as they are; any other
/// failure (Hdf5Error, std::system_error, ...) becomes std::runtime_error("cannot write PATH:
/// REASON"), REASON "no space left on device" when errno says the disk or quota is full,
/// followed by a note that `path` still holds the previous save if there is one.
/// If the rename fails, the tmp file is removed and InputError("output", path, ...) is thrown.
void publish_atomically(const std::string& path,
                        const std::function<void(const std::string& tmp_path)>& write);

/// Writes `bytes` to `path` (created or truncated) and fsyncs it, so that a rename that follows
/// publishes data that is on the disk. Throws InputError("output", output, ...) if `path`
/// cannot be created, std::system_error carrying errno if writing it fails.
void write_file_bytes(const std::string& path, std::span<const unsigned char> bytes, const std::string& output);

/// The error publish_atomically throws for a failed write of `path` (errno `err`, 0 if none):
/// "cannot write PATH: REASON", with the note about the previous save. For writers that update
/// `path` in place and must report a full disk in the same words.
std::runtime_error write_failure(const std::string& path, int err, const std::string& detail);

/// Builds an HDF5 file in memory with `write` and writes its bytes to `tmp` (write_file_bytes;
/// `output` names the file in messages). Throws like write_file_bytes, Hdf5Error.
void write_h5_image(const std::string& tmp, const std::string& output, const std::function<void(const File&)>& write);

/// publish_atomically for an HDF5 file: `write` fills a file built in memory, whose bytes are
/// then written to the tmp name by write_file_bytes. HDF5 itself never meets a full disk (a
/// failed flush inside HDF5 leaves its library state broken, up to a crash at exit).
void publish_h5_atomically(const std::string& path, const std::function<void(const File&)>& write);

}  // namespace h5
}  // namespace rocksweep
