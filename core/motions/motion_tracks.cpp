#include "core/motions/motion_tracks.h"

#include <algorithm>
#include <cctype>
#include <numeric>

#include "core/io/printable.h"

namespace smpl {
namespace {

// A decimal integer of any length ("12", "-3", "18446744073709551616"):
// ids from dict keys are exact, never through a double or an int64.
bool isNumber(const std::string& s) {
  const size_t from = !s.empty() && s[0] == '-' ? 1 : 0;
  return s.size() > from &&
         std::all_of(s.begin() + from, s.end(), [](unsigned char c) { return std::isdigit(c); });
}

// a < b for two isNumber() texts in canonical form (no leading zeros):
// by sign, then digit count, then digits.
bool numberLess(const std::string& a, const std::string& b) {
  const bool na = a[0] == '-', nb = b[0] == '-';
  if (na != nb) return na;
  const bool shorter = a.size() != b.size() ? a.size() < b.size() : a < b;
  if (a == b) return false;
  return na ? !shorter : shorter;
}

// Ids in file order or numeric order: numbers as numbers, then text.
bool idLess(const std::string& a, const std::string& b) {
  const bool number_a = isNumber(a), number_b = isNumber(b);
  if (number_a && number_b) return numberLess(a, b);
  if (number_a != number_b) return number_a;
  return a < b;
}

int64_t detections(const Motion& m) {
  return static_cast<int64_t>(m.frames.size()) - m.held_frames;
}

std::string range(const Motion& m) {
  return std::to_string(m.first_frame) + "-" +
         std::to_string(m.first_frame + static_cast<int64_t>(m.frames.size()) - 1);
}

// Rows reordered by `order` (indices into the old rows); absent parts stay absent.
template <class Row>
void reorder(const std::vector<size_t>& order, std::vector<Row>* rows) {
  if (rows->empty()) return;
  std::vector<Row> out;
  out.reserve(order.size());
  for (size_t i : order) out.push_back((*rows)[i]);
  *rows = std::move(out);
}

void reorderMatrix(const std::vector<size_t>& order, Eigen::MatrixXd* m) {
  if (m->rows() == 0) return;
  Eigen::MatrixXd out(static_cast<Eigen::Index>(order.size()), m->cols());
  for (size_t i = 0; i < order.size(); ++i) out.row(i) = m->row(order[i]);
  *m = std::move(out);
}

std::string idList(const std::vector<Motion>& tracks) {
  std::string text;
  for (size_t i = 0; i < tracks.size(); ++i)
    text += (i ? ", " : "") + printable(tracks[i].track, 64);
  return text;
}

}  // namespace

Result<TrackChoice> parseTrackChoice(const std::string& text) {
  TrackChoice c;
  if (text == "longest") return c;
  if (text == "all") return c.kind = TrackChoice::Kind::All, c;
  const bool ok = !text.empty() && text.size() <= 64 &&
                  std::all_of(text.begin(), text.end(), [](unsigned char ch) {
                    return std::isalnum(ch) || ch == '-' || ch == '_' || ch == '.' || ch == '+';
                  });
  if (!ok)
    return makeError(
        "--track: expected 'longest', 'all' or a track id, got '" + printable(text, 64) + "'",
        ErrorKind::Usage);
  c.kind = TrackChoice::Kind::Id;
  c.id = text;
  return c;
}

Status assembleTrack(const std::vector<int64_t>& frames, const std::string& path, Motion* m) {
  const size_t n = m->frames.size();
  if (frames.size() != n || n == 0)
    return makeError(path + ": track " + printable(m->track, 64) + " has " + std::to_string(n) +
                     " poses for " + std::to_string(frames.size()) + " frame numbers");
  if ((!m->hands.left.empty() && m->hands.left.size() != n) ||
      (!m->hands.right.empty() && m->hands.right.size() != n))
    return makeError(path + ": track " + printable(m->track, 64) + " has hand poses for " +
                     std::to_string(m->hands.left.size()) + " of its " + std::to_string(n) +
                     " poses");
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return frames[a] < frames[b]; });
  for (size_t i = 1; i < n; ++i)
    if (frames[order[i]] == frames[order[i - 1]])
      return makeError(path + ": track " + printable(m->track, 64) + " has two poses for frame " +
                       std::to_string(frames[order[i]]));
  const int64_t first = frames[order.front()], span = frames[order.back()] - first + 1;
  if (span > 100000000)
    return makeError(path + ": track " + printable(m->track, 64) + " spans " +
                     std::to_string(span) + " frames");
  // Held frames repeat the previous detection: an index per clip frame.
  std::vector<size_t> rows;
  for (size_t i = 0; i < n; ++i) {
    const int64_t f = frames[order[i]];
    while (static_cast<int64_t>(rows.size()) < f - first) rows.push_back(rows.back());
    rows.push_back(order[i]);
  }
  if (Status st =
          m->charge.add(static_cast<uint64_t>(rows.size() - n) *
                            (sizeof(Rotations) + m->frames[0].size() * sizeof(Eigen::Matrix3d)),
                        path, "held frames");
      !st)
    return st;
  reorder(rows, &m->frames);
  reorder(rows, &m->translation);
  reorder(rows, &m->world_rotation);
  reorder(rows, &m->world_translation);
  reorder(rows, &m->hands.left);  // pending fit hands (SMPLer-X), one per row
  reorder(rows, &m->hands.right);
  reorderMatrix(rows, &m->expression);
  reorderMatrix(rows, &m->dmpls);
  m->first_frame = first;
  m->held_frames = static_cast<int64_t>(rows.size() - n);
  m->held.clear();
  if (m->held_frames > 0)
    for (size_t i = 0; i < rows.size(); ++i) m->held.push_back(i > 0 && rows[i] == rows[i - 1]);
  if (m->held_frames > 0)
    m->notes.push_back("track " + printable(m->track, 64) +
                       ": source frames without a detection: " + std::to_string(m->held_frames) +
                       " (each holds the previous one)");
  return Status();
}

