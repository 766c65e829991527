// The fast-marching engine's per-vertex and per-face records, laid out for its hot loop
// (geodesic/fast_marching.cpp). Private to core/geodesic: other folders use FastMarcher's API.
#pragma once

namespace gr::detail {

struct Candidate {  // the best update found so far for one vertex
  double u;
  int cell;
};

struct Saved {  // value of a vertex before the current run improved it tentatively
  int v, cell, run;
  double u;
};

/// A face (v, a, b) around v, as the hot loop reads it: contiguous per vertex.
struct StarFace {
  int a, b;  ///< the other vertices (slots), in face order
  /// The obtuse corner of this face, if it is at a or b and has an acute split i: 2 i if at a,
  /// 2 i + 1 if at b; -1 otherwise. (A triangle has at most one obtuse corner.)
  int split;
  double lva, lvb, lab;  ///< edge lengths
};

/// Per acute split, what a star face needs: the far vertex R (slot) and the unfolded lengths.
struct NearSplit {
  int r;
  double lenXR, lenAR, lenBR;
};

/// With a non-uniform metric, parallel to star_: the metric's edge costs and mean P of the
/// face, read in the same sequential order instead of P at two random neighbours.
struct StarCost {
  double edgeA, edgeB;  ///< (P_v + P_a) / 2 * |va|, (P_v + P_b) / 2 * |vb|
  double face;          ///< (P_v + P_a + P_b) / 3
};

/// The acute splits whose far vertex R is a given slot, in slot order (CSR), with the slots of
/// X, A, B and the lengths copied in: the loop over them reads one contiguous record each.
struct FarSplit {
  int x, a, b;
  double lenXA, lenXB, lenXR, lenAR, lenBR;
};

/// Per-vertex state the hot loop reads together (one cache line for a neighbour).
struct Node {
  double u;  ///< U, tentative while in the heap
  int run;   ///< run in which the vertex was last accepted; 0 = not known
  int cell;
};

}  // namespace gr::detail
