#pragma once
// Patching one transfer of the multigrid hierarchy (fine level -> next coarser) after the fine
// operator's pattern changed locally, instead of building it anew: what a tear or a cut needs.
//
// A tear appends vertices and couples them to their neighbours (SystemMatrix::growPattern); the
// couplings it breaks stay in the pattern as explicit zeros. Far from the crack nothing changed,
// so the aggregates there, the rows of P and A P, the coarse operator's rows and the index lists
// that fill them (AmgHierarchy::Level) are still right, only shifted in their arrays. The patch:
//   1. finds the fine rows whose pattern changed (compared with the pattern before; new rows) and
//      the `seeds` (coarse vertices of the level above whose aggregate changed: they stand for
//      something else now);
//   2. dissolves every aggregate holding one of them and aggregates the freed vertices again
//      (amg_aggregation.h: the passes of the whole-level aggregation restricted to them, on this
//      step's values, so a vertex cut off by the crack no longer shares its old neighbours'
//      aggregate); new aggregates reuse the dissolved ids first, and if fewer are needed, the
//      highest ids are moved into the holes (no empty coarse vertex);
//   3. derives again P's rows that see a vertex whose aggregate id changed or whose row changed,
//      A P's rows that see such a P row, and the coarse rows fed by either, with the code a build
//      uses (amg_transfer_pattern.h); every other row is copied with its index lists shifted by how
//      far its storage moved;
//   4. reports the coarse vertices whose aggregate changed, to seed the patch of the next level.
// Why the coarse levels are built anew below AmgSettings::patchMinimumVertices: measured at 64²
// with 15 tears spread over the sheet, the finest level's patch frees 248 of 4,125 vertices, but
// the next level (698 vertices, ~9 per aggregate, ~20 couplings per row) would free 413 to 431 of
// them, with or without the seeds: a coarse vertex's aggregate spans so much of the sheet that a
// few tears touch most of them. Its build costs 1.6 ms there.
// Every step is serial and in a fixed order: a patched hierarchy is the same for any thread
// count. It need not equal a fresh build (the aggregates away from the change are those of the
// last build, as between topology changes anyway); the numbers (smoothing, Galerkin products)
// are then redone as every step redoes them. omega is kept (any omega gives a valid P).
#include <vector>

#include "integrate/amg_hierarchy.h"

namespace weft {

struct TransferPatch {
  int freedVertices = 0;         // fine vertices aggregated again
  BlockPattern previousCoarse;   // the coarse operator's pattern before the patch (the next level's "before")
  std::vector<int> coarseSeeds;  // coarse vertices whose set of fine vertices changed, increasing
};

// Patches `fine`'s aggregates, P, A P and index lists and `coarse`'s operator pattern (values left
// for the numeric setup) after fine.A's pattern changed from `previousFine`; `seeds` are fine
// vertices to aggregate again although their rows did not change. Returns false, with nothing
// changed, when the patch would free more than settings.patchLimit of the fine vertices or the
// coarsening would stall: the caller builds this transfer anew.
// `product` / `previousProduct`: the operator whose product with P makes A P (the finest level's
// AmgHierarchy::setFinestProductOperator), as it is and as its pattern was; null: fine.A.
bool patchTransfer(AmgHierarchy::Level& fine, AmgHierarchy::Level& coarse, const BlockPattern& previousFine,
                   const std::vector<int>& seeds, const AmgSettings& settings, TransferPatch& out,
                   const BlockSparseMatrix* product = nullptr, const BlockPattern* previousProduct = nullptr);

}  // namespace weft
