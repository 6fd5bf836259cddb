#include "forces/membrane_ahead.h"

#include <algorithm>
#include <cstring>

#include "sim/cloth.h"
#include "sim/stage_profile.h"

namespace weft {

MembraneAhead::Key MembraneAhead::keyOf(const MembraneElement& element, const Vec3& xa, const Vec3& xb,
                                        const Vec3& xc) {
  Key key;
  const Vec3* corners[3] = {&xa, &xb, &xc};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) key.values[3 * i + k] = (*corners[i])[k];
  }
  for (int k = 0; k < 3; ++k) {
    key.values[9 + k] = element.ru[k];
    key.values[12 + k] = element.rv[k];
  }
  key.values[15] = element.restArea;
  return key;
}

void MembraneAhead::evaluate(const Cloth& cloth, HessianMode mode, int threads, StageProfile& profile) {
  // Timed as the membrane stage it stands in for (the next step's evaluation, done early).
  StageTimer timer(profile, "membrane");
  const int count = static_cast<int>(cloth.membranes.size());
  const std::vector<Vec3>& x = cloth.mesh.x;
  const PreparedElasticity law = prepareElasticity(cloth.material.elasticity);
  keys_.resize(count);
  contributions_.resize(count);
#pragma omp parallel for num_threads(std::max(1, threads)) schedule(static)
  for (int t = 0; t < count; ++t) {
    const MembraneElement& element = cloth.membranes[t];
    const Vec3& xa = x[element.v[0]];
    const Vec3& xb = x[element.v[1]];
    const Vec3& xc = x[element.v[2]];
    keys_[t] = keyOf(element, xa, xb, xc);
    evaluateMembrane(element, law, xa, xb, xc, mode, contributions_[t]);
  }
  mode_ = mode;
  law_ = cloth.material.elasticity;
  valid_ = true;
}

std::size_t MembraneAhead::heapBytes() const {
  return keys_.capacity() * sizeof(Key) + contributions_.capacity() * sizeof(MembraneContribution);
}

void MembraneAhead::clear() { valid_ = false; }

bool MembraneAhead::serves(const ElasticitySettings& law) const { return valid_ && law == law_; }

const MembraneContribution* MembraneAhead::find(int t, const MembraneElement& element, const Vec3& xa,
                                                const Vec3& xb, const Vec3& xc) const {
  if (t < 0 || t >= static_cast<int>(keys_.size())) return nullptr;
  const Key key = keyOf(element, xa, xb, xc);
  // Bit for bit (memcmp, not ==): -0.0 and 0.0, which == takes as equal, may evaluate apart.
  if (std::memcmp(key.values.data(), keys_[t].values.data(), sizeof(key.values)) != 0) return nullptr;
  return &contributions_[t];
}

}  // namespace weft
