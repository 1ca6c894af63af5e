#include "util/write_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <sys/stat.h>
#include <unistd.h>

namespace glimmer {

bool writeReplacing(const std::string& path,
                    const std::function<bool(const std::string& target, std::string& error)>& write,
                    std::string& error) {
    struct stat st{};
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        if (S_ISDIR(st.st_mode)) {
            error = "cannot write " + path + ": it is a folder";
            return false;
        }
        return write(path, error);  // a device or FIFO: nothing to replace
    }
    const std::string tmp = path + ".glimmer-tmp-" + std::to_string(::getpid());
    if (!write(tmp, error)) {
        ::unlink(tmp.c_str());
        if (error.empty()) error = "cannot write " + path;
        return false;
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        error = "cannot write " + path + ": " + std::strerror(errno);
        ::unlink(tmp.c_str());
        return false;
    }
    return true;
}

bool writeBytesReplacing(const std::string& path, const void* data, std::size_t size, std::string& error) {
    return writeReplacing(
        path,
        [&](const std::string& target, std::string& why) {
            std::FILE* f = std::fopen(target.c_str(), "wb");
            if (!f) {
                why = "cannot write " + path + ": " + std::strerror(errno);
                return false;
            }
            bool ok = std::fwrite(data, 1, size, f) == size;
            int err = ok ? 0 : errno;
            if (std::fclose(f) != 0 && ok) ok = false, err = errno;  // a full disk shows at the flush
            if (!ok) why = "cannot write " + path + ": " + std::strerror(err ? err : EIO);
            return ok;
        },
        error);
}

}  // namespace glimmer
