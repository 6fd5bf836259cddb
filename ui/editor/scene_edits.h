#pragma once
// The edits the editor's panels make, as pure functions from a scene's JSON to the edited JSON.
// The panels only decide *which* edit the user asked for; what it means for the file lives here,
// where it is tested without a window. Every function takes the parsed scene too, so an edit of a
// value that the file names by preset ("material": "royal-target") can first write the preset's
// values inline and then change one of them: the file stays self-describing and the preset file
// is never touched.
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace weft::editor {

// Weft angle of cloth `cloth` (degrees from material x).
nlohmann::json withWeftAngle(const nlohmann::json& scene, int cloth, double degrees);

// --- Tear table ------------------------------------------------------------------------------
// The cloth's tear table inline (the parsed one, which may come from the material or a preset),
// so its entries can be edited. A cloth without a table gets a uniform one of `defaultStrength`.
nlohmann::json withInlineTearTable(const nlohmann::json& scene, const Scene& parsed, int cloth,
                                   double defaultStrength = 10.0);
// Entry k of the cloth's table set to `strength` (table units).
nlohmann::json withTearStrength(const nlohmann::json& scene, const Scene& parsed, int cloth, int k, double strength);
// The table resampled to `directions` evenly spaced directions over [0, 180), each value the old
// table's interpolated strength there (adding or removing directions keeps the curve's shape).
nlohmann::json withTearDirections(const nlohmann::json& scene, const Scene& parsed, int cloth, int directions);
// A tear table preset by name (presets/tear_tables/NAME.json), or none: the cloth never tears.
nlohmann::json withTearTablePreset(const nlohmann::json& scene, int cloth, const std::string& name);
nlohmann::json withoutTearTable(const nlohmann::json& scene, const Scene& parsed, int cloth);

// --- Material --------------------------------------------------------------------------------
nlohmann::json withMaterialPreset(const nlohmann::json& scene, int cloth, const std::string& name);
// The cloth's resolved material inline, under its own name, so its numbers can be edited. The
// material's tear table moves to the cloth's "tear_table" if the cloth has none of its own.
nlohmann::json withInlineMaterial(const nlohmann::json& scene, const Scene& parsed, int cloth);
nlohmann::json withAreaDensity(const nlohmann::json& scene, const Scene& parsed, int cloth, double kgPerM2);
nlohmann::json withBendingScale(const nlohmann::json& scene, const Scene& parsed, int cloth, double scale);
nlohmann::json withStiffnessScale(const nlohmann::json& scene, const Scene& parsed, int cloth, double scale);
// One measured coefficient: row -1 is the zero-strain row, rows 0.. the directions at the
// reference stretch; column 0..3 is c11, c12, c22, c33 (N/m).
nlohmann::json withElasticityCoefficient(const nlohmann::json& scene, const Scene& parsed, int cloth, int row,
                                         int column, double value);
// Bending stiffness (N*m): for a measured model, row 0..2 (edge direction 0, 45, 90 deg) and
// column 0..4 (curvature 0, 5, 10, 15, 20 1/m); for a constant model row and column are ignored.
nlohmann::json withBendingStiffness(const nlohmann::json& scene, const Scene& parsed, int cloth, int row, int column,
                                    double value);
// An isotropic membrane (Young's modulus E*h in N/m, Poisson ratio), replacing measured data.
nlohmann::json withIsotropicElasticity(const nlohmann::json& scene, const Scene& parsed, int cloth,
                                       double youngModulus, double poissonRatio);

// --- Scene objects and forces ---------------------------------------------------------------
// A static obstacle of a generated shape ("sphere" or "box", `size` its radius or half extent,
// m) at `position`, named uniquely from `shape`.
nlohmann::json withObstacleAdded(const nlohmann::json& scene, const std::string& shape, const Vec3& position,
                                 double size);
nlohmann::json withoutObstacle(const nlohmann::json& scene, int obstacle);
// A mesh obstacle's sharp tags read from `file` ("sharp_tags", a path relative to the scene's folder).
nlohmann::json withSharpTagsFile(const nlohmann::json& scene, int obstacle, const std::string& file);
// The obstacle's mesh keeps its sharp tags in the scene itself: "sharp_tags": {...} (the tag
// file's form), replacing a file path.
nlohmann::json withSharpTagsInline(const nlohmann::json& scene, int obstacle, const nlohmann::json& tags);
// A copy of cloth `cloth` moved by `offset` (m), named uniquely.
nlohmann::json withClothDuplicated(const nlohmann::json& scene, int cloth, const Vec3& offset);
nlohmann::json withoutCloth(const nlohmann::json& scene, int cloth);  // the last cloth cannot go
nlohmann::json withGravity(const nlohmann::json& scene, const Vec3& gravity);
nlohmann::json withWind(const nlohmann::json& scene, const Vec3& velocity);
nlohmann::json withMassDamping(const nlohmann::json& scene, double perSecond);

// --- Solver and playback ---------------------------------------------------------------------
nlohmann::json withTimeStep(const nlohmann::json& scene, double dt);
nlohmann::json withSubsteps(const nlohmann::json& scene, int substeps);
nlohmann::json withLinearTolerance(const nlohmann::json& scene, double tolerance);
// By the names the scene file uses: "newton", "cg", "gravity"...
nlohmann::json withIntegrator(const nlohmann::json& scene, const std::string& name);
nlohmann::json withLinearSolverType(const nlohmann::json& scene, const std::string& name);
// The CG's preconditioner: "amg" (the default), "lagged_cholesky", "lagged_exact_cholesky", "block_jacobi".
nlohmann::json withPreconditioner(const nlohmann::json& scene, const std::string& name);
nlohmann::json withStage(const nlohmann::json& scene, const std::string& stage, bool runs);

}  // namespace weft::editor
