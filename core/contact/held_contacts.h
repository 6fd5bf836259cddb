#pragma once
// Contact inside the implicit solve: cloth resting on obstacles and the ground, and two-way
// coupling with dynamic obstacles.
//
// Supports: with a large step, the solve alone moves a cloth resting on a box or a ball as if the
// obstacle were not there (into it), and the contact passes then stop only the vertices that
// touch: the cloth ends stretched between stopped and falling vertices, and the next solve does
// the same again, so a drape over a box corner keeps edges stretched several times over. So a
// vertex that starts the step touching a static or kinematic obstacle or the ground is held
// along the surface normal in the solve (Baraff & Witkin 1998, §5.3 constrain such
// vertices; a stiff normal penalty keeps our solver unchanged): it moves with the surface along
// the normal and freely along it.
//
// Dynamic obstacles:
//
// Why: impulses after the solve (contact_passes.h) exchange only the momentum the cloth's vertices
// carry, and an implicit step gives a light vertex on stiff cloth almost none: the solve moves it
// to equilibrium instead of accelerating it. A ball resting on a sheet, or thrown into one, then
// barely feels the cloth's tension and sinks or flies through it.
//
// So a cloth vertex that ended the previous step touching a dynamic obstacle carries, in the next
// solve, a share of the obstacle's mass moving at the obstacle's velocity there
// (integrator.h HeldVertex): the cloth's stiffness and the obstacle's inertia meet implicitly, as
// if the body were split into point masses glued to the vertices it rests on, and the impulse each
// vertex received is given back to the body with the opposite sign, at the touched point (so the
// body also turns). Momentum is exchanged exactly; a light ball does not bounce off a stiff sheet
// as it would if the body were treated as infinitely heavy within the solve. A vertex that the
// body pulled rather than pushed (the cloth is leaving) is released for the next step. The contact
// passes still run after the solve and keep everything apart.
#include <vector>

#include "contact/contact_body.h"
#include "contact/contact_pairs.h"
#include "contact/near_pairs.h"
#include "integrate/integrator.h"
#include "scene/contact_spec.h"

namespace weft {

struct Cloth;
struct Obstacle;

class HeldContacts {
 public:
  // At the start of a step: the cloth vertices within `reach` of an obstacle's surface or the
  // ground, from the pairs near each other at the start (near_pairs.h, any vertex-face or
  // edge-edge pair), except those released by their last reaction.
  // For a dynamic obstacle every touching pair carries an equal share of its mass, split over the
  // pair's cloth vertices by their weights.
  void collect(const std::vector<ContactBody>& bodies, const std::vector<NearPair>& nearPairs, const GroundSpec* ground,
               const std::vector<int>& bodyToWorldIndex, double reach);
  // Before the integrators: each held vertex's share of its obstacle's mass and the obstacle's
  // velocity there (from its pose now to its predicted end pose). `out` has one list per cloth.
  void prescribe(const std::vector<Cloth>& cloths, const std::vector<Obstacle>& obstacles, double h,
                 std::vector<std::vector<HeldVertex>>& out) const;
  // After the integrators: the obstacles take the opposite of every reaction.
  void applyReactions(const std::vector<Cloth>& cloths, std::vector<Obstacle>& obstacles,
                      const std::vector<std::vector<HeldVertex>>& held, double h);

  std::size_t size() const { return contacts_.size(); }
  std::size_t heapBytes() const;  // util/heap_bytes.h (defined in sim/world_memory.cpp)

 private:
  static constexpr int kGround = -1;
  struct Contact {
    int cloth = 0;
    int vertex = 0;
    int obstacle = 0;                // kGround for the ground plane
    bool sharesMass = false;         // a dynamic obstacle (else a normal support)
    double massFraction = 0.0;       // of the obstacle's mass carried by this vertex
    Vec3 bodyPoint = Vec3::Zero();   // the vertex's position in the obstacle's body frame
    Vec3 bodyNormal = Vec3::Zero();  // outward surface normal there, body frame
  };
  bool wasReleased(int cloth, int vertex) const;  // released_ must be sorted
  void collectGround(const std::vector<ContactBody>& bodies, const GroundSpec& ground,
                     const std::vector<int>& bodyToWorldIndex, double reach);

  std::vector<Contact> contacts_;
  // collect's scratch: one share per (cloth body, vertex, obstacle body) touching, summed over
  // the pairs (weights and weighted normals); each vertex's shares form a list through `next`.
  struct Share {
    int clothBody = 0, vertex = 0, obstacleBody = 0;
    int next = -1;
    double weight = 0.0;
    Vec3 normalSum = Vec3::Zero();
  };
  std::vector<Share> shares_;
  std::vector<std::vector<int>> firstShare_;  // per body, per vertex: its latest share, or -1
  std::vector<int> shareOrder_;
  std::vector<std::pair<int, int>> released_;  // (cloth, vertex) pulled away in the last step
};

}  // namespace weft
