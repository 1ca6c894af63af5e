// Reading a file the script names, the one way every layer does it: only
// regular files (never /proc, devices, FIFOs or folders), and never more
// than a stated number of bytes, checked before anything is allocated.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace glimmer {

// The largest input file any reader accepts (images, volumes, models).
constexpr std::size_t kMaxInputFileBytes = std::size_t(1) << 30;

// False with `error` ("is not a regular file", "cannot open", ...) unless
// `path` names a regular file (symlinks followed). Reads nothing.
bool checkRegularFile(const std::string& path, std::string& error);

// Reads all of `path` into `out`. False with a one-line `error` (without the
// path) when it is not a regular file, cannot be read, or is larger than
// `maxBytes`. Opening never blocks (a FIFO is refused, not waited on).
bool readRegularFile(const std::string& path, std::size_t maxBytes, std::string& out, std::string& error);
bool readRegularFile(const std::string& path, std::size_t maxBytes, std::vector<std::uint8_t>& out,
                     std::string& error);

}  // namespace glimmer
