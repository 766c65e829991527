#include "filter_geodesic_remesh/filter_support.h"

namespace gr::filters {

Expected<CurrentMesh> currentMesh(MeshDocument& doc) {
  MeshModel* mm = doc.mm();
  if (mm == nullptr) return invalidInput("there is no mesh to work on");
  Expected<adapters::CoreView> view = adapters::toCore(mm->cm);
  if (!view) return view.status();
  return CurrentMesh{mm, std::move(view).value()};
}

}  // namespace gr::filters
