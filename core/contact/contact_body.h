#pragma once
// What the contact passes see of a cloth or an obstacle during one step: its collision topology,
// where its vertices are at the start (x0) and end (x1) of the step, and how it answers an impulse.
//
// Contact works on the candidate end-of-step state that the integrator produced (Bridson, Fedkiw &
// Anderson 2002, §6): every vertex moves on a straight line from x0 to x1 = x0 + h v. The passes
// change velocities by impulses and keep x1 in step with them.
//   - A cloth vertex has a lumped mass (a pinned vertex counts as infinitely heavy).
//   - An obstacle answers as one rigid body: a static or kinematic one is infinitely heavy, a
//     dynamic one takes the impulse at the contact point (linear and angular), and its whole end
//     pose, hence every x1 of its mesh, moves.
#include <vector>

#include "collision/candidate_pairs.h"
#include "collision/collision_mesh.h"
#include "util/types.h"

namespace weft {

struct Obstacle;

struct ContactBody {
  const CollisionMesh* topology = nullptr;
  const std::vector<Vec3>* x0 = nullptr;  // start of the step
  std::vector<Vec3>* x1 = nullptr;        // candidate end of the step (changed by impulses)
  std::vector<Vec3>* v = nullptr;         // cloth: vertex velocities; obstacle: null
  const std::vector<double>* inverseMass = nullptr;  // cloth: per vertex, 0 when pinned
  Obstacle* obstacle = nullptr;           // obstacle: the rigid body behind the mesh
  double friction = 0.0;                  // Coulomb coefficient against cloth (obstacle), or cloth on cloth
  SweptMesh swept;                        // boxes and BVH for the broad phase

  bool isCloth() const { return obstacle == nullptr; }
};

// One side of a contact: a point on a body, as a weighted sum of up to three of its vertices
// (a vertex: 1 weight; a point on an edge: 2; a point in a triangle: 3).
struct ContactSide {
  int body = 0;
  int count = 0;
  int vertex[3] = {0, 0, 0};
  double weight[3] = {0.0, 0.0, 0.0};
};

Vec3 sidePosition(const std::vector<ContactBody>& bodies, const ContactSide& side, bool atEnd);
// Velocity over the step: (x1 - x0) / h, which for a cloth equals its velocity.
Vec3 sideVelocity(const std::vector<ContactBody>& bodies, const ContactSide& side, double h);
// Inverse of the effective mass the side offers to an impulse along the unit direction n.
double sideInverseMass(const std::vector<ContactBody>& bodies, const ContactSide& side, const Vec3& n);
// Applies the impulse (N s) to the side's point; keeps x1 = x0 + h v.
void applySideImpulse(std::vector<ContactBody>& bodies, const ContactSide& side, const Vec3& impulse, double h);

}  // namespace weft
