// MuJoCo's own reading of an MJCF file written by smpl-export (--out x.xml),
// against an independent reference (mjcf_reference.py: rest joints and the
// closed rest mesh's volume from the GLB export or from the model file with
// numpy, in the model's Y-up axes). Links MuJoCo (Debian libmujoco-dev);
// smpl-export itself does not.
//
//   mjcf_check MODEL.xml REFERENCE.txt DENSITY
//
// Checks, each failing the program (exit 1, one line naming the check):
//   (a) mj_loadXML loads it; at qpos0, after mj_kinematics, every body named
//       after a reference joint exists and its xpos equals the joint turned
//       Z up, (x, y, z) -> (x, -z, y), within 1e-6 m; the model has no other
//       bodies than the world and the joints;
//   (d) the same positions read without the Z-up turn miss by more than 1 mm
//       (the check above can tell a wrong axis convention);
//   (c) every body mass > 0 and their sum equals volume * DENSITY within 1%;
//   (b) 1000 mj_step under gravity: qpos and qvel finite at every step and no
//       MuJoCo warning (an unstable simulation is reset by MuJoCo with a
//       warning, which would hide a NaN).
//
//   mjcf_check MODEL.xml REFERENCE.txt DENSITY --hulls [--wrong-frame]
//
// Also (h), --mjcf-geoms mesh (REFERENCE.txt's "hull NAME X Y Z" points from
// mjcf_reference.py --hulls): a body has a mesh geom exactly when the
// reference has hull points for it, and at qpos0 the mesh's vertices placed
// in the world by MuJoCo (geom_xpos + geom_xmat * mesh_vert: MuJoCo moves a
// mesh to its own centre and axes and offsets the geom to match) are the
// reference points turned Z up, as sets, within 1e-6 m. --wrong-frame reads
// mesh_vert in the body's frame (the offset ignored): the error must exceed
// 1 mm.
//
//   mjcf_check --motion MODEL.xml MOTION.txt [--wrong-order | --quat-xyzw]
//
// The reference motion (MOTION.txt from mjcf_reference.py --motion: the
// .qpos.npz rows read by numpy and numpy's posed joints):
//   (m) every name of the .npz's joint_names is a MuJoCo joint whose qpos
//       address is the running offset of the row (the row is in MuJoCo's
//       qpos order) and the row's length is nq; hinge values in [-pi, pi];
//   (p) at frames 0, T/2 and T-1, qpos = the row (set joint by joint, by
//       name), mj_kinematics: every body's xpos equals numpy's posed joint
//       turned Z up within 1e-5 m;
//   (k) the model has min(T, 100) keyframes; key 0 and the last key equal
//       their .npz rows (|difference| <= 1e-12) at time i / fps.
// A wrong reading must miss: --wrong-order (MODEL.xml with each body's
// hinges listed z, y, x, so MuJoCo applies Rz Ry Rx) and --quat-xyzw (every
// quaternion of the row read as x, y, z, w) require the (p) error to exceed
// 1e-3 m and skip (m) and (k).
#include <mujoco/mujoco.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Joint {
  std::string name;
  double p[3];
};

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "mjcf_check: FAIL %s\n", what.c_str());
  std::exit(1);
}

void readReference(const char* path, double* volume, std::vector<Joint>* joints,
                   std::vector<Joint>* hull = nullptr) {
  std::ifstream in(path);
  if (!in) fail(std::string("cannot read ") + path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string kind;
    s >> kind;
    if (kind == "volume") {
      s >> *volume;
    } else if (kind == "joint") {
      Joint j;
      s >> j.name >> j.p[0] >> j.p[1] >> j.p[2];
      joints->push_back(j);
    } else if (kind == "hull" && hull) {
      Joint j;
      s >> j.name >> j.p[0] >> j.p[1] >> j.p[2];
      hull->push_back(j);
    }
  }
  if (joints->empty()) fail(std::string(path) + ": no joints");
}

// Largest distance between each joint's body xpos and the joint mapped by `zup`.
double maxError(const mjModel* m, const mjData* d, const std::vector<Joint>& joints, bool zup) {
  double worst = 0.0;
  for (const Joint& j : joints) {
    const int id = mj_name2id(m, mjOBJ_BODY, j.name.c_str());
    if (id < 0) fail("(a) no body named '" + j.name + "'");
    const double want[3] = {j.p[0], zup ? -j.p[2] : j.p[1], zup ? j.p[1] : j.p[2]};
    double e = 0.0;
    for (int c = 0; c < 3; ++c)
      e += (d->xpos[3 * id + c] - want[c]) * (d->xpos[3 * id + c] - want[c]);
    worst = std::fmax(worst, std::sqrt(e));
  }
  return worst;
}

