#include "util/read_file.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#ifdef __linux__
#include <linux/magic.h>
#include <sys/statfs.h>
#endif
#include <unistd.h>

namespace glimmer {
namespace {

// Kernel file systems whose "regular" files are not data: /proc/self/environ,
// /proc/self/mem and /sys files report S_IFREG with size 0. Linux only: the
// browser build's files live in Emscripten's in-memory file system, which
// has no such files.
bool pseudoFileSystem(int fd) {
#ifndef __linux__
    (void)fd;
    return false;
#else
    struct statfs fs {};
    if (::fstatfs(fd, &fs) != 0) return true;  // cannot tell: refuse
    switch (static_cast<unsigned long>(fs.f_type)) {
    case PROC_SUPER_MAGIC:
    case SYSFS_MAGIC:
    case DEBUGFS_MAGIC:
    case SECURITYFS_MAGIC:
    case CGROUP_SUPER_MAGIC:
    case CGROUP2_SUPER_MAGIC:
    case TRACEFS_MAGIC:
    case BPF_FS_MAGIC:
    case EFIVARFS_MAGIC: return true;
    default: return false;
    }
#endif
}

std::string sizeText(std::size_t bytes) {
    if (bytes >= (std::size_t(1) << 20)) return std::to_string(bytes >> 20) + " MiB";
    return std::to_string(bytes) + " bytes";
}

// Opens without blocking and checks the kind of file behind the descriptor
// (not the name: the name could be swapped between a check and the open).
int openRegular(const std::string& path, struct stat& st, std::string& error) {
    int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        error = std::string("cannot open: ") + std::strerror(errno);
        return -1;
    }
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || pseudoFileSystem(fd)) {
        const bool dir = S_ISDIR(st.st_mode);
        ::close(fd);
        error = dir ? "is a folder, not a file" : "is not a regular file";
        return -1;
    }
    return fd;
}

template <typename Buffer>
bool readAll(const std::string& path, std::size_t maxBytes, Buffer& out, std::string& error) {
    struct stat st {};
    int fd = openRegular(path, st, error);
    if (fd < 0) return false;
    if (st.st_size < 0 || std::size_t(st.st_size) > maxBytes) {
        ::close(fd);
        error = "is larger than " + sizeText(maxBytes);
        return false;
    }
    Buffer data;
    data.resize(std::size_t(st.st_size));
    std::size_t got = 0;
    bool ok = true;
    // A file that grows while it is read is cut at the size it had: the
    // limit above holds whatever happens.
    while (got < data.size()) {
        ssize_t n = ::read(fd, &data[got], data.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            error = std::string("cannot read: ") + std::strerror(errno);
            ok = false;
            break;
        }
        if (n == 0) break;
        got += std::size_t(n);
    }
    ::close(fd);
    if (!ok) return false;
    data.resize(got);
    out = std::move(data);
    return true;
}

}  // namespace

bool checkRegularFile(const std::string& path, std::string& error) {
    struct stat st {};
    int fd = openRegular(path, st, error);
    if (fd < 0) return false;
    ::close(fd);
    return true;
}

bool readRegularFile(const std::string& path, std::size_t maxBytes, std::string& out, std::string& error) {
    return readAll(path, maxBytes, out, error);
}

bool readRegularFile(const std::string& path, std::size_t maxBytes, std::vector<std::uint8_t>& out,
                     std::string& error) {
    return readAll(path, maxBytes, out, error);
}

}  // namespace glimmer
