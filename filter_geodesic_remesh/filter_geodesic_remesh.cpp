#include "filter_geodesic_remesh/filter_geodesic_remesh.h"

#include <string>

#include "filter_geodesic_remesh/filter_support.h"

FilterGeodesicRemeshPlugin::FilterGeodesicRemeshPlugin() {
  for (const gr::filters::FilterSpec& s : gr::filters::filterTable()) typeList << s.id;
  for (FilterIDType id : types()) actionList << new QAction(filterName(id), this);
}

QString FilterGeodesicRemeshPlugin::pluginName() const { return "FilterGeodesicRemesh"; }

const gr::filters::FilterSpec* FilterGeodesicRemeshPlugin::spec(FilterIDType id) const {
  for (const gr::filters::FilterSpec& s : gr::filters::filterTable())
    if (s.id == id) return &s;
  return nullptr;
}

QString FilterGeodesicRemeshPlugin::filterName(FilterIDType id) const {
  const auto* s = spec(id);
  return s ? QString(s->name) : QString("Unknown filter");
}

QString FilterGeodesicRemeshPlugin::filterInfo(FilterIDType id) const {
  const auto* s = spec(id);
  return s ? QString(s->info) : QString();
}

MeshFilterInterface::FilterClass FilterGeodesicRemeshPlugin::getClass(QAction* action) {
  const auto* s = spec(ID(action));
  return s ? s->filterClass : FilterClass(MeshFilterInterface::Generic);
}

int FilterGeodesicRemeshPlugin::postCondition(QAction* action) const {
  const auto* s = spec(ID(action));
  return s ? s->postConditions : int(MeshModel::MM_NONE);
}

void FilterGeodesicRemeshPlugin::initParameterSet(QAction* action, MeshModel& mesh, RichParameterList& params) {
  if (const auto* s = spec(ID(action))) s->declare(mesh, params);
}

bool FilterGeodesicRemeshPlugin::applyFilter(QAction* action, MeshDocument& doc, const RichParameterList& params,
                                             vcg::CallBackPos* cb) {
  const auto* s = spec(ID(action));
  if (s == nullptr) {
    errorMessage = "unknown filter";
    return false;
  }
  gr::filters::FilterContext ctx;
  ctx.log = [this](const std::string& line) { Log(GLLogStream::FILTER, line); };
  ctx.warn = [this](const std::string& line) { Log(GLLogStream::WARNING, line); };
  if (cb != nullptr) ctx.progress = gr::Progress([cb](int percent, const char* msg) { return cb(percent, msg); });

  const gr::Status status = gr::filters::runCatchingExceptions([&] { return s->apply(doc, params, ctx); });
  if (status) return true;
  // meshlabserver prints the log but not errorMessage: say it in both.
  const std::string line = std::string(s->name) + " failed (" + gr::toString(status.code) + "): " + status.message;
  Log(GLLogStream::WARNING, line);
  errorMessage = QString::fromStdString(status.message);
  return false;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterGeodesicRemeshPlugin)
