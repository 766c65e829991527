// Region boundaries moved onto the sharp edges next to them: the last step of the segmentation.
//
// The fronts of a feature-aligned metric slow down at sharp edges, so two cells meet in the slow
// band around an edge; a face is labelled by its vertices' cells, and the boundary often runs
// one ring of faces beside the sharp edge instead of on it (fandisk, 20 regions: 43% of the
// boundary length). This pass moves such faces to the neighbouring region:
//
//     cell A | cell B            the faces of the strip between the sharp edge (||) and the
//   ---------||----------        boundary (:) have a vertex in each cell; moving them to B
//     A    A ||:  B   B          puts the boundary on the sharp edge, where cutting costs
//     A    A || A :  B           nothing
//
// The moves lower the boundary's weighted length sum_e w(e) |e| (w = 1 on smooth edges, falling
// to 0 between 30 and 60 degrees of dihedral angle) and stay in a band along the Voronoi boundary
// (faces with a vertex in each cell, and their neighbours: a few faces across, so regions
// keep their size). Per pair of neighbouring regions (a, b), the faces of the band take the
// labels of the minimum cut between the faces around the band labelled a and those labelled b
// (Edmonds-Karp on the band's faces, capacities w(e) |e|), and keep them only if a and b are
// still topological disks (counted; otherwise the pair's band is left as it was).
// Cost: per pair, O(band * cut) with a band of a few faces across; O(F) in all for the labels.
#pragma once

#include <vector>

#include "core/mesh/tri_mesh.h"

namespace gr {

/// Moves faces of `faceRegion` (every region a disk) across region boundaries onto the sharp
/// edges beside them, as above; `cell` is the Voronoi cell of each vertex. Returns the faces
/// moved.
int snapBoundariesToSharpEdges(const TriMesh& mesh, const std::vector<int>& cell, std::vector<int>& faceRegion,
                               int regions);

}  // namespace gr
