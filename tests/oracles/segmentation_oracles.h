// Competitors of the geodesic segmentation, the anchors its tests and benchmarks compare with:
// CGAL's Variational Shape Approximation (planar proxies, L21 metric) and plain Euclidean k-means
// of the face centroids. Both return one label per face of the mesh, in the mesh's face order.
#pragma once

#include <vector>

#include "core/mesh/tri_mesh.h"

namespace gr::oracle {

/// CGAL::Surface_mesh_approximation::approximate_triangle_mesh (Cohen-Steiner, Alliez, Desbrun
/// 2004) on a Surface_mesh copy (toSurfaceMesh): L21 metric, HIERARCHICAL seeding (CGAL's default,
/// deterministic: no std::rand) with its 5 default relaxations, max_number_of_proxies(regions),
/// then number_of_iterations(iterations) of partitioning and fitting. Per face, its proxy index in
/// [0, p), p the number of proxies CGAL ends with: p <= regions, and p may be smaller (the
/// hierarchical seeding stops when no proxy can be added). CGAL grows each proxy from its seed
/// face over face adjacency, so a proxy is edge-connected within one component of the mesh.
/// Empty if CGAL cannot run: toSurfaceMesh refuses the mesh (non-manifold, incoherent
/// orientation), regions < 1 or regions >= faceCount / 3 (CGAL then ignores the count and falls
/// back to its error-drop criterion), CGAL throws, or a face is left without a proxy.
std::vector<int> cgalVsaSegmentation(const TriMesh& mesh, int regions, int iterations = 30);

/// Lloyd's k-means of the face centroids in 3D (Euclidean distance, nothing of the surface), each
/// face weighted by its area: centres are area-weighted means. Seeding: area-weighted k-means++
/// (first centre drawn with probability proportional to area, each next one proportional to
/// area * squared distance to the nearest centre) from std::mt19937(seed), drawn with the
/// generator's raw output only, so labels are the same with every standard library. Then up to
/// `iterations` rounds (at least one) of assignment (ties to the lower cluster) and update,
/// stopping early when no label changes; a cluster left empty is moved onto the face of largest
/// area * squared distance to its centre. Per face, its cluster in [0, k), every cluster
/// non-empty. Empty if k < 1 or k > faceCount. Cost O(faceCount * k * iterations), brute force.
std::vector<int> kmeansFaceCentroids(const TriMesh& mesh, int k, unsigned seed = 0, int iterations = 30);

}  // namespace gr::oracle
