// The MeshLab plugin: each MeshLab virtual is a lookup in filterTable() (filter_spec.h).
#pragma once

#include <common/interfaces.h>

#include "filter_geodesic_remesh/filter_spec.h"

class FilterGeodesicRemeshPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  FilterGeodesicRemeshPlugin();

  QString pluginName() const override;
  QString filterName(FilterIDType id) const override;
  QString filterInfo(FilterIDType id) const override;
  FilterClass getClass(QAction* action) override;
  int postCondition(QAction* action) const override;
  FILTER_ARITY filterArity(QAction*) const override { return SINGLE_MESH; }
  void initParameterSet(QAction* action, MeshModel& mesh, RichParameterList& params) override;
  bool applyFilter(QAction* action, MeshDocument& doc, const RichParameterList& params, vcg::CallBackPos* cb) override;

 private:
  const gr::filters::FilterSpec* spec(FilterIDType id) const;
};
