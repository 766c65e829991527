// Geodesic Lloyd iteration: seeds moved to the intrinsic centres of mass of their geodesic
// Voronoi cells, towards a geodesic centroidal Voronoi tessellation (paper §4.2).
//
//   seeds --multi-source front--> cells V_i and field U --> energy sum_i E_i = sum_x m_x U(x)^2
//         --each cell: a descent of E_i(w) = integral over V_i of d(x, w)^2 dm, from its seed
//         --> new seeds; again, until `iterations` or a relative decrease below `tolerance`
//
// The centre of mass w of a cell (its Karcher mean) is where the integral of log_w(x) dm over the
// cell vanishes. A descent step runs one front from w over the cell and its ring of vertices
// (FastMarchingParams::region), takes log_w(x) as d(x, w) times the unit direction of x - w in
// the tangent plane at w (exact on a flat cell, first order on a curved one), and moves w by the
// mean of it divided by P(w) (in mesh units: the Newton step of E_i) to the point of the cell's
// faces nearest to that target, so seeds lie inside faces, not only on vertices. A step shorter
// than 1% of the cell's size ends the descent; one that does not lower E_i is halved once, then
// the descent ends. Two steps per iteration (the paper's descent takes about 8 to converge; the
// outer iterations carry it on: bunny00, 500 seeds, 20 iterations of the segmentation in 2.1 s
// instead of 4.2 s with 8 steps, the same energy within 1%).
//
// The mass element dm is the surface's area (one third of the faces around each vertex), or the
// metric's area P^2 ds (`metricArea`: cells of equal metric area, so that an adaptive density
// 1/F^2 is kept).
//
// Over-relaxation (`overRelaxation`): seeds move past the centre, by omega times the step; bunny00
// from 100 farthest-point samples: 94.5% of their energy after 6 iterations instead of 95.1%;
// both end at 92.9-93.0% after 20 (Lloyd's local minimum next to the samples).
// Guarantees: the energy, as recomputed from a multi-source front of the seeds, never increases
// from one accepted iteration to the next (an iteration that would raise it is undone and ends the
// run); every seed keeps a cell (a seed whose cell vanished goes to the vertex farthest from all
// seeds, counted in `reseeded`).
// Cost per iteration: the new cells, plus per cell at most 3 fronts per descent step over the
// cell and its ring: about 1 + 2 * (descent steps taken) fronts over the whole mesh. With cells
// of 40 vertices or more on average, the new cells come from the last accepted ones: every vertex starts at an upper bound of its distance
// to its cell's moved seed (its distance to the old seed plus how far that seed moved, plus half
// an edge), and each seed's front then runs alone where it goes below that
// (FastMarcher::startFromBound). That visits about 1.1-1.3 times the vertices of one front from
// all seeds, but each front stays in its cell's memory: a front from 1,000 seeds jumps across
// the whole mesh between heap pops (armadillo_sub3, 1.66M vertices: 10 iterations 18.4 -> 10 s).
// The fields agree with one front from all seeds (bunny00, 500 seeds: the same energy to 1e-16
// after the first iteration).
#pragma once

#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/geodesic/fast_marching.h"
#include "core/geodesic/metric.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

/// Options of the geodesic Lloyd iteration (Peyré & Cohen 2006, §4.2).
struct LloydParams {
  int iterations = 20;  ///< at most this many iterations (>= 0; 0 = only the cells of the seeds)
  /// Stop when one iteration lowers the energy by less than this fraction of it (>= 0; 0 = never).
  double tolerance = 1e-4;
  /// Descent steps per cell and iteration, each checked by a front over the cell (>= 0). 0: one
  /// step from the cells' own field, checked only by the next iteration's energy (no front per cell:
  /// about 3x faster per iteration, and on bunny00 a lower energy after 8 iterations).
  int descentSteps = 0;
  bool metricArea = false;  ///< mass element P^2 ds instead of ds (see the top of this file)
  /// Over-relaxation omega in [1, 2): each seed moves omega times the way to its cell's centre of
  /// mass (the point of the cell's faces nearest to that), which speeds up Lloyd's slow
  /// convergence; an iteration that would raise the energy is redone with omega = 1. 1 = plain Lloyd.
  double overRelaxation = 1.6;
  /// End with every seed on a vertex: moved to the vertex of its face with the largest
  /// barycentric coordinate, and the cells of those seeds computed (callers that need vertex
  /// seeds: a labelling of faces by their vertices, samples on a refined surface).
  bool vertexSeeds = false;
  /// The marcher already holds the field of exactly `seeds`, seed i in cell i (as
  /// farthestPointSampling leaves it): the first cells are read from it instead of a front over
  /// the whole mesh.
  bool marcherHoldsSeedsField = false;
  /// Seeds on boundary vertices stay where they are (a remeshing samples its boundaries first so
  /// that they stay boundaries).
  bool keepBoundarySeeds = false;
};

struct LloydResult {
  std::vector<SurfacePoint> seeds;  ///< the final seeds, one per cell
  std::vector<double> distance;     ///< per vertex, U to the nearest final seed
  std::vector<int> cell;            ///< per vertex, the index of its nearest final seed (-1: unreached)
  /// The energy sum_i E_i before the first iteration and after each accepted one (and, with
  /// vertexSeeds, of the seeds on vertices last: it may be a little higher).
  std::vector<double> energy;
  int iterations = 0;   ///< iterations accepted
  int reseeded = 0;     ///< seeds re-placed because their cell vanished
  bool undone = false;  ///< the last iteration raised the energy and was undone
};

/// Per-vertex mass of the energy: one third of the area of the faces around each vertex, times
/// P^2 when `metricArea` (P from `metric`, uniform = 1).
std::vector<double> lloydVertexMass(const TriMesh& mesh, const Metric& metric, bool metricArea);

/// Lloyd iterations from `seeds` on `mesh` under `metric`, with `marcher` (built on the same mesh
/// and metric; it is reset, and holds the final seeds' field on return). Fails (InvalidInput) on
/// no seed, a seed out of range, a metric of the wrong size or parameters out of range;
/// (Cancelled) if the progress callback says so.
Expected<LloydResult> geodesicLloyd(const TriMesh& mesh, const Metric& metric, FastMarcher& marcher,
                                    std::vector<SurfacePoint> seeds, const LloydParams& params = {},
                                    Progress progress = {});

}  // namespace gr
