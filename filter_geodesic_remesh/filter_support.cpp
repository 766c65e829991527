#include "filter_geodesic_remesh/filter_support.h"

#include <exception>
#include <new>

namespace gr::filters {

Expected<CurrentMesh> currentMesh(MeshDocument& doc) {
  MeshModel* mm = doc.mm();
  if (mm == nullptr) return invalidInput("there is no mesh to work on");
  Expected<adapters::CoreView> view = adapters::toCore(mm->cm);
  if (!view) return view.status();
  return CurrentMesh{mm, std::move(view).value()};
}

Status runCatchingExceptions(const std::function<Status()>& apply) {
  try {
    return apply();
  } catch (const std::bad_alloc&) {
    return outOfMemory("out of memory");
  } catch (const std::exception& e) {
    return internalError(std::string("internal error: ") + e.what());
  } catch (...) {
    return internalError("internal error: an exception of unknown type");
  }
}

}  // namespace gr::filters
