#include "core/motions/motion_romp.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "core/io/printable.h"
#include "core/motions/motion_internal.h"
#include "core/motions/motion_tracks.h"
#include "core/motions/motion_video_rows.h"

namespace smpl {
namespace {
using motion_detail::has;

bool matchesRomp(const DataNode& root) {
  return has(root, "results") && has(root, "sequence_results");
}

constexpr double kInfantAge = 0.8;  // bev/post_parser.py SMPLA_parser baby_thresh

// One person's rows before they become a Motion.
struct Person {
  std::string id;
  video_rows::Rows thetas, trans, betas;
  std::vector<int64_t> frames;
};

// Rows of an `np.savez` 0-d object member: the dict itself (or a list of one dict).
const DataNode* memberDict(const DataNode& root, const char* key) {
  const DataNode* d = root.get(key);
  if (d && d->isList() && d->children.size() == 1) d = &d->children[0];
  return d && d->isDict() ? d : nullptr;
}

Status trackOf(const DataNode& seq, const std::string& id, const std::string& path, Person* p) {
  const std::string ctx = path + ": track " + printable(id, 64);
  p->id = id;
  if (!seq.isDict()) return makeError(ctx + ": " + describeNode(seq) + ", expected a dict");
  if (Status s = video_rows::rowsOf(seq.get("smpl_thetas"), ctx, "smpl_thetas", &p->thetas); !s)
    return s;
  if (Status s = video_rows::rowsOf(seq.get("cam_trans"), ctx, "cam_trans", &p->trans); !s)
    return s;
  if (Status s = video_rows::rowsOf(seq.get("smpl_betas"), ctx, "smpl_betas", &p->betas); !s)
    return s;
  video_rows::Rows ids;
  if (Status s = video_rows::rowsOf(seq.get("frame_id"), ctx, "frame_id", &ids); !s) return s;
  const Array& t = p->thetas.get();
  Result<std::vector<int64_t>> f = video_rows::frameIds(
      ids.get(), t.shape.empty() ? 0 : static_cast<size_t>(t.shape[0]), ctx, "frame_id");
  if (!f) return f.error();
  p->frames = std::move(*f);
  return Status();
}

// sorted(results): person 0 of each frame that has one, at its position.
Status firstPersons(const DataNode& results, const std::string& path, Person* p) {
  std::vector<size_t> order(results.keys.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return results.keys[a] < results.keys[b]; });
  DataNode rows[3];  // smpl_thetas, cam_trans, smpl_betas: lists of each frame's row 0
  const char* keys[3] = {"smpl_thetas", "cam_trans", "smpl_betas"};
  for (DataNode& r : rows) r.kind = DataNode::Kind::List;
  for (size_t pos = 0; pos < order.size(); ++pos) {
    const DataNode& frame = results.children[order[pos]];
    if (!frame.isDict() || video_rows::countOf(frame.get("smpl_thetas")) == 0) continue;
    for (int k = 0; k < 3; ++k) {
      DataNode row;
      row.kind = DataNode::Kind::Array;
      Result<const Array*> element = video_rows::elementOf(frame.get(keys[k]), 0, path, &row.array);
      if (!element) return element.error();
      const Array* a = *element;
      if (!a)
        return makeError(path + ": frame '" + printable(results.keys[order[pos]], 64) + "': '" +
                         keys[k] + "' has no row for person 0");
      if (a != &row.array) {  // a List child: copied, charged first
        if (Status s = row.array.charge.add(a->data.size() * sizeof(double), path, "a row"); !s)
          return s;
        row.array.shape = a->shape;
        row.array.dtype = a->dtype;
        row.array.data = a->data;
      }
      rows[k].children.push_back(std::move(row));
    }
    p->frames.push_back(static_cast<int64_t>(pos));
  }
  p->id = "";
  const std::string ctx = path + ": person 0";
  if (Status s = video_rows::rowsOf(&rows[0], ctx, keys[0], &p->thetas); !s) return s;
  if (Status s = video_rows::rowsOf(&rows[1], ctx, keys[1], &p->trans); !s) return s;
  return video_rows::rowsOf(&rows[2], ctx, keys[2], &p->betas);
}

// Betas: 10 SMPL columns; BEV's 11th (the SMPL+A age) averaged into *age.
Status putBetas(const Person& p, const std::string& ctx, Motion* m, double* age) {
  const Array& b = p.betas.get();
  const int64_t t = static_cast<int64_t>(m->frames.size());
  if (b.shape.size() != 2 || b.shape[0] != t || (b.shape[1] != 10 && b.shape[1] != 11))
    return makeError(ctx + ": 'smpl_betas' has shape " + shapeString(b.shape) + "; expected (" +
                     std::to_string(t) + ",10) (ROMP) or (" + std::to_string(t) + ",11) (BEV)");
  Array smpl;
  smpl.shape = {t, 10};
  smpl.dtype = "<f8";
  *age = -1;
  if (b.shape[1] == 11) *age = 0;
  for (int64_t f = 0; f < t; ++f) {
    smpl.data.insert(smpl.data.end(), b.data.begin() + f * b.shape[1],
                     b.data.begin() + f * b.shape[1] + 10);
    if (b.shape[1] == 11) *age += b.data[f * 11 + 10] / static_cast<double>(t);
  }
  return video_rows::putBetas(smpl, ctx, "smpl_betas", p.id.empty() ? "" : "track " + p.id + ": ",
                              m);
}

Status toMotion(const Person& p, const std::string& path, Motion* m, double* age) {
  const std::string ctx = p.id.empty() ? path : path + ": track " + printable(p.id, 64);
  m->track = p.id;
  if (Status s = video_rows::putSmplPoses(p.thetas.get(), ctx, "smpl_thetas", m); !s) return s;
  if (Status s = video_rows::putTranslation(p.trans.get(), ctx, "cam_trans", m); !s) return s;
  if (Status s = putBetas(p, ctx, m, age); !s) return s;
  const bool bev = *age >= 0;
  m->source_layout = bev ? "bev" : "romp";
  m->world = MotionWorld::CameraYDown;
  m->world_why = std::string(bev ? "BEV" : "ROMP") + "'s 'cam_trans' is in the camera frame";
  if (bev) m->translation_anchor = {"left_hip", "right_hip"};
  m->fps = 0.0;
  return assembleTrack(p.frames, path, m);
}

// The notes of a BEV track (anchor, dropped age), or its refusal text.
std::string bevNote(const Motion& m, double age) {
  char text[200];
  std::snprintf(text, sizeof text,
                "%sbetas[10] (SMPL+A age %.3g) is dropped: the adult SMPL "
                "shape is used; translation anchored at the mid-hip (BEV root_align)",
                m.track.empty() ? "" : ("track " + m.track + ": ").c_str(), age);
  return text;
}

Status decodeRomp(const DataNode& root, const LayoutInput& in, MotionSet* out) {
  if (in.options.source_params == SourceParams::Global)
    return makeError(in.path + ": --source-params global: " + "ROMP/BEV output has no " +
                     "world-frame parameters");
  const DataNode* seq = memberDict(root, "sequence_results");
  const DataNode* results = memberDict(root, "results");
  std::vector<Person> people;
  if (seq && !seq->children.empty()) {
    people.resize(seq->children.size());
    for (size_t i = 0; i < people.size(); ++i)
      if (Status s = trackOf(seq->children[i], seq->keys[i], in.path, &people[i]); !s) return s;
  } else {
    if (!results) return makeError(in.path + ": 'results' is not a dict of frames");
    people.resize(1);
    if (Status s = firstPersons(*results, in.path, &people[0]); !s) return s;
    if (people[0].frames.empty()) return makeError(in.path + ": no frame has a person");
    out->notes.push_back("no tracking ids: person 0 of each frame");
  }
  std::string infants;
  double infant_age = 0;
  const size_t before = out->tracks.size();
  for (const Person& p : people) {
    Motion m;
    double age = -1;
    if (Status s = toMotion(p, in.path, &m, &age); !s) return s;
    if (age > kInfantAge) {
      infants += (infants.empty() ? "" : ", ") + p.id;
      infant_age = age;
      continue;
    }
    if (age >= 0) m.notes.push_back(bevNote(m, age));
    out->tracks.push_back(std::move(m));
  }
  char text[200];
  std::snprintf(text, sizeof text, "BEV's infant body (SMIL, age coefficient %.3g > %.1f)",
                infant_age, kInfantAge);
  if (out->tracks.size() == before)
    return makeError(in.path + ": " + text + " is not an SMPL body");
  const bool bev = out->tracks[before].source_layout == "bev";
  out->notes.insert(out->notes.begin(), std::string("read as ") + (bev ? "BEV" : "ROMP") +
                                            " output (video_results.npz; SMPL)");
  if (!infants.empty())
    out->notes.push_back("track(s) " + infants + ": " + text + ", not an SMPL body: left out");
  return Status();
}

}  // namespace

const MotionLayout& rompLayout() {
  static const MotionLayout row{"romp",
                                "ROMP / BEV video_results.npz (results, sequence_results)",
                                kNpzFile,
                                matchesRomp,
                                {"results", "sequence_results"},
                                decodeRomp,
                                24.0};
  return row;
}

}  // namespace smpl
