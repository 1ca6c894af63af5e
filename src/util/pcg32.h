// PCG32 (O'Neill, pcg-random.org, the "minimal C" variant): a tiny generator
// whose stream is the same on every platform and standard library, unlike
// std::rand or the std distributions. Used wherever Glimmer makes
// "random" data that tests and reference pictures must reproduce.
#pragma once
#include <cstdint>

namespace glimmer {

class Pcg32 {
public:
    // `sequence` picks one of 2^63 independent streams; the default is PCG's own.
    explicit Pcg32(std::uint64_t seed, std::uint64_t sequence = 721347520444481703ULL) : inc_((sequence << 1u) | 1u) {
        next();
        state_ += seed;
        next();
    }
    std::uint32_t next() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    // Uniform in [0, 1).
    float unit() { return float(next() >> 8) * (1.f / 16777216.f); }
    // Uniform in [-1, 1).
    float symmetric() { return 2.f * unit() - 1.f; }

private:
    std::uint64_t state_ = 0;
    std::uint64_t inc_;
};

}  // namespace glimmer
