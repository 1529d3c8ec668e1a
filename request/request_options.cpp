#include "request/request_options.h"

#include "core/io/file_io.h"

namespace smpl {

ExportOptions exportOptionsOf(const ExportRequest& r, const std::vector<double>& betas) {
  ExportOptions o;
  o.betas = betas;
  o.expression = r.expression;
  o.max_influences = r.all_influences ? kAllInfluences : r.max_influences;
  o.skin_weights = r.skin_weights;
  o.correctives = r.correctives;
  o.corrective_refit = r.corrective_refit;
  o.encoding = r.encoding;
  o.corrective_basis = r.corrective_basis;
  o.shape_keys = r.shape_keys;
  o.expression_keys = r.expression_keys;
  o.uv_obj = r.uv;
  o.name = r.name;
  o.quantize_morphs = r.quantize_morphs;
  o.root_bone = r.root_bone;
  o.origin = r.origin.value_or(r.root_bone ? Origin::Floor : Origin::Model);
  const WriterFormat* format = writerFormatForPath(r.out);
  o.mesh = !format || format->needs_mesh;  // a skeleton-only writer: no skin, no morph targets
  return o;
}

AnimationOptions animationOptionsOf(const ExportRequest& r) {
  AnimationOptions a;
  a.fps = r.fps.value_or(0.0);
  a.first_frame = r.first_frame;
  a.end_frame = r.end_frame;
  a.up = r.up;
  a.in_place = r.in_place;
  return a;
}

WriterOptions writerOptionsOf(const ExportRequest& r, const std::string& buffer_path) {
  WriterOptions w;
  const WriterFormat* format = writerFormatForPath(r.out);
  w.binary = !format || format->binary;
  w.buffer_uri = buffer_path.empty() ? "" : baseName(buffer_path);
  w.fbx_units = r.fbx_units;
  w.fbx_version = r.fbx_version;
  w.fbx_compress_level = r.fbx_compress_level;
  w.threads = r.threads.value_or(0);
  w.morph_epsilon = r.corrective_epsilon;
  w.draco = r.draco;
  w.meshopt = r.meshopt;
  w.quantize_animation = r.quantize_animation;
  w.bvh_units = r.bvh_units;
  w.density = r.density;
  w.mjcf_joints = r.mjcf_joints;
  w.mjcf_motors = r.mjcf_motors;
  return w;
}

}  // namespace smpl
