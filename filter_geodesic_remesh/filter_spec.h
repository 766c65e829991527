// FilterSpec: one row per filter of the plugin. The MeshLab plugin class only looks rows up.
//
// A filter is two functions: `declare` lists its parameters, `apply` converts the mesh, calls
// the core and writes the result back. `apply` returns a gr::Status; the plugin logs the
// message (meshlabserver prints the log, not the error string) and returns false. `apply`
// must leave the document untouched when it fails: compute first, then commit.
#pragma once

#include <common/interfaces.h>

#include <functional>
#include <string>
#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"

namespace gr::filters {

/// What a filter may use besides the document and its parameters.
struct FilterContext {
  std::function<void(const std::string&)> log;   ///< a line in MeshLab's log (FILTER level)
  std::function<void(const std::string&)> warn;  ///< a warning line (shown in red)
  Progress progress;                             ///< MeshLab's progress bar
};

struct FilterSpec {
  int id;
  const char* name;  ///< exact filter name, used by .mlx scripts
  const char* info;  ///< HTML description, cites the paper section
  MeshFilterInterface::FilterClass filterClass;
  int postConditions;  ///< MeshModel::MM_* bits the filter changes
  void (*declare)(const MeshModel& mesh, RichParameterList& params);
  Status (*apply)(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx);
};

/// All filters of the plugin, in menu order.
const std::vector<FilterSpec>& filterTable();

}  // namespace gr::filters
