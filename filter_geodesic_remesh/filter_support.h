// Small pieces every filter uses: the current mesh as the core sees it, and number formatting
// for the log.
#pragma once

#include <common/interfaces.h>

#include <string>

#include "core/base/status.h"
#include "vcg_adapters/cmesho_adapter.h"

namespace gr::filters {

/// The document's current mesh and its core view (fails on no mesh, no faces, NaN, bad faces).
struct CurrentMesh {
  MeshModel* model = nullptr;
  adapters::CoreView view;
};
Expected<CurrentMesh> currentMesh(MeshDocument& doc);

/// printf-style formatting of one number, for log lines.
std::string formatNumber(double x, const char* spec = "%.6g");
/// A duration for the log: "87.7 ms" under ten seconds, "23.5 s" from there on.
std::string formatDuration(double milliseconds);

}  // namespace gr::filters
