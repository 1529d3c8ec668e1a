#include "exporter/asset_names.h"

#include <string>

#include "core/io/printable.h"
#include "core/utf8.h"

namespace smpl {
namespace {

// Calls f(name, what) for every name of the asset (const or not).
template <class A, class F>
void visitNames(A& a, F&& f) {
  f(a.name, "asset name");
  for (auto& n : a.skeleton.names) f(n, "joint name");
  for (auto& t : a.mesh.morph_targets) f(t.name, "morph target name");
  for (auto& c : a.animations) f(c.name, "animation name");
  for (auto& c : a.animations) f(c.source.track, "animation track");  // a person id from the file
  f(a.metadata.model_name, "model_name");
  for (auto& c : a.metadata.correctives) f(c.target, "corrective target");
  for (auto& t : a.metadata.corrective_basis.targets) f(t, "corrective basis target");
  f(a.metadata.dmpl.basis, "DMPL basis name");
  for (auto& d : a.metadata.dmpl.targets) f(d.target, "DMPL target");
}

}  // namespace

void escapeAssetNames(Asset* asset) {
  visitNames(*asset, [](std::string& name, const char*) {
    if (!isValidUtf8(name)) name = escapeInvalidUtf8(name);
  });
}

Status checkAssetNames(const Asset& asset) {
  Status st;
  visitNames(asset, [&](const std::string& name, const char* what) {
    if (st && !isValidUtf8(name))
      st = makeError(std::string(what) + " '" + printable(name) + "' is not valid UTF-8");
  });
  return st;
}

}  // namespace smpl