void checkRest(const mjModel* m, mjData* d, const std::vector<Joint>& joints) {
  if (m->nbody != int(joints.size()) + 1)
    fail("(a) " + std::to_string(m->nbody - 1) + " bodies besides the world; the reference has " +
         std::to_string(joints.size()) + " joints");
  mj_kinematics(m, d);
  const double zup = maxError(m, d, joints, true), yup = maxError(m, d, joints, false);
  std::printf("(a) rest joints, Z up: max |xpos - J| = %.3g m (tolerance 1e-6)\n", zup);
  std::printf("(d) the same read Y up (no turn): max error %.3g m (must exceed 1e-3)\n", yup);
  if (!(zup <= 1e-6)) fail("(a) body positions differ from the rest joints turned Z up");
  if (!(yup > 1e-3)) fail("(d) the Y-up reading matches too: the check cannot tell the axes");
}

void checkMass(const mjModel* m, double volume, double density) {
  double total = 0.0;
  for (int b = 1; b < m->nbody; ++b) {
    if (!(m->body_mass[b] > 0)) fail("(c) body " + std::to_string(b) + " has mass <= 0");
    total += m->body_mass[b];
  }
  const double want = volume * density, rel = std::fabs(total - want) / want;
  std::printf("(c) sum of masses %.9g kg; volume %.9g m^3 x %g kg/m^3 = %.9g kg; rel. diff %.3g\n",
              total, volume, density, want, rel);
  if (!(rel <= 0.01)) fail("(c) the masses do not sum to volume x density (1%)");
}

void checkSteps(const mjModel* m, mjData* d) {
  mj_resetData(m, d);
  for (int step = 0; step < 1000; ++step) {
    mj_step(m, d);
    for (int i = 0; i < m->nq; ++i)
      if (!std::isfinite(d->qpos[i])) fail("(b) qpos not finite at step " + std::to_string(step));
    for (int i = 0; i < m->nv; ++i)
      if (!std::isfinite(d->qvel[i])) fail("(b) qvel not finite at step " + std::to_string(step));
    for (int w = 0; w < mjNWARNING; ++w)
      if (d->warning[w].number > 0)
        fail("(b) MuJoCo warning " + std::to_string(w) + " at step " + std::to_string(step));
  }
  std::printf("(b) 1000 steps of %g s: finite, no warnings; root at z = %.4g m\n", m->opt.timestep,
              d->qpos[2]);
}

double distance(const double* a, const double* b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// The largest distance from a point of `from` to its nearest point of `to`.
double oneSided(const std::vector<std::array<double, 3>>& from,
                const std::vector<std::array<double, 3>>& to) {
  double worst = 0.0;
  for (const auto& a : from) {
    double best = INFINITY;
    for (const auto& b : to) best = std::fmin(best, distance(a.data(), b.data()));
    worst = std::fmax(worst, best);
  }
  return worst;
}

// Mesh geom `g`'s vertices in the world at the current state.
std::vector<std::array<double, 3>> worldVertices(const mjModel* m, const mjData* d, int g,
                                                 bool wrong_frame) {
  const int mesh = m->geom_dataid[g], body = m->geom_bodyid[g];
  const double* pos = wrong_frame ? d->xpos + 3 * body : d->geom_xpos + 3 * g;
  const double* mat = wrong_frame ? d->xmat + 9 * body : d->geom_xmat + 9 * g;
  std::vector<std::array<double, 3>> out;
  for (int v = 0; v < m->mesh_vertnum[mesh]; ++v) {
    const float* p = m->mesh_vert + 3 * (m->mesh_vertadr[mesh] + v);
    std::array<double, 3> w;
    for (int r = 0; r < 3; ++r)
      w[size_t(r)] = pos[r] + mat[3 * r] * p[0] + mat[3 * r + 1] * p[1] + mat[3 * r + 2] * p[2];
    out.push_back(w);
  }
  return out;
}

void checkHulls(const mjModel* m, const mjData* d, const std::vector<Joint>& hull,
                bool wrong_frame) {
  double worst = 0.0;
  int meshes = 0;
  for (int b = 1; b < m->nbody; ++b) {
    const std::string name = mj_id2name(m, mjOBJ_BODY, b);
    std::vector<std::array<double, 3>> want;
    for (const Joint& j : hull)
      if (j.name == name) want.push_back({j.p[0], -j.p[2], j.p[1]});  // Z up
    int found = -1;
    for (int g = 0; g < m->ngeom; ++g)
      if (m->geom_bodyid[g] == b && m->geom_type[g] == mjGEOM_MESH) found = g;
    if ((found >= 0) != !want.empty())
      fail("(h) body " + name +
           (found >= 0 ? " has a mesh geom but no hull points"
                       : " has hull points but no mesh geom"));
    if (found < 0) continue;
    ++meshes;
    const auto got = worldVertices(m, d, found, wrong_frame);
    worst = std::fmax(worst, std::fmax(oneSided(got, want), oneSided(want, got)));
  }
  std::printf(
      "(h) %d mesh geoms%s: max distance between MuJoCo's world vertices and the "
      "reference points %.3g m (%s)\n",
      meshes, wrong_frame ? " read in the body frame" : "", worst,
      wrong_frame ? "must exceed 1e-3" : "tolerance 1e-6");
  if (meshes == 0) fail("(h) no mesh geoms");
  if (wrong_frame ? !(worst > 1e-3) : !(worst <= 1e-6))
    fail(wrong_frame ? "(h) the body-frame reading matches too: the check cannot tell"
                     : "(h) the mesh geoms are not the reference points");
}

struct MotionRef {
  std::vector<std::string> names;  // the MuJoCo joints in row order
  int frames = 0;
  double fps = 0.0;
  std::vector<std::pair<int, std::vector<double>>> rows;  // frame, qpos row
  std::vector<std::pair<int, Joint>> poses;               // frame, posed joint (Y up)
};

MotionRef readMotion(const char* path) {
  std::ifstream in(path);
  if (!in) fail(std::string("cannot read ") + path);
  MotionRef r;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string kind;
    s >> kind;
    if (kind == "names") {
      size_t n = 0;
      s >> n;
      r.names.resize(n);
      for (std::string& name : r.names) s >> name;
    } else if (kind == "frames") {
      s >> r.frames;
    } else if (kind == "fps") {
      s >> r.fps;
    } else if (kind == "row") {
      int f = 0;
      s >> f;
      std::vector<double> row;
      for (double v; s >> v;) row.push_back(v);
      r.rows.emplace_back(f, row);
    } else if (kind == "pose") {
      std::pair<int, Joint> p;
      s >> p.first >> p.second.name >> p.second.p[0] >> p.second.p[1] >> p.second.p[2];
      r.poses.push_back(p);
    }
  }
  if (r.names.empty() || r.rows.empty() || r.poses.empty())
    fail(std::string(path) + ": incomplete");
  return r;
}

