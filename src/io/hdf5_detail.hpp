#pragma once
// What the pieces of the HDF5 wrapper (hdf5_*.cpp) share and no user of it needs: turning HDF5's
// error stack into an Hdf5Error, and quoting names in its messages. Internal to src/io/.
#include <string>
#include <string_view>

namespace rocksweep::h5::detail {

/// Throws Hdf5Error("<context>: <HDF5's error stack>") carrying errno as the failed call left it;
/// clears the stack.
[[noreturn]] void fail(std::string_view context);

/// `s` between single quotes, for messages.
std::string in_quotes(std::string_view s);

}  // namespace rocksweep::h5::detail
