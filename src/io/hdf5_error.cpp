// Errors of the HDF5 wrapper: HDF5's own error stack read into one line and thrown as an
// Hdf5Error. Apart because every other piece of the wrapper reports through it.
#include <algorithm>
#include <cerrno>
#include <string>
#include <vector>

#include "hdf5_detail.hpp"
#include "rocksweep/io/hdf5.hpp"

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

}  // namespace

namespace detail {

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

}  // namespace detail

void silence_errors() noexcept { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

std::int64_t check(std::int64_t status, std::string_view context) {
    if (status < 0) detail::fail(context);
    return status;
}

}  // namespace rocksweep::h5
