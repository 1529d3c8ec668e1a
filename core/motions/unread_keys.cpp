#include "core/motions/unread_keys.h"

#include <algorithm>
#include <cctype>

#include "core/io/printable.h"

namespace smpl {
namespace {

std::string lower(const std::string& key) {
  std::string k = key;
  std::transform(k.begin(), k.end(), k.begin(), [](unsigned char c) { return std::tolower(c); });
  return k;
}

bool containsAny(const std::string& key, std::initializer_list<const char*> words) {
  const std::string k = lower(key);
  for (const char* word : words)
    if (k.find(word) != std::string::npos) return true;
  return false;
}

// One ignored key, and how often the same name recurs (per track, per frame).
struct Unread {
  std::string name;   // the array's own key: what groups repeats
  std::string first;  // "people/0/extra_pose (30,45)"
  size_t count = 0;
};

void add(std::vector<Unread>* out, const std::string& name, const std::string& path,
         const std::vector<int64_t>& shape) {
  for (Unread& u : *out)
    if (u.name == name) {
      ++u.count;
      return;
    }
  out->push_back({name, path + " " + shapeString(shape), 1});
}

// `covered`: an ancestor List was fetched, so its elements were read with it
// (stackList and the row readers take a fetched list whole); a Dict's
// children need their own fetch.
void walk(const DataNode& node, const std::string& path, const std::string& name, bool covered,
          std::vector<Unread>* out) {
  covered = covered || node.read;
  switch (node.kind) {
    case DataNode::Kind::None:
      return;
    case DataNode::Kind::Array:
      if (!covered && !node.array.isString() && node.array.strings.empty() &&
          looksLikeBodyData(name))
        add(out, name, path, node.array.shape);
      return;
    case DataNode::Kind::List:
      for (size_t i = 0; i < node.children.size(); ++i)
        walk(node.children[i], (path.empty() ? "" : path + "/") + std::to_string(i), name, covered,
             out);
      return;
    case DataNode::Kind::Dict:
      for (size_t i = 0; i < node.children.size(); ++i)
        walk(node.children[i], path.empty() ? node.keys[i] : path + "/" + node.keys[i],
             node.keys[i], false, out);
      return;
  }
}

bool named(const std::string& name, const std::vector<std::string>& notes) {
  for (const std::string& note : notes)
    if (note.find(name) != std::string::npos) return true;
  return false;
}

}  // namespace

bool looksLikePose(const std::string& key) {
  return containsAny(key, {"pose", "rot", "theta", "orient", "joint", "motion"});
}

bool looksLikeBodyData(const std::string& key) {
  return looksLikePose(key) ||
         containsAny(key, {"hand", "jaw", "eye", "expression", "trans", "betas", "shape"});
}

void clearReadMarks(const DataNode& root) {
  root.read = false;
  for (const DataNode& child : root.children) clearReadMarks(child);
}

std::string unreadKeysNote(const DataNode& root, const std::vector<UndecodedMember>& undecoded,
                           const std::string& row, const std::vector<std::string>& notes) {
  std::vector<Unread> unread;
  if (root.isDict() || root.isList()) walk(root, "", "", false, &unread);
  for (const UndecodedMember& m : undecoded)
    if (looksLikeBodyData(m.name)) add(&unread, m.name, m.name, m.shape);
  std::string list;
  size_t shown = 0, more = 0;
  for (const Unread& u : unread) {
    if (named(u.name, notes)) continue;
    if (shown == 8 || list.size() > 400) {
      ++more;
      continue;
    }
    list += (shown++ ? ", " : "") + printable(u.first, 96);
    if (u.count > 1) list += " in " + std::to_string(u.count) + " entries";
  }
  if (list.empty()) return "";
  if (more) list += ", ... (" + std::to_string(more) + " more)";
  return "ignored: " + list + " (arrays the " + row + " reader does not read)";
}

}  // namespace smpl
