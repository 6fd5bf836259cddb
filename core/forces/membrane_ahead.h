#pragma once
// The next step's membrane stage, evaluated at the end of this one: every triangle's contribution
// (energy, stress, force, Hessian) at the positions the next step starts from, so that the tear
// stage reads its stresses instead of evaluating the membrane a second time, and the next step's
// assembly takes each contribution as it stands.
//
// Why: a tearing cloth evaluated its membrane twice per step at the same positions, once in the
// tear stage (the stress that tears, at the end of the step) and once at the start of the next
// step (the forces and Hessian of the linearized solve, at those same positions): at 64^2 the
// tear stage's copy was a third of its cost.
//
// A contribution is reused only when it is exactly what an evaluation would give: the same
// elasticity settings, the same Hessian mode, and for the triangle the same rest data and the
// same three positions, bit for bit. Anything else (a pin script or the editor moved a vertex, a
// tear rebuilt the triangle, a live edit changed the material) is evaluated afresh, so results
// never depend on whether the cache was used.
#include <array>
#include <cstddef>
#include <vector>

#include "forces/membrane.h"
#include "material/elasticity.h"
#include "util/types.h"

namespace weft {

struct Cloth;
struct StageProfile;

class MembraneAhead {
 public:
  // Every triangle of the cloth at its current positions, in `mode` (threads: as the elastic
  // stage's, the results do not depend on it).
  void evaluate(const Cloth& cloth, HessianMode mode, int threads, StageProfile& profile);
  // Nothing is reused until the next evaluate.
  void clear();
  // Whether the cache holds contributions of this law (checked once per evaluation, not per
  // triangle), and the Hessian mode they were evaluated in (their stress, energy and force do not
  // depend on it).
  bool serves(const ElasticitySettings& law) const;
  HessianMode mode() const { return mode_; }
  // Triangle t's contribution when the cache holds it for exactly this element at these
  // positions; null otherwise. Call only where serves() holds.
  const MembraneContribution* find(int t, const MembraneElement& element, const Vec3& xa, const Vec3& xb,
                                   const Vec3& xc) const;
  std::size_t heapBytes() const;

 private:
  struct Key {
    std::array<double, 16> values;  // the three positions, r_u, r_v and the rest area
  };
  static Key keyOf(const MembraneElement& element, const Vec3& xa, const Vec3& xb, const Vec3& xc);

  bool valid_ = false;
  HessianMode mode_ = HessianMode::None;
  ElasticitySettings law_;
  std::vector<Key> keys_;
  std::vector<MembraneContribution> contributions_;
};

// util/heap_bytes.h, for the world's per-cloth vector of these.
inline std::size_t heapBytes(const MembraneAhead& ahead) { return ahead.heapBytes(); }

}  // namespace weft