int widthOf(int type) { return type == mjJNT_FREE ? 7 : type == mjJNT_BALL ? 4 : 1; }

// (m): the row is MuJoCo's qpos, joint by joint, in order.
void checkLayout(const mjModel* m, const MotionRef& r) {
  int offset = 0;
  for (const std::string& name : r.names) {
    const int j = mj_name2id(m, mjOBJ_JOINT, name.c_str());
    if (j < 0) fail("(m) no joint named '" + name + "'");
    if (m->jnt_qposadr[j] != offset)
      fail("(m) joint '" + name + "' at qpos " + std::to_string(m->jnt_qposadr[j]) +
           ", the row has it at " + std::to_string(offset));
    offset += widthOf(m->jnt_type[j]);
  }
  if (offset != m->nq)
    fail("(m) the joints cover " + std::to_string(offset) + " of nq " + std::to_string(m->nq));
  for (const auto& row : r.rows) {
    if (int(row.second.size()) != m->nq)
      fail("(m) row " + std::to_string(row.first) + " length differs from nq");
    for (int j = 0; j < m->njnt; ++j)
      if (m->jnt_type[j] == mjJNT_HINGE && std::fabs(row.second[size_t(m->jnt_qposadr[j])]) > M_PI)
        fail("(m) a hinge angle outside [-pi, pi] at frame " + std::to_string(row.first));
  }
  std::printf("(m) %zu joints, nq %d: the .npz row order is MuJoCo's; hinge angles in [-pi, pi]\n",
              r.names.size(), m->nq);
}

// qpos from a row, joint by joint by name; `xyzw`: quaternions read x, y, z, w.
void setQpos(const mjModel* m, mjData* d, const MotionRef& r, const std::vector<double>& row,
             bool xyzw) {
  size_t at = 0;
  for (const std::string& name : r.names) {
    const int j = mj_name2id(m, mjOBJ_JOINT, name.c_str());
    if (j < 0) fail("(m) no joint named '" + name + "'");
    const int w = widthOf(m->jnt_type[j]), adr = m->jnt_qposadr[j];
    for (int i = 0; i < w; ++i) d->qpos[adr + i] = row[at + size_t(i)];
    const int q = w == 7 ? 3 : w == 4 ? 0 : -1;  // the quaternion's first value
    if (xyzw && q >= 0)
      for (int i = 0; i < 4; ++i) d->qpos[adr + q + i] = row[at + size_t(q + (i + 3) % 4)];
    at += size_t(w);
  }
}

