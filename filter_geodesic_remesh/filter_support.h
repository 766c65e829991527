// Small pieces every filter uses: the current mesh as the core sees it (and, through
// core/base/format.h, number formatting for the log).
#pragma once

#include <common/interfaces.h>

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

}  // namespace gr::filters
