#include "serve/random_token.h"

#include <sys/random.h>

#include <cerrno>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace glimmer {
namespace {

std::vector<std::uint8_t> randomBytes(std::size_t n) {
    std::vector<std::uint8_t> out(n);
    std::size_t got = 0;
    while (got < n) {
        const ssize_t r = getrandom(out.data() + got, n - got, 0);
        if (r < 0) {
            if (errno == EINTR) continue;
            throw std::runtime_error("no randomness from the kernel (getrandom)");
        }
        got += std::size_t(r);
    }
    return out;
}

}  // namespace

std::string randomToken(int bytes) {
    static const char* kHex = "0123456789abcdef";
    std::string out;
    for (std::uint8_t b : randomBytes(std::size_t(bytes))) {
        out += kHex[b >> 4];
        out += kHex[b & 15];
    }
    return out;
}

std::string randomClassCode() {
    static const std::string kAlphabet = "23456789ABCDEFGHJKMNPQRSTUVWXYZ";  // 31 letters
    std::string out;
    // 256 % 31 != 0: bytes at or above 248 are drawn again, so every letter is equally likely.
    while (out.size() < 9) {
        for (std::uint8_t b : randomBytes(16)) {
            if (out.size() == 4) out += '-';
            if (out.size() >= 9) break;
            if (b < 248) out += kAlphabet[b % 31];
        }
    }
    return out;
}

}  // namespace glimmer
