// Secrets of `glimmer serve`: the tokens in a student's link and the
// teacher's, from the kernel's random source (getrandom), never from a
// seeded generator a student could replay.
#pragma once
#include <string>

namespace glimmer {

// `bytes` random bytes as lowercase hex (16 bytes: 128 bits, 32 characters).
// Throws std::runtime_error when the kernel gives no randomness.
std::string randomToken(int bytes = 16);

// A class code to type: 8 characters from an alphabet without look-alikes
// (no 0/O, 1/I/L), as "K7QX-M9WP". A code only lets a student join once
// under a name not taken; requests are rate-limited (serve_limits.h).
std::string randomClassCode();

}  // namespace glimmer
