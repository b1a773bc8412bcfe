#include "core/sim/scene.h"

#include <cmath>

#include "core/sim/scene_booth.h"
#include "core/sim/scene_demo.h"
#include "core/sim/scene_room.h"

namespace ydscope {

std::unique_ptr<Scene> make_scene(std::string_view name, std::uint64_t seed) {
  if (name == "room") return std::make_unique<RoomScene>(seed);
  if (name == "demo") return std::make_unique<DemoScene>(seed);
  if (name == "booth") return std::make_unique<BoothScene>(seed);
  return nullptr;
}

std::string_view scene_names() { return "room, demo, booth"; }

double hash_unit(std::uint64_t seed, std::int64_t a, std::int64_t b) {
  std::uint64_t z = seed ^ (static_cast<std::uint64_t>(a) * 0x9E3779B97F4A7C15ULL) ^
                    (static_cast<std::uint64_t>(b) * 0xC2B2AE3D27D4EB4FULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

double hash_normal(std::uint64_t seed, std::int64_t a, std::int64_t b) {
  // Sum of four uniforms (Irwin-Hall), scaled to unit deviation: cheap and bounded (|x| < 3.5).
  double sum = 0.0;
  for (std::int64_t k = 0; k < 4; ++k) sum += hash_unit(seed + static_cast<std::uint64_t>(k) * 7919u, a, b);
  return (sum - 2.0) * std::sqrt(3.0);
}

}  // namespace ydscope
