#include "exporter/export_options.h"

namespace smpl {

const char* correctiveEncodingName(CorrectiveEncoding encoding) {
  switch (encoding) {
    case CorrectiveEncoding::Unit:
      return "unit";
    case CorrectiveEncoding::Split:
      return "split";
    default:
      return "signed";
  }
}

}  // namespace smpl
