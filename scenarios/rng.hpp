// A small seeded random source (SplitMix64) whose sequence is the same on
// every platform and standard library, so a scenario with a seed behaves the
// same in CI and on a laptop. std::uniform_*_distribution would not promise that.
#pragma once

#include <cstdint>

namespace slmp::scenarios {

class Rng {
public:
    explicit Rng(std::uint64_t seed = 1) : state_(seed) {}

    // A seed for the n-th independent stream of a scenario (each fault, each
    // random walk has its own, so adding one does not change the others).
    static std::uint64_t stream(std::uint64_t seed, std::uint64_t n) { return Rng(seed ^ (0x9E3779B97F4A7C15ull * (n + 1))).next(); }

    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1).
    double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    // Uniform in [low, high].
    double between(double low, double high) { return low + (high - low) * unit(); }
    // Uniform integer in [0, n).
    std::uint64_t below(std::uint64_t n) { return n == 0 ? 0 : next() % n; }

private:
    std::uint64_t state_;
};

}  // namespace slmp::scenarios
