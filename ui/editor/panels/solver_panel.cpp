// Solver: time step, substeps, integrator, linear solver and tolerance, with live readouts of the
// step time per stage, solver iterations and residual, energy and the tear count.
#include <cmath>
#include <string>

#include "editor/scene_edits.h"
#include "scene/preconditioner_names.h"
#include "panels.h"

namespace weft::editor {

namespace {

const char* integratorName(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::LinearizedBackwardEuler: return "linearized_backward_euler";
    case IntegratorKind::Newton: return "newton";
    case IntegratorKind::SymplecticEuler: return "symplectic_euler";
    case IntegratorKind::Bdf2: return "bdf2";
    case IntegratorKind::Bdf2Newton: return "bdf2_newton";
  }
  return "";
}

}  // namespace

void drawSolverPanel(EditorSession& session, PanelState& state) {
  if (!ImGui::Begin("Solver")) {
    ImGui::End();
    return;
  }
  const SolverSpec& solver = session.scene().solver;
  double dt = solver.dt * 1000.0;
  // Every typed value goes to the strict reader, which refuses a bad one with the reason.
  if (numberField("time step (ms)", dt, "%.4g", 120)) session.edit(withTimeStep(session.json(), dt / 1000.0), "time step");
  recordWidget(state, "solver/dt");
  showRefusal(session, "time step");
  int substeps = solver.substeps;
  ImGui::SetNextItemWidth(120);
  if (ImGui::InputInt("substeps", &substeps, 1, 1, ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
    session.edit(withSubsteps(session.json(), substeps), "substeps");
  }
  recordWidget(state, "solver/substeps");
  showRefusal(session, "substeps");
  const char* integrators[] = {"linearized_backward_euler", "newton", "symplectic_euler", "bdf2", "bdf2_newton"};
  const char* current = integratorName(solver.integrator);
  ImGui::SetNextItemWidth(220);
  if (ImGui::BeginCombo("integrator", current)) {
    for (const char* name : integrators) {
      if (ImGui::Selectable(name, std::string(name) == current)) {
        session.edit(withIntegrator(session.json(), name), std::string("integrator ") + name);
      }
    }
    ImGui::EndCombo();
  }
  const char* solverName = solver.linearSolver == LinearSolverKind::Cholmod ? "cholmod" : "cg";
  ImGui::SetNextItemWidth(120);
  if (ImGui::BeginCombo("linear solver", solverName)) {
    for (const char* name : {"cg", "cholmod"}) {
      if (ImGui::Selectable(name, std::string(name) == solverName)) {
        session.edit(withLinearSolverType(session.json(), name), std::string("linear solver ") + name);
      }
    }
    ImGui::EndCombo();
  }
  if (solver.linearSolver == LinearSolverKind::ConjugateGradient) {
    // The speed against accuracy of each: docs/solver.md (amg: linear cost; the lagged Cholesky
    // factors grow as n^1.5; block Jacobi is cheap but slow to converge on stiff fabric).
    const char* preconditioner = preconditionerName(solver.linearPreconditioner);
    ImGui::SetNextItemWidth(170);
    if (ImGui::BeginCombo("preconditioner", preconditioner)) {
      for (const PreconditionerKind kind : kPreconditioners) {
        const char* name = preconditionerName(kind);
        if (ImGui::Selectable(name, std::string(name) == preconditioner)) {
          session.edit(withPreconditioner(session.json(), name), std::string("preconditioner ") + name);
        }
      }
      ImGui::EndCombo();
    }
  }
  double tolerance = solver.linearTolerance;
  if (numberField("CG tolerance", tolerance, "%.2g", 120)) {
    session.edit(withLinearTolerance(session.json(), tolerance), "CG tolerance");
  }
  recordWidget(state, "solver/tolerance");
  showRefusal(session, "CG tolerance");

  ImGui::Separator();
  // The latest step's figures, read from the snapshot: the worker may be stepping.
  const std::shared_ptr<const WorldSnapshot> shown = session.view();
  const double steps = std::max<long long>(shown->stepCount, 1);
  ImGui::Text("mean step time by stage (ms):");
  const StageProfile& profile = shown->profile;
  for (std::size_t i = 0; i < profile.names.size(); ++i) {
    ImGui::Text("  %-22s %8.3f", profile.names[i].c_str(), profile.totalMs[i] / steps);
  }
  const SolverStats& stats = shown->solver;
  ImGui::Text("linear iterations per step %.1f, last residual %.2g", stats.linearIterations / steps,
              stats.lastLinearResidual);
  if (solver.integrator == IntegratorKind::Newton || solver.integrator == IntegratorKind::Bdf2Newton) {
    ImGui::Text("Newton iterations per step %.1f, last residual %.2g m/s", stats.newtonIterations / steps,
                stats.lastNewtonResidual);
  }
  ImGui::Text("tears %lld", shown->tears);
  // Energies cost a force evaluation: the snapshot refreshes them every few steps.
  ImGui::Text("energy: kinetic %.4g J, elastic %.4g J, gravity %.4g J", shown->metrics.kineticEnergy,
              shown->metrics.elasticEnergy, shown->metrics.gravityEnergy);
  ImGui::End();
}

}  // namespace weft::editor
