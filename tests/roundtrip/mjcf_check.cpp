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
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
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

void readReference(const char* path, double* volume, std::vector<Joint>* joints) {
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

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) fail("usage: mjcf_check MODEL.xml REFERENCE.txt DENSITY");
  double volume = 0.0;
  std::vector<Joint> joints;
  readReference(argv[2], &volume, &joints);
  char error[1000] = "";
  mjModel* m = mj_loadXML(argv[1], nullptr, error, sizeof error);
  if (!m) fail(std::string("(a) mj_loadXML: ") + error);
  if (error[0]) std::printf("mj_loadXML warning: %s\n", error);
  mjData* d = mj_makeData(m);
  std::printf("%s: %d bodies, nq %d, nv %d, %d geoms\n", argv[1], m->nbody, m->nq, m->nv, m->ngeom);
  checkRest(m, d, joints);
  checkMass(m, volume, std::atof(argv[3]));
  checkSteps(m, d);
  mj_deleteData(d);
  mj_deleteModel(m);
  std::printf("mjcf_check: OK\n");
  return 0;
}
