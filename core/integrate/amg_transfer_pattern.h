#pragma once
// The symbolic half of one multigrid transfer (fine level -> next coarser): from the fine
// operator's pattern and the aggregates, the patterns of P, A P and the coarse operator
// A_c = P^T A P, and the index lists through which the numeric setup fills them
// (AmgHierarchy::Level). Derived whole for a new hierarchy (AmgHierarchy::coarsen), or in part
// after a local change (amg_patch.h): the rows not marked are copied from the transfer as it was,
// their index lists shifted by how far their storage moved.
//
//   - P's row i: the aggregates of i and of its neighbours in A;
//   - A P's row i: the union of P's rows over i's neighbours;
//   - A_c's row I: the union of A P's rows over the fine vertices i with a block (i, I) in P.
// The products' symbolic phase is Gustavson's (1978): a row's columns are gathered once with a
// marker per column, and the slot of a column in a row is read from a table of positions, not
// searched (measured at 64²: the searches and the sorting of repeated columns were most of a build).
#include <vector>

#include "integrate/amg_hierarchy.h"

namespace weft {

// Which rows to derive; the others are copied from the previous transfer. A row of A P must be
// marked when its own row of A or the P row of any neighbour is; a coarse row when the P or A P row
// of any fine vertex it gathers (before or after the change) is.
struct TransferRows {
  std::vector<char> p;        // per fine vertex
  std::vector<char> product;  // per fine vertex
  std::vector<char> coarse;   // per coarse vertex
};

// A transfer's patterns and index lists as they were before a change (moved out of the levels).
struct PreviousTransfer {
  BlockPattern A;   // the fine operator's pattern
  BlockPattern P, AP, Ac;
  std::vector<int> tentativeSlots, smoothingSlots, productSlots, productStart, galerkinSlots;
};

// Moves the transfer's patterns and index lists out of `fine` and `coarse` (A's pattern is given:
// the fine level holds the new one already).
PreviousTransfer takeTransfer(AmgHierarchy::Level& fine, AmgHierarchy::Level& coarse, BlockPattern previousFineA);

// Sets fine.P, fine.AP, coarse.A's pattern (values zero) and the index lists of both levels from
// fine.A's pattern and fine.aggregateOf (ids 0 .. coarseCount - 1). `rows` null: every row
// derived (`previous` unused); else the rows not marked are copied from `previous`.
// `productOperator`, if given, is the operator whose product with P makes A P (and so the coarse
// operator), in place of fine.A (same rows): fine.A still decides P.
void setTransferPattern(AmgHierarchy::Level& fine, AmgHierarchy::Level& coarse, int coarseCount,
                        const TransferRows* rows, const PreviousTransfer* previous,
                        const BlockSparseMatrix* productOperator = nullptr);

}  // namespace weft
