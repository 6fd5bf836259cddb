#include "sim/health_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "contact/obstacle.h"
#include "sim/world.h"

namespace weft {
namespace {

constexpr double kMaxStrain = 10.0;              // principal Green strain: a stretch of 360 %
constexpr double kEnergyGrowth = 10.0;           // x the energy scale
constexpr int kUnresolvedContactSteps = 5;       // ... out of the last kContactWindow steps
constexpr std::int64_t kContactWindow = 100;
constexpr int kFailedSolveSteps = 3;             // in a row
constexpr int kUnconvergedNewtonSteps = 3;       // in a row
constexpr double kNewtonProgress = 0.1;          // its last change over its first, at most
constexpr double kSpeedFloor = 100.0;            // m/s, added to 10 x what the inputs can give

std::string format(const char* pattern, double a, double b) {
  char text[320];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

double totalEnergy(const WorldMetrics& m) { return m.kineticEnergy + m.elasticEnergy + m.gravityEnergy; }

double totalMass(const World& world) {
  double mass = 0.0;
  for (int c = 0; c < world.clothCount(); ++c) {
    for (double m : world.cloth(c).mass) mass += m;
  }
  for (int i = 0; i < world.obstacleCount(); ++i) {
    if (world.obstacle(i).motion == ObstacleMotion::Dynamic) mass += world.obstacle(i).body.mass;
  }
  return mass;
}

// The fastest a scripted input moves: pin scripts and obstacle keyframes from their keys, wind
// from its velocity. Kinematic bodies' current speeds are added at each check.
double scriptedSpeed(const Scene& scene) {
  double speed = scene.stages.wind ? scene.forces.wind.velocity.norm() * (1.0 + scene.forces.wind.gustAmplitude) : 0.0;
  for (const ClothSpec& cloth : scene.cloths) {
    for (const PinGroup& pins : cloth.pins) {
      for (std::size_t k = 1; k < pins.script.size(); ++k) {
        const double dt = pins.script[k].time - pins.script[k - 1].time;
        if (dt > 0.0) speed = std::max(speed, (pins.script[k].offset - pins.script[k - 1].offset).norm() / dt);
      }
    }
  }
  for (const ObstacleSpec& obstacle : scene.obstacles) {
    speed = std::max(speed, obstacle.velocity.norm());
    for (std::size_t k = 1; k < obstacle.keyframes.size(); ++k) {
      const double dt = obstacle.keyframes[k].time - obstacle.keyframes[k - 1].time;
      if (dt > 0.0) speed = std::max(speed, (obstacle.keyframes[k].translate - obstacle.keyframes[k - 1].translate).norm() / dt);
    }
  }
  return speed;
}

bool feedsEnergy(const Scene& scene) {
  if (scene.stages.wind && scene.forces.wind.velocity.squaredNorm() > 0.0) return true;
  for (const ClothSpec& cloth : scene.cloths) {
    for (const PinGroup& pins : cloth.pins) {
      if (!pins.script.empty()) return true;
    }
  }
  return std::any_of(scene.obstacles.begin(), scene.obstacles.end(),
                     [](const ObstacleSpec& o) { return o.motion == ObstacleMotion::Kinematic; });
}

// Surface speed of the kinematic obstacles now: |v| + |w| r.
double kinematicSpeed(const World& world) {
  double speed = 0.0;
  for (int i = 0; i < world.obstacleCount(); ++i) {
    const Obstacle& o = world.obstacle(i);
    if (o.motion != ObstacleMotion::Kinematic) continue;
    double radius = 0.0;
    for (const Vec3& p : o.bodyVertices) radius = std::max(radius, p.norm());
    speed = std::max(speed, o.body.state.linearVelocity.norm() + o.body.state.angularVelocity.norm() * radius);
  }
  return speed;
}

// The fastest cloth vertex or dynamic body; NaN propagates (checked before as non-finite).
double fastest(const World& world) {
  double speed = 0.0;
  for (int c = 0; c < world.clothCount(); ++c) {
    for (const Vec3& v : world.cloth(c).v) speed = std::max(speed, v.norm());
  }
  for (int i = 0; i < world.obstacleCount(); ++i) {
    const Obstacle& o = world.obstacle(i);
    if (o.motion == ObstacleMotion::Dynamic) speed = std::max(speed, o.body.state.linearVelocity.norm());
  }
  return speed;
}

}  // namespace

HealthCheck::HealthCheck(const World& world, std::int64_t frameSteps) : frameSteps_(std::max<std::int64_t>(1, frameSteps)) {
  const Scene& scene = world.scene();
  const WorldMetrics start = world.metrics();
  hasEnergyInput_ = feedsEnergy(scene);
  startEnergy_ = totalEnergy(start);
  gravity_ = scene.stages.gravity ? scene.forces.gravity.norm() : 0.0;
  energyScale_ = std::max({std::abs(start.kineticEnergy) + std::abs(start.elasticEnergy) + std::abs(start.gravityEnergy),
                           totalMass(world) * std::max(gravity_, 1.0) * 1.0, 1e-6});
  inputSpeed_ = scriptedSpeed(scene);
  newtonLimit_ = std::max(1000.0 * scene.solver.newtonTolerance, 1e-3);
  lastUnresolvedSteps_ = world.contactRuns() ? world.contactStats().unresolvedSteps : 0;
  lastLinearFailures_ = world.solverStats().linearSolveFailures;
}

void HealthCheck::fail(const World& world, HealthFailure failure) {
  if (failure_) return;
  failure.step = world.stepCount();
  failure.time = world.time();
  failure_ = std::move(failure);
}

bool HealthCheck::afterStep(const World& world) {
  if (failure_) return false;
  const std::int64_t step = world.stepCount();

  if (world.contactRuns()) {
    const long long unresolved = world.contactStats().unresolvedSteps;
    if (unresolved > lastUnresolvedSteps_) unresolvedSteps_.push_back(step);
    lastUnresolvedSteps_ = unresolved;
    while (!unresolvedSteps_.empty() && unresolvedSteps_.front() <= step - kContactWindow) unresolvedSteps_.pop_front();
    if (static_cast<int>(unresolvedSteps_.size()) >= kUnresolvedContactSteps) {
      fail(world, {0, 0.0, "contact", "contact", double(unresolvedSteps_.size()), double(kUnresolvedContactSteps - 1),
                   format("contact left collisions unresolved in %.0f of the last 100 steps (at most %.0f); "
                          "lower solver.dt or raise solver.substeps (or contact.impact_zone_iterations)",
                          double(unresolvedSteps_.size()), double(kUnresolvedContactSteps - 1))});
      return false;
    }
  }

  const SolverStats& stats = world.solverStats();
  failedSolveRun_ = stats.linearSolveFailures > lastLinearFailures_ ? failedSolveRun_ + 1 : 0;
  lastLinearFailures_ = stats.linearSolveFailures;
  if (failedSolveRun_ >= kFailedSolveSteps) {
    fail(world, {0, 0.0, "linear-solve", "linear solve", double(failedSolveRun_), double(kFailedSolveSteps - 1),
                 format("a linear solve failed (iteration bound or factorization) in %.0f steps in a row (at most %.0f); "
                        "raise solver.linear_solver.max_iterations, use solver.linear_solver.type = cholmod, or lower solver.dt",
                        double(failedSolveRun_), double(kFailedSolveSteps - 1))});
    return false;
  }

  const IntegratorKind integrator = world.scene().solver.integrator;
  const bool newton = integrator == IntegratorKind::Newton || integrator == IntegratorKind::Bdf2Newton;
  // Far from converged: its last iteration still changed the velocity by more than the floor and
  // by more than a tenth of what its first iteration did (it was not getting anywhere). A Newton
  // that cut its change tenfold but stopped at the cap (it converges linearly where contact
  // compresses the cloth, whose Hessian it makes definite) is closer to its solution than the
  // linearized integrator's single iteration, and is not stopped.
  const double limit = std::max(newtonLimit_, kNewtonProgress * stats.lastNewtonFirstChange);
  unconvergedRun_ = newton && !(stats.lastNewtonResidual <= limit) ? unconvergedRun_ + 1 : 0;
  if (unconvergedRun_ >= kUnconvergedNewtonSteps) {
    fail(world, {0, 0.0, "newton", "newton", stats.lastNewtonResidual, limit,
                 format("Newton stopped at its iteration cap with a velocity change of %.3g m/s (limit %.3g m/s: a "
                        "tenth of its first iteration's, at least 1000 x its tolerance) in 3 steps in a row; raise "
                        "solver.newton.max_iterations or lower solver.dt",
                        stats.lastNewtonResidual, limit)});
    return false;
  }

  if (step % frameSteps_ == 0) return checkNow(world);
  return true;
}

bool HealthCheck::checkNow(const World& world) {
  if (failure_) return false;
  const WorldMetrics m = world.metrics();
  if (!m.finite) {
    fail(world, {0, 0.0, "non-finite", "integrate", 0.0, 0.0,
                 "a position or velocity became NaN or infinite; lower solver.dt or raise solver.substeps"});
    return false;
  }
  const double strainLimit = kMaxStrain;
  if (!(m.maxStrain <= strainLimit)) {
    fail(world, {0, 0.0, "strain", "membrane", m.maxStrain, strainLimit,
                 format("a triangle reached a Green strain of %.3g, past %.3g, beyond any fabric; lower solver.dt, raise "
                        "solver.substeps, or check the forces and the mesh's UV scale",
                        m.maxStrain, strainLimit)});
    return false;
  }
  const double speedLimit = 10.0 * (inputSpeed_ + kinematicSpeed(world) + gravity_ * world.time()) + kSpeedFloor;
  const double speed = fastest(world);
  if (!(speed <= speedLimit)) {
    fail(world, {0, 0.0, "speed", "integrate", speed, speedLimit,
                 format("something moves at %.3g m/s, faster than the scene can drive it (limit %.3g m/s); "
                        "lower solver.dt or raise solver.substeps",
                        speed, speedLimit)});
    return false;
  }
  if (!hasEnergyInput_) {
    const double gained = totalEnergy(m) - startEnergy_;
    if (!(gained <= kEnergyGrowth * energyScale_)) {
      fail(world, {0, 0.0, "energy", "integrate", gained, kEnergyGrowth * energyScale_,
                   format("the total energy grew by %.3g J with nothing feeding it (limit %.3g J); "
                          "lower solver.dt, raise solver.substeps, or use solver.integrator = newton",
                          gained, kEnergyGrowth * energyScale_)});
      return false;
    }
  }
  return true;
}

std::string healthWarning(const HealthFailure& failure) {
  std::ostringstream line;
  line << "unhealthy run at step " << failure.step << " (t = " << failure.time << " s), " << failure.stage
       << " stage: " << failure.message;
  return line.str();
}

}  // namespace weft
