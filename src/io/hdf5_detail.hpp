#pragma once
// What the pieces of the HDF5 wrapper (hdf5_*.cpp) share and no user of it needs: turning HDF5's
// error stack into an Hdf5Error, quoting names in its messages, and the one mapping of element
// types to memory and file types. Internal to src/io/.
#include <cstdint>
#include <string>
#include <string_view>

#include "rocksweep/io/hdf5.hpp"

namespace rocksweep::h5::detail {

/// Throws Hdf5Error("<context>: <HDF5's error stack>") carrying errno as the failed call left it;
/// clears the stack.
[[noreturn]] void fail(std::string_view context);

/// `s` between single quotes, for messages.
std::string in_quotes(std::string_view s);

/// HDF5's memory and (explicitly little-endian) file types of each Element, and its name for
/// messages.
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

}  // namespace rocksweep::h5::detail
