#pragma once
// Mass, centre of mass and inertia of a solid of uniform density bounded by a closed triangle mesh.
//
// Method: the divergence theorem turns each volume integral (of 1, x, x x^T) into a sum over the
// surface triangles. Concretely, every triangle (a, b, c) spans a signed tetrahedron with a
// reference point r, of signed volume det[a-r, b-r, c-r] / 6 (positive when the triangle faces away
// from r); over a closed surface the signed tetrahedra add up to the solid exactly, whatever r is
// (inside or not). Per tetrahedron, with p = a-r, q = b-r, s = c-r, d = det[p, q, s]:
//   volume          V  = d / 6
//   first moment    ∫x = d / 24 (p + q + s)
//   second moment ∫xxᵀ = d / 120 (ppᵀ + qqᵀ + ssᵀ + (p+q+s)(p+q+s)ᵀ)
// (the last from ∫u² = 1/60, ∫uv = 1/120 over the unit tetrahedron, mapped by [p q s]).
// The inertia tensor about the centre of mass c is ρ (tr(C) I - C), with C = ∫(x-c)(x-c)ᵀ.
// The same integrals appear as face sums in B. Mirtich, "Fast and accurate computation of
// polyhedral mass properties", J. Graphics Tools 1(2), 1996, and in D. Eberly, "Polyhedral Mass
// Properties (Revisited)", Geometric Tools, 2002.
//
// r is the centre of the mesh's bounding box rather than the origin: a mesh placed far from its
// origin would otherwise lose digits when C is shifted to the centre of mass.
#include <string>

#include "rigid/triangle_mesh.h"

namespace weft {

struct MassProperties {
  double volume = 0.0;               // m^3
  double mass = 0.0;                 // kg
  Vec3 centreOfMass = Vec3::Zero();  // m, body frame
  Mat3 inertia = Mat3::Zero();       // kg m^2, about the centre of mass, along the body axes
};

// The volume enclosed by a closed mesh: positive when its triangles face outward, negative when
// the whole mesh is turned inside out. Meaningless for an open mesh (check closedSurfaceProblems).
double signedVolume(const TriangleMesh& mesh);

// For a closed, outward mesh and a density in kg/m^3. An inward-facing (negative volume) or empty
// mesh is rejected with an InputError naming `meshName` (a file, or the shape that made it), since
// its inertia would be negative.
MassProperties computeMassProperties(const TriangleMesh& mesh, double density, const std::string& meshName);

// Moves the mesh so that its centre of mass (uniform density) is the body-frame origin, as a
// RigidBody requires. Returns the old centre of mass, i.e. where the new origin sits in the old
// frame: a pose given for the old origin moves to the new one by adding R * (returned vector).
// Rejects an inward mesh like computeMassProperties.
Vec3 recentreAtCentreOfMass(TriangleMesh& ioMesh, const std::string& meshName);

}  // namespace weft
