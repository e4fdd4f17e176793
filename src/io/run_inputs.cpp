#include "rocksweep/io/run_inputs.hpp"

#include <sys/stat.h>

#include <vector>

#include "rocksweep/core/errors.hpp"

namespace rocksweep {

namespace {

struct Input {
    std::string what, path;
    dev_t dev;
    ino_t ino;
};

// One process runs one command line; the registry lives as long as it (rank 0 claims outputs).
std::vector<Input>& inputs() {
    static std::vector<Input> all;
    return all;
}

[[noreturn]] void refuse(const std::string& field, const std::string& path, const Input& in) {
    throw InputError(field, path,
                     "a file that is not one of the run's inputs (it is " + in.what +
                         (in.path == path ? std::string() : " " + in.path) + ", which the run reads)");
}

/// The input noted for the file `st` describes (by identity: any of its names), or none.
const Input* noted(const struct stat& st) {
    for (const Input& in : inputs())
        if (in.dev == st.st_dev && in.ino == st.st_ino) return &in;
    return nullptr;
}

}  // namespace

void note_input(const std::string& what, const std::string& path) {
    struct stat st {};
    if (path.empty() || ::stat(path.c_str(), &st) != 0) return;
    if (!noted(st)) inputs().push_back({what, path, st.st_dev, st.st_ino});  // the first name it was given is kept
}

void refuse_input_as_output(const std::string& field, const std::string& path) {
    struct stat st {};
    if (path.empty() || ::stat(path.c_str(), &st) != 0) return;
    if (const Input* in = noted(st)) refuse(field, path, *in);
}

void refuse_same_file(const std::string& field, const std::string& path, const std::string& what, const std::string& input) {
    struct stat out {}, in {};
    if (path.empty() || input.empty() || ::stat(path.c_str(), &out) != 0 || ::stat(input.c_str(), &in) != 0) return;
    if (out.st_dev == in.st_dev && out.st_ino == in.st_ino) refuse(field, path, Input{what, input, in.st_dev, in.st_ino});
}

void forget_inputs() { inputs().clear(); }

}  // namespace rocksweep
