// Writing an output the one way every writer does it: into a temporary file
// beside it, renamed over the output only once complete (issue 30). A full
// disk, a kill or a failed encoder then leaves the last good picture where
// it was, never a truncated one, and no reader ever sees half a file.
//
// Contract:
//   - `path` is replaced whole or not at all. The temporary file
//     ("NAME.glimmer-tmp-PID") is removed on every failure.
//   - An output that exists and is not a regular file (/dev/null, a FIFO,
//     /dev/stdout) is written in place: it cannot be renamed over, and it
//     holds no picture to lose.
//   - Errors are one line without the path's own diagnosis prefix:
//     "cannot write out.png: No space left on device".
#pragma once
#include <cstddef>
#include <functional>
#include <string>

namespace glimmer {

// Calls `write(target, error)` with the file it should create (the
// temporary file, or `path` itself for a special file), then renames it
// over `path`. `write` returns false with `error` set when it fails.
bool writeReplacing(const std::string& path,
                    const std::function<bool(const std::string& target, std::string& error)>& write,
                    std::string& error);

// `size` bytes from `data` as the whole of `path`, the same way.
bool writeBytesReplacing(const std::string& path, const void* data, std::size_t size, std::string& error);

}  // namespace glimmer
