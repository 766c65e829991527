// Figures of a segmentation measured from its face labels alone (shared by the segmentation tests
// and bench_segmentation, the same code for ours and the anchors): disks recounted by
// test::recount, area spread, compactness, alignment with sharp edges.
#pragma once

#include <vector>

#include "core/mesh/tri_mesh.h"

namespace gr::test {

struct SegmentationFigures {
  int regions = 0;                 ///< labels 0..max
  int nonDisks = 0;                ///< regions that are not one edge-connected topological disk
  int empty = 0;                   ///< labels below the largest with no face
  double areaCv = 0.0;             ///< coefficient of variation of the regions' areas
  double meanIsoperimetric = 0.0;  ///< mean of 4 pi A / P^2 (P: the region's boundary length)
  double boundaryOnSharp = 0.0;    ///< share of region-boundary length on edges of dihedral > 60 deg
  double sharpCovered = 0.0;       ///< share of sharp-edge length (dihedral > 60 deg) on region boundaries
};

/// `region` has one label >= 0 per face. A disk: one piece (recount's components), Euler
/// characteristic 1, one boundary loop, manifold edges and vertices.
SegmentationFigures segmentationFigures(const TriMesh& mesh, const std::vector<int>& region);

}  // namespace gr::test
