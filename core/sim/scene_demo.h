#pragma once
// The "demo" scene, made for trade shows: a breathing six-petal flower turning slowly at the centre,
// six moons orbiting the other way between its petals, and a spiky star-shaped wall around it all
// counter-rotating, swept by a "lighthouse" arc. On G1 the petal tips carry the specular flag and
// the lighthouse arc the ambient-light flag, so colouring by flag shows them too. Deterministic.
#include <cstdint>

#include "core/sim/scene.h"

namespace ydscope {

class DemoScene final : public Scene {
 public:
  explicit DemoScene(std::uint64_t seed) : seed_(seed) {}
  SceneReturn sample(double angle_deg, std::int64_t t_ns) const override;
  std::string_view name() const override { return "demo"; }

 private:
  std::uint64_t seed_;
};

}  // namespace ydscope
