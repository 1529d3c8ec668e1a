// The .usda and .usdz writers (usd_writer.h).
#include "writers/usd/usd_writer.h"

#include "writers/usd/usd_layer.h"
#include "writers/usd/usdz_archive.h"

namespace smpl {
namespace {

struct UsdaWriter : Writer {
  const char* name() const override { return "usda"; }
  Result<std::string> serialize(const Asset& asset, const WriterOptions&) const override {
    return usdaLayer(asset);
  }
};

struct UsdzWriter : Writer {
  const char* name() const override { return "usdz"; }
  Result<std::string> serialize(const Asset& asset, const WriterOptions&) const override {
    Result<std::string> layer = usdaLayer(asset);
    if (!layer) return layer.error();
    return usdzArchive({{"body.usda", std::move(*layer)}});
  }
};

}  // namespace

const Writer& usdaWriter() {
  static const UsdaWriter writer;
  return writer;
}

const Writer& usdzWriter() {
  static const UsdzWriter writer;
  return writer;
}

}  // namespace smpl