// (p): the largest body error over the checked frames.
double checkPoses(const mjModel* m, mjData* d, const MotionRef& r, bool xyzw) {
  double worst = 0.0;
  for (const auto& row : r.rows) {
    std::vector<Joint> joints;
    for (const auto& p : r.poses)
      if (p.first == row.first) joints.push_back(p.second);
    if (joints.empty()) continue;  // a keyframe row only
    mj_resetData(m, d);
    setQpos(m, d, r, row.second, xyzw);
    mj_kinematics(m, d);
    const double e = maxError(m, d, joints, true);
    std::printf("(p) frame %d: max |xpos - numpy posed joint| = %.3g m over %zu bodies\n",
                row.first, e, joints.size());
    worst = std::fmax(worst, e);
  }
  return worst;
}

// (k): keyframes equal the .npz rows.
void checkKeys(const mjModel* m, const MotionRef& r) {
  const int want = std::min(r.frames, 100);
  if (m->nkey != want)
    fail("(k) " + std::to_string(m->nkey) + " keyframes, expected " + std::to_string(want));
  double worst = 0.0;
  int compared = 0;
  for (const auto& row : r.rows) {
    if (row.first >= m->nkey || (row.first != 0 && row.first != m->nkey - 1)) continue;
    for (int i = 0; i < m->nq; ++i)
      worst =
          std::fmax(worst, std::fabs(m->key_qpos[row.first * m->nq + i] - row.second[size_t(i)]));
    if (std::fabs(m->key_time[row.first] - row.first / r.fps) > 1e-9)
      fail("(k) key " + std::to_string(row.first) + " time differs from i / fps");
    ++compared;
  }
  std::printf("(k) %d keyframes (T = %d); keys 0 and %d: max |key_qpos - .npz row| = %.3g\n",
              m->nkey, r.frames, m->nkey - 1, worst);
  if (compared != (m->nkey > 1 ? 2 : 1) || !(worst <= 1e-12))
    fail("(k) keyframes differ from the .npz rows");
}

int motionMain(int argc, char** argv) {
  const std::string mode = argc == 5 ? argv[4] : "";
  if ((argc != 4 && argc != 5) || (argc == 5 && mode != "--wrong-order" && mode != "--quat-xyzw"))
    fail("usage: mjcf_check --motion MODEL.xml MOTION.txt [--wrong-order | --quat-xyzw]");
  const MotionRef r = readMotion(argv[3]);
  char error[1000] = "";
  mjModel* m = mj_loadXML(argv[2], nullptr, error, sizeof error);
  if (!m) fail(std::string("(m) mj_loadXML: ") + error);
  mjData* d = mj_makeData(m);
  if (mode.empty()) checkLayout(m, r);
  const double worst = checkPoses(m, d, r, mode == "--quat-xyzw");
  if (mode.empty()) {
    std::printf("(p) max joint error %.3g m (tolerance 1e-5)\n", worst);
    if (!(worst <= 1e-5)) fail("(p) MuJoCo's bodies differ from numpy's posed joints");
    checkKeys(m, r);
  } else {
    std::printf("(p) %s: max joint error %.3g m (must exceed 1e-3)\n", mode.c_str(), worst);
    if (!(worst > 1e-3)) fail("(p) " + mode + " matches too: the check cannot tell the convention");
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  std::printf("mjcf_check --motion: OK\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::string(argv[1]) == "--motion") return motionMain(argc, argv);
  const std::string mode = argc >= 5 ? argv[4] : "";
  const bool wrong_frame = argc == 6 && std::string(argv[5]) == "--wrong-frame";
  if (argc < 4 || (argc >= 5 && mode != "--hulls") || (argc == 6 && !wrong_frame) || argc > 6)
    fail("usage: mjcf_check MODEL.xml REFERENCE.txt DENSITY [--hulls [--wrong-frame]]");
  double volume = 0.0;
  std::vector<Joint> joints, hull;
  readReference(argv[2], &volume, &joints, &hull);
  char error[1000] = "";
  mjModel* m = mj_loadXML(argv[1], nullptr, error, sizeof error);
  if (!m) fail(std::string("(a) mj_loadXML: ") + error);
  if (error[0]) std::printf("mj_loadXML warning: %s\n", error);
  mjData* d = mj_makeData(m);
  std::printf("%s: %d bodies, nq %d, nv %d, %d geoms\n", argv[1], m->nbody, m->nq, m->nv, m->ngeom);
  checkRest(m, d, joints);
  if (mode == "--hulls") checkHulls(m, d, hull, wrong_frame);
  checkMass(m, volume, std::atof(argv[3]));
  checkSteps(m, d);
  mj_deleteData(d);
  mj_deleteModel(m);
  std::printf("mjcf_check: OK\n");
  return 0;
}
