#pragma once
// The "demo" scene, made for trade shows: a breathing six-petal flower turning slowly at the centre,
// five moons orbiting the other way between its petals, and a spiky star-shaped wall around it all
// counter-rotating, swept by a "lighthouse" arc. On G1 the petal tips carry the specular flag and
// the lighthouse arc the ambient-light flag, so colouring by flag shows them too. Deterministic.
#include <array>
#include <cstdint>

#include "core/sim/scene.h"

namespace ydscope {

class DemoScene final : public Scene {
 public:
  explicit DemoScene(std::uint64_t seed) : seed_(seed) {}
  SceneReturn sample(double angle_deg, std::int64_t t_ns) const override;
  std::string_view name() const override { return "demo"; }

  static constexpr int kMoons = 5;  // not 6: the moons must not line up with the six petals

 private:
  struct Moons {
    std::int64_t ms = -1;
    std::array<double, 2 * kMoons> xy{};
  };
  // Moon positions move on a 1 ms clock; the last set is cached so a lap does not redo the
  // trigonometry per sample. The result stays a function of (angle, time) alone.
  const Moons& moons_at(std::int64_t t_ns) const;

  std::uint64_t seed_;
  mutable Moons moons_;
};

}  // namespace ydscope
