// The noise of a ray device's k-th sample (docs/physics.md §10.6): a
// stream of its own, seeded from the device's seed and k, so that a sample
// not taken (nobody reads it) leaves every later one as it would have been.
// ROS-free.
#pragma once

#include <cstdint>

namespace rigid_body_sim::core {

/// The seed of sample k of a device seeded `seed`: SplitMix64's finalizer
/// of seed + (k + 1) × its golden-ratio increment (Steele, Lea and Flood,
/// "Fast splittable pseudorandom number generators", 2014), so that
/// neighbouring k give unrelated streams.
inline std::uint64_t sampleSeed(std::uint64_t seed, std::uint64_t k) {
  std::uint64_t z = seed + (k + 1) * 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31U);
}

}  // namespace rigid_body_sim::core