Result<std::vector<Motion>> selectTracks(MotionSet set, const TrackChoice& choice,
                                         const std::string& path) {
  std::vector<Motion>& tracks = set.tracks;
  std::stable_sort(tracks.begin(), tracks.end(),
                   [](const Motion& a, const Motion& b) { return idLess(a.track, b.track); });
  // Two tracks of one id would share an output and a --track pick (a JSON
  // id 1 and "1"): refused before anything is written.
  for (size_t i = 1; i < tracks.size(); ++i)
    if (tracks[i].track == tracks[i - 1].track)
      return makeError(path + ": two tracks have the id " + printable(tracks[i].track, 64) +
                       "; give them distinct ids");
  const bool named = tracks.size() > 1 || !tracks.front().track.empty();
  size_t pick = 0;
  if (choice.kind == TrackChoice::Kind::Id) {
    if (!named)
      return makeError(path + ": no track " + printable(choice.id, 64) +
                       " (one person, no track ids)");
    while (pick < tracks.size() && tracks[pick].track != choice.id) ++pick;
    if (pick == tracks.size())
      return makeError(path + ": no track " + printable(choice.id, 64) +
                       " (tracks: " + idList(tracks) + ")");
  }
  for (size_t i = 1; choice.kind == TrackChoice::Kind::Longest && i < tracks.size(); ++i)
    if (detections(tracks[i]) > detections(tracks[pick])) pick = i;
  std::vector<Motion> out;
  for (size_t i = 0; i < tracks.size(); ++i) {
    if (choice.kind != TrackChoice::Kind::All && i != pick) continue;
    Motion m = std::move(tracks[i]);
    m.notes.insert(m.notes.begin(), set.notes.begin(), set.notes.end());
    if (tracks.size() > 1) {
      std::string note = "track " + printable(m.track, 64) + " of " +
                         std::to_string(tracks.size()) + " (source frames " + range(m) +
                         (choice.kind == TrackChoice::Kind::Longest ? ", the longest)" : ")");
      if (choice.kind == TrackChoice::Kind::Longest) {
        std::string others;
        for (size_t j = 0; j < tracks.size(); ++j)
          if (j != i)
            others += (others.empty() ? "" : ", ") + printable(tracks[j].track, 64) + " (" +
                      range(tracks[j]) + ")";
        note += "; other tracks: " + others + "; pick one with --track ID or all";
      }
      m.notes.insert(m.notes.begin() + set.notes.size(), note);
    }
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace smpl
