// Small pieces every filter uses: the current mesh as the core sees it (and, through
// core/base/format.h, number formatting for the log).
#pragma once

#include <common/interfaces.h>

#include <chrono>
#include <functional>
#include <string>

#include "core/base/format.h"
#include "core/base/status.h"
#include "vcg_adapters/cmesho_adapter.h"

namespace gr::filters {

/// The document's current mesh and its core view (fails on no mesh, no faces, NaN, bad faces).
struct CurrentMesh {
  MeshModel* model = nullptr;
  adapters::CoreView view;
};
Expected<CurrentMesh> currentMesh(MeshDocument& doc);

/// Runs `apply` and turns an exception escaping it into a Status, so that MeshLab never sees one:
/// std::bad_alloc -> OutOfMemory ("out of memory"), any other -> Internal ("internal error: ...").
Status runCatchingExceptions(const std::function<Status()>& apply);

/// Milliseconds from `start` to now (the log's Time line).
inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// A checkerboard of `squares` x `squares` squares, `size` texels a side, written next to the mesh's file as
/// <its name><suffix> (or in the temporary folder for a mesh without one): the absolute path, or an
/// empty string if it could not be written.
std::string writeCheckerboard(const MeshModel& mm, int size, const std::string& suffix, int squares = 32);

}  // namespace gr::filters
