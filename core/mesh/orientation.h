// Coherent orientation: every face turned to agree with its neighbours across manifold edges.
#pragma once

#include <vector>

#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

/// The same mesh with its faces oriented coherently: across every manifold edge the two faces
/// run the edge in opposite directions. In each component the orientation most faces already
/// have is kept; a face is flipped by swapping its corners 1 and 2 (so a point with barycentric
/// coordinates (b0, b1, b2) in the flipped face has (b0, b2, b1) in the original), and
/// `flipped` (optional) receives one flag per face. Fails (InvalidInput) on a non-orientable
/// component (a Moebius strip, a Klein bottle) and (NonManifold) on non-manifold edges.
/// Cost: O(F).
Expected<TriMesh> orientCoherently(const TriMesh& mesh, std::vector<char>* flipped = nullptr);

}  // namespace gr
