#include "core/base/status.h"

namespace gr {

const char* toString(StatusCode code) {
  switch (code) {
    case StatusCode::Ok: return "Ok";
    case StatusCode::InvalidInput: return "InvalidInput";
    case StatusCode::NonManifold: return "NonManifold";
    case StatusCode::Degenerate: return "Degenerate";
    case StatusCode::NotConverged: return "NotConverged";
    case StatusCode::Cancelled: return "Cancelled";
    case StatusCode::OutOfMemory: return "OutOfMemory";
    case StatusCode::Internal: return "Internal";
  }
  return "Unknown";
}

}  // namespace gr
