#include "filter_geodesic_remesh/filter_support.h"

#include <QDir>
#include <QFileInfo>
#include <QImage>

#include <algorithm>
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

std::string writeCheckerboard(const MeshModel& mm, int size, const std::string& suffix, int squares) {
  QImage image(size, size, QImage::Format_RGB32);
  const int square = std::max(1, size / std::max(1, squares));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      image.setPixel(x, y, ((x / square + y / square) % 2) ? qRgb(235, 235, 235) : qRgb(60, 90, 160));
  const QFileInfo mesh(mm.fullName());
  const QString dir =
      !mm.fullName().isEmpty() && QFileInfo(mesh.absolutePath()).isWritable() ? mesh.absolutePath() : QDir::tempPath();
  const QString base = mesh.completeBaseName().isEmpty() ? QString("mesh") : mesh.completeBaseName();
  const QString path = QDir(dir).absoluteFilePath(base + QString::fromStdString(suffix));
  return image.save(path, "PNG") ? path.toStdString() : std::string();
}

}  // namespace gr::filters
