// Publishing a file so that nothing is ever half written: built in memory (HDF5's core driver),
// written to NAME.tmp by plain write() + fsync, then renamed. A full disk is then an errno we
// keep, not a failure inside HDF5's own teardown.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/hdf5.hpp"

namespace rocksweep::h5 {

namespace {

// The core driver's memory, through the file image callbacks: it is ours to keep at close.
// (H5Fget_file_image on an open 1.8-format file returns a superblock whose checksum does not
// match its cleared status flags in HDF5 1.10; the bytes freed at close are the real file.)
// The udata is the caller's MemoryImage, which outlives the file: HDF5's "copies" of it are
// the same pointer, and freeing one frees nothing.
using ImageBuffer = MemoryImage;

void* image_malloc(std::size_t size, H5FD_file_image_op_t, void* udata) {
    static_cast<ImageBuffer*>(udata)->driver_size = size;
    return std::malloc(size);
}
void* image_memcpy(void* dest, const void* src, std::size_t size, H5FD_file_image_op_t, void*) {
    return std::memcpy(dest, src, size);
}
void* image_realloc(void* ptr, std::size_t size, H5FD_file_image_op_t, void* udata) {
    static_cast<ImageBuffer*>(udata)->driver_size = size;
    return std::realloc(ptr, size);
}
herr_t image_free(void* ptr, H5FD_file_image_op_t op, void* udata) {
    auto* buffer = static_cast<ImageBuffer*>(udata);
    if (op == H5FD_FILE_IMAGE_OP_FILE_CLOSE && ptr) {
        const auto* bytes = static_cast<const unsigned char*>(ptr);
        buffer->bytes.assign(bytes, bytes + buffer->driver_size);
    }
    std::free(ptr);
    return 0;
}
void* udata_copy(void* udata) { return udata; }
herr_t udata_free(void*) { return 0; }

}  // namespace

File File::create_in_memory(const std::string& name, MemoryImage& image) {
    silence_errors();
    PropertyList fapl = PropertyList::create(H5P_FILE_ACCESS);
    check(H5Pset_fapl_core(fapl.id(), std::size_t{1} << 16, 0), "setting the in-memory driver");
    H5FD_file_image_callbacks_t callbacks{image_malloc, image_memcpy, image_realloc, image_free,
                                          udata_copy,   udata_free,   &image};
    check(H5Pset_file_image_callbacks(fapl.id(), &callbacks), "setting the in-memory driver");
    return create_with(name, fapl);
}

namespace {

bool disk_full(int err) { return err == ENOSPC || err == EDQUOT || err == EFBIG; }

}  // namespace

/// One line for a save that failed: the file, the reason, and what the user still has.
std::runtime_error write_failure(const std::string& path, int err, const std::string& detail) {
    std::string text = "cannot write " + path + ": " + (disk_full(err) ? "no space left on device" : detail);
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) text += " (" + path + " still holds the previous save)";
    return std::runtime_error(text);
}

void publish_atomically(const std::string& path,
                        const std::function<void(const std::string& tmp_path)>& write) {
    const std::string tmp = path + ".tmp";
    auto remove_tmp = [&] {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
    };
    try {
        write(tmp);
    } catch (const InputError&) {
        remove_tmp();
        throw;
    } catch (const std::invalid_argument&) {
        remove_tmp();
        throw;
    } catch (const Hdf5Error& e) {
        remove_tmp();
        throw write_failure(path, e.sys_errno(), e.what());
    } catch (const std::system_error& e) {
        remove_tmp();
        throw write_failure(path, e.code().value(), e.what());
    } catch (...) {
        remove_tmp();
        throw;
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        remove_tmp();
        throw InputError("output", path, "a writable location (renaming " + tmp + " onto it: " +
                                             ec.message() + ")");
    }
}

void write_file_bytes(const std::string& path, std::span<const unsigned char> bytes, const std::string& output) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0)
        throw InputError("output", output, "a writable location (creating " + path + ": " + std::strerror(errno) + ")");
    auto fail_with_errno = [&](const char* doing) {
        const int err = errno;
        ::close(fd);
        throw std::system_error(err, std::generic_category(), doing + (" " + path));
    };
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;  // a signal that only raised a flag
        if (n < 0) fail_with_errno("writing");
        done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0) fail_with_errno("syncing");
    if (::close(fd) != 0) throw std::system_error(errno, std::generic_category(), "closing " + path);
}

void write_h5_image(const std::string& tmp, const std::string& output, const std::function<void(const File&)>& write) {
    MemoryImage image;
    std::size_t size = 0;
    {
        File f = File::create_in_memory(tmp, image);
        write(f);
        // The image's size is the allocated end of the file; the driver's buffer is rounded
        // up to its increment. Flushed first: a flush allocates the last metadata.
        check(H5Fflush(f.id(), H5F_SCOPE_LOCAL), "flushing '" + tmp + "'");
        size = static_cast<std::size_t>(check(H5Fget_file_image(f.id(), nullptr, 0), "sizing '" + tmp + "'"));
        f.close();
    }
    // Past `size` the buffer must be the driver's zero padding: anything else would be
    // metadata the close wrote after the flush, and a file cut there would be corrupt.
    if (image.bytes.size() < size ||
        std::any_of(image.bytes.begin() + static_cast<std::ptrdiff_t>(size), image.bytes.end(),
                    [](unsigned char b) { return b != 0; }))
        throw Hdf5Error("building '" + tmp + "' in memory: the closed file does not end where HDF5 said");
    write_file_bytes(tmp, std::span<const unsigned char>(image.bytes.data(), size), output);
}

void publish_h5_atomically(const std::string& path, const std::function<void(const File&)>& write) {
    publish_atomically(path, [&](const std::string& tmp) { write_h5_image(tmp, path, write); });
}

}  // namespace rocksweep::h5
