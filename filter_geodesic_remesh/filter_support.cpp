#include "filter_geodesic_remesh/filter_support.h"

#include <cstdio>

namespace gr::filters {

Expected<CurrentMesh> currentMesh(MeshDocument& doc) {
  MeshModel* mm = doc.mm();
  if (mm == nullptr) return invalidInput("there is no mesh to work on");
  Expected<adapters::CoreView> view = adapters::toCore(mm->cm);
  if (!view) return view.status();
  return CurrentMesh{mm, std::move(view).value()};
}

std::string formatNumber(double x, const char* spec) {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, x);
  return buf;
}

std::string formatDuration(double milliseconds) {
  return milliseconds < 10000.0 ? formatNumber(milliseconds, "%.3g") + " ms" : formatNumber(milliseconds / 1000.0, "%.3g") + " s";
}

}  // namespace gr::filters
