#include "metrics_writer.h"

#include <cmath>
#include <cstdio>

#include "scene/preconditioner_names.h"

namespace weft::app {

std::string integratorName(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::LinearizedBackwardEuler: return "linearized_backward_euler";
    case IntegratorKind::Newton: return "newton";
    case IntegratorKind::SymplecticEuler: return "symplectic_euler";
    case IntegratorKind::Bdf2: return "bdf2";
    case IntegratorKind::Bdf2Newton: return "bdf2_newton";
  }
  return "unknown";
}

std::string linearSolverName(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::ConjugateGradient: return "cg";
    case LinearSolverKind::Cholmod: return "cholmod";
  }
  return "unknown";
}

std::string hashHex(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

nlohmann::ordered_json runMetrics(const World& world, double wallSeconds) {
  const Scene& scene = world.scene();
  const WorldMetrics m = world.metrics();
  const SolverStats& stats = world.solverStats();
  const StageProfile& profile = world.profile();

  long long vertices = 0;
  long long triangles = 0;
  for (int i = 0; i < world.clothCount(); ++i) {
    vertices += world.cloth(i).vertexCount();
    triangles += world.cloth(i).triangleCount();
  }
  nlohmann::ordered_json stageMs = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < profile.names.size(); ++k) stageMs[profile.names[k]] = profile.totalMs[k];

  // An explicit integrator solves no linear system; saying "none" avoids suggesting that the
  // configured solver was exercised.
  const bool explicitIntegrator = scene.solver.integrator == IntegratorKind::SymplecticEuler;

  nlohmann::ordered_json j;
  j["scene"] = scene.name;
  j["steps"] = world.stepCount();
  j["sim_time_s"] = world.time();
  j["wall_s"] = wallSeconds;
  j["stages"] = world.stagesRun();
  j["stage_ms"] = stageMs;
  j["vertices"] = vertices;
  j["triangles"] = triangles;
  // A non-finite state has no meaningful strain or energy: the key is left out rather than written
  // as null (what JSON makes of NaN) or as a number that means nothing.
  const auto putFinite = [&j](const char* key, double value) {
    if (std::isfinite(value)) j[key] = value;
  };
  putFinite("max_strain", m.maxStrain);
  putFinite("kinetic_energy", m.kineticEnergy);
  putFinite("elastic_energy", m.elasticEnergy);
  putFinite("gravity_energy", m.gravityEnergy);
  j["finite"] = m.finite;
  j["solver"] = {
      {"integrator", integratorName(scene.solver.integrator)},
      {"linear_solver", explicitIntegrator ? std::string("none") : linearSolverName(scene.solver.linearSolver)},
      {"preconditioner", explicitIntegrator || scene.solver.linearSolver != LinearSolverKind::ConjugateGradient
                             ? std::string("none")
                             : preconditionerName(scene.solver.linearPreconditioner)},
      {"linear_iterations", stats.linearIterations},
      {"last_linear_residual", stats.lastLinearResidual},
      {"max_linear_residual", stats.maxLinearResidual},
      {"newton_iterations", stats.newtonIterations},
      {"last_newton_residual", stats.lastNewtonResidual},
      {"linear_solve_failures", stats.linearSolveFailures},
      {"bdf2_restarts", stats.bdf2Restarts},
  };
  if (world.contactRuns()) {
    const ContactStats& c = world.contactStats();
    const double contactMs = profile.totalWithPrefix("contact_");
    j["collision"] = {
        {"stage_ms", contactMs},
        {"self_collision", scene.contact.self},
        {"proximity_impulses", c.proximityImpulses},
        {"ground_contacts", c.groundContacts},
        {"ccd_collisions", c.ccdCollisions},
        {"ccd_iterations", c.ccdIterations},
        {"impact_zone_steps", c.impactZoneSteps},
        {"impact_zone_rounds", c.impactZoneRounds},
        {"impact_zones", c.impactZones},
        {"unresolved_steps", c.unresolvedSteps},
        {"sharp_contacts", c.sharpContacts},
        {"held_vertices", c.heldVertices},
        {"pair_cache",
         {{"uses", c.pairCache.uses},
          {"served", c.pairCache.served},
          {"full_builds", c.pairCache.fullBuilds},
          {"reanchored_vertices", c.pairCache.reanchoredVertices}}},
    };
  }
  if (world.tearingRuns()) {
    const TearStats& t = world.tearStats();
    nlohmann::ordered_json log = nlohmann::ordered_json::array();
    for (const TearRecord& r : world.tearLog()) {
      log.push_back({{"time_s", r.time},
                     {"cloth", r.cloth},
                     {"position", {r.position.x(), r.position.y(), r.position.z()}},
                     {"rest_position", {r.restPosition.x(), r.restPosition.y()}},
                     {"direction_deg", r.angleDeg},
                     {"alpha_deg", r.alphaDeg},
                     {"from_border", r.ray},
                     {"separation_n_m", r.separation},
                     {"required_n_m", r.required},
                     {"ratio", r.ratio}});
    }
    j["tears"] = t.tears;
    j["tearing"] = {{"stage_ms", profile.totalWithPrefix("tear_")},
                    {"refused", t.refused},
                    {"vertices_searched", t.search.vertices},
                    {"vertices_skipped_by_bound", t.search.skipped},
                    {"lines_evaluated", t.search.linesEvaluated}};
    j["tear_log"] = log;
  }
  j["state_hash"] = hashHex(world.stateHash());
  j["threads"] = scene.solver.threads;
  j["dt"] = scene.solver.dt;
  j["substeps"] = scene.solver.substeps;
  return j;
}

}  // namespace weft::app
