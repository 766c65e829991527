#include "core/remesh/remesh.h"

namespace gr {

Expected<RemeshResult> remesh(FastMarcher& marcher, const RemeshParams& params, Progress progress) {
  RemeshResult r;
  Expected<FpsResult> sampling = farthestPointSampling(marcher, params.sampling, progress.sub(0.0, 0.65));
  if (!sampling) return sampling.status();
  r.sampling = std::move(*sampling);
  Expected<DelaunayResult> mesh = geodesicDelaunay(marcher, r.sampling.origin, params.triangulation,
                                                   progress.sub(0.65, 0.95));
  if (!mesh) return mesh.status();
  r.mesh = std::move(*mesh);
  if (!progress.report(0.95, "Relaxation")) return cancelled();
  Expected<RelaxationResult> relaxation =
      relaxOnSurface(r.mesh.mesh, r.mesh.origin, marcher.mesh(), params.relaxation);
  if (!relaxation) return relaxation.status();
  r.relaxation = *relaxation;
  return r;
}

}  // namespace gr
