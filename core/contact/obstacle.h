#pragma once
// An obstacle or tool in the world: a closed triangle mesh in its body frame, moved rigidly —
// held still, along a kinematic script, or as a dynamic rigid body pushed by gravity and by the
// cloth. Contact sees it through its world vertices at the start (x0) and end (x1) of the step.
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "collision/collision_mesh.h"
#include "rigid/kinematic_script.h"
#include "rigid/rigid_body.h"
#include "rigid/rigid_pose.h"
#include "rigid/sharp_tags.h"
#include "scene/contact_spec.h"
#include "util/types.h"

namespace weft {

struct Obstacle {
  std::string name;
  ObstacleMotion motion = ObstacleMotion::Static;
  std::vector<Vec3> bodyVertices;   // in the body frame (origin = the body's reference point)
  CollisionMesh topology;
  std::vector<char> sharpVertex;    // per vertex: tagged sharp
  std::vector<char> sharpEdge;      // per CollisionMesh edge: tagged sharp
  double friction = 0.3;
  RigidBody body;                   // current pose and velocity; infinitely heavy unless dynamic
  KinematicScript script;           // kinematic: the path (keyframes or a constant velocity)
  // The step in progress: the pose at its start and its (candidate) end, and the world vertices.
  RigidPose start, end;
  double stepDuration = 0.0;  // s
  std::vector<Vec3> x0, x1;
};

// Marks the features `tags` names sharp and every other one not (the tags' vertex ids are the
// obstacle's; an edge names its two vertices). Ids out of range are a programming error.
void markSharpFeatures(const SharpTags& tags, Obstacle& obstacle);

// Loads or generates the mesh, its sharp tags and mass properties, and places it. Throws
// InputError naming the scene file and the obstacle's JSON field for a bad mesh or tag file.
Obstacle buildObstacle(const ObstacleSpec& spec, const std::string& sceneFile, int index);

// The sharp tags buildObstacle gives `spec`: its inline "sharp_tags", else its tags file, else
// none; read as strictly (throws InputError as buildObstacle does).
SharpTags sharpTagsOfSpec(const ObstacleSpec& spec, const std::string& sceneFile, int index);
// The tags `obstacle` has now (what markSharpFeatures marked), in canonical form.
SharpTags sharpTagsOf(const Obstacle& obstacle);

// Starts a step from time t of length h: the start pose is the current one; the candidate end pose
// is the script's (kinematic), the current one (static), or where the current velocity takes it
// after gravity (dynamic). Fills x0 and x1.
void beginObstacleStep(Obstacle& obstacle, double t, double h, const Vec3& gravity);
// Starts a step of length h that takes the obstacle from its current pose to `end` instead of where
// its motion would (a kinematic tool dragged by hand in the editor). endObstacleStep then commits
// it as it commits a scripted step: the velocity recorded is that of this displacement, which is
// also the straight-line sweep CCD and the sharp-contact records see. Fills x0 and x1.
void beginObstacleStepTo(Obstacle& obstacle, const RigidPose& end, double h);
// Commits the end pose (a dynamic body's velocities include every contact impulse).
void endObstacleStep(Obstacle& obstacle);

// Contact response (contact_body.h). Inverse effective mass along the unit n at a world point on
// the body at the start of the step; 0 unless dynamic.
double obstacleInverseMass(const Obstacle& obstacle, const Vec3& point, const Vec3& n);
// Applies an impulse at a world point (start of the step) to a dynamic body and moves its candidate
// end pose and x1 accordingly; no effect on static and kinematic obstacles.
void applyObstacleImpulse(Obstacle& obstacle, const Vec3& impulse, const Vec3& point, double h);
// Sets a dynamic body's velocities (impact zones move it with its zone) and its candidate end pose
// and x1 accordingly; no effect on static and kinematic obstacles.
void setObstacleVelocity(Obstacle& obstacle, const Vec3& linearVelocity, const Vec3& angularVelocity, double h);
// Where the body's motion over the step carries a point that is at `pointAtStart` at the start.
Vec3 carriedByObstacle(const Obstacle& obstacle, const Vec3& pointAtStart);

bool isSharpVertex(const Obstacle& obstacle, int vertex);
bool isSharpEdge(const Obstacle& obstacle, int collisionEdge);

}  // namespace weft
