// smpl-bench --compare (compare.h). Every number comes from this one run:
//  - load: loadModel() of the full-size SMPL stand-in as a Python 2 chumpy
//    .pkl, a stored .npz and a deflated .npz (tools/bench/make_standin.py),
//    warm (read once first), median of 5, MB of file per wall second; and
//    the deflated file's inflate + CRC alone (its cap);
//  - whole-process CLI export: smpl-export --model <stand-in .pkl> --out
//    x.glb / x.fbx, process start to exit, median of 3;
//  - in-process write: GLB and FBX (--fbx-compress-level 1, 0, 6) serialisation
//    of the same asset, median of 5, with the file sizes;
//  - forward pass: forwardBatch on 1 thread vs smplx.SMPL (the authors'
//    PyTorch code, tools/bench/smplx_forward_time.py) on 1 thread, same model,
//    same frame count and batch size, CPU time per frame (robust to other load),
//    with posedirs packed once beforehand (smplx builds its model before
//    timing too) into a result matrix reused between the passes (smplx
//    reuses its buffers), and once more as the plain call (packing and a
//    fresh result each call); and the limit:
//    the model's multiply-adds per frame at this core's multiply-add peak,
//    measured here by a timed FMA loop for the kernel set forwardBatch runs;
//  - Blender 3.4's own glTF and FBX exporters writing the asset smpl-export
//    wrote (imported first; only the export is timed);
//  - a 10-minute 120 fps clip exported by the CLI: its peak resident memory
//    (the child's ru_maxrss) against the size of the GLB it wrote.
#include "tools/bench/compare.h"

#include <immintrin.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/io/npz.h"
#include "core/math/forward_batch.h"
#include "core/math/pose_sampler.h"
#include "core/models/model_loader.h"
#include "exporter/pipeline.h"
#include "writers/writer.h"

namespace smpl {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const char* const kStandins[] = {"standin_smpl_py2.pkl", "standin_smpl_stored.npz",
                                 "standin_smpl_deflated.npz", "standin_motion_10min.npz"};

double seconds(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double clockSeconds(clockid_t clock) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return ts.tv_sec + ts.tv_nsec * 1e-9;
}
double threadCpuSeconds() { return clockSeconds(CLOCK_THREAD_CPUTIME_ID); }

// CPU seconds (user + system) of this process, or of its finished children.
double cpuSeconds(bool children) {
  if (!children) return clockSeconds(CLOCK_PROCESS_CPUTIME_ID);
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Median wall and CPU seconds of `repeats` calls (CPU: this process's, or
// its children's when fn runs a program). On a loaded machine wall time
// includes waiting for a core; CPU time does not.
struct Timing {
  double wall = -1, cpu = -1;
};
Timing medianSeconds(int repeats, const std::function<void()>& fn, bool children = false) {
  std::vector<double> wall, cpu;
  for (int i = 0; i < repeats; ++i) {
    const double cpu0 = cpuSeconds(children);
    const auto start = Clock::now();
    fn();
    wall.push_back(seconds(start));
    cpu.push_back(cpuSeconds(children) - cpu0);
  }
  return {median(wall), median(cpu)};
}

std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Runs a shell command; returns its exit status and combined output.
int run(const std::string& command, std::string* output) {
  output->clear();
  FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (!p) return -1;
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) output->append(buf, n);
  const int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The value after `tag` on the line that starts with it, or a negative number.
double field(const std::string& text, const std::string& tag, int index = 0) {
  const size_t at = text.find(tag + " ");
  if (at == std::string::npos) return -1;
  const char* p = text.c_str() + at + tag.size();
  for (int i = 0; i < index; ++i) std::strtod(p, const_cast<char**>(&p));
  return std::strtod(p, nullptr);
}

bool ensureStandins(const std::string& dir) {
  bool present = true;
  for (const char* name : kStandins) present = present && fs::exists(fs::path(dir) / name);
  if (present) return true;
  std::printf("making the full-size stand-in in %s ...\n", dir.c_str());
  std::string out;
  const int rc = run("/usr/bin/python3 " +
                         quote(std::string(SMPL_SOURCE_DIR) + "/tools/bench/make_standin.py") +
                         " " + quote(dir),
                     &out);
  if (rc != 0)
    std::fprintf(stderr, "smpl-bench: make_standin.py failed (%d): %s\n", rc, out.c_str());
  return rc == 0;
}

void row(const char* what, const std::string& ours, const std::string& peer,
         const std::string& ratio) {
  std::printf("| %-56s | %-16s | %-26s | %-16s |\n", what, ours.c_str(), peer.c_str(),
              ratio.c_str());
}

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

void compareLoad(const std::string& dir) {
  const char* names[] = {"load .pkl (py2 chumpy, latin-1 payloads)", "load .npz (stored)",
                         "load .npz (deflated)"};
  for (int i = 0; i < 3; ++i) {
    const std::string path = (fs::path(dir) / kStandins[i]).string();
    const double mb = fs::file_size(path) / 1e6;
    (void)loadModel(path);  // warm: the file is in the page cache
    const Timing t = medianSeconds(5, [&] { (void)loadModel(path); });
    row(names[i], fmt("%.0f", mb / t.wall) + fmt(" / %.0f MB/s", mb / t.cpu),
        fmt("%.1f MB file", mb), "");
  }
  // The deflated file's cap: inflating (libdeflate) and CRC-checking every
  // member into fresh buffers, nothing decoded; the load above can't beat it.
  const std::string path = (fs::path(dir) / kStandins[2]).string();
  const double mb = fs::file_size(path) / 1e6;
  Result<NpzArchive> npz = NpzArchive::open(path);
  if (!npz) return row("  inflate + CRC only", npz.message(), "", "");
  const Timing t = medianSeconds(5, [&] {
    for (const std::string& key : npz->keys()) (void)npz->memberView(key);
  });
  row("  of which inflate + CRC alone (libdeflate, no decoding)",
      fmt("%.0f", mb / t.wall) + fmt(" / %.0f MB/s", mb / t.cpu), fmt("%.1f MB file", mb), "");
}

struct CliTimes {
  Timing glb, fbx, glb_truncated;  // default options; --skin-weights truncated (no weight fit)
  std::string glb_path;
};

CliTimes compareCli(const std::string& dir) {
  CliTimes t;
  const std::string model = (fs::path(dir) / kStandins[0]).string();
  struct Run {
    const char* ext;
    const char* extra;
    Timing* timing;
  };
  for (const Run& r : {Run{"glb", "", &t.glb}, Run{"fbx", "", &t.fbx},
                       Run{"glb", " --skin-weights truncated", &t.glb_truncated}}) {
    const std::string stem = *r.extra ? "cli_truncated." : "cli.";
    const std::string out = (fs::path(dir) / (stem + r.ext)).string();
    std::string log;
    bool ok = true;
    const Timing s = medianSeconds(
        3,
        [&] {
          ok = ok && run(quote(SMPL_EXPORT_BIN) + " --model " + quote(model) + " --out " +
                             quote(out) + r.extra,
                         &log) == 0;
        },
        /*children=*/true);
    if (!ok) std::fprintf(stderr, "smpl-bench: smpl-export failed: %s\n", log.c_str());
    *r.timing = ok ? s : Timing();
    if (r.timing == &t.glb) t.glb_path = out;
  }
  row("whole-process CLI export, .pkl -> .glb",
      fmt("%.2f", t.glb.wall) + fmt(" / %.2f s", t.glb.cpu), "", "");
  row("whole-process CLI, .pkl -> .glb, truncated weights",
      fmt("%.2f", t.glb_truncated.wall) + fmt(" / %.2f s", t.glb_truncated.cpu), "", "");
  row("whole-process CLI export, .pkl -> .fbx",
      fmt("%.2f", t.fbx.wall) + fmt(" / %.2f s", t.fbx.cpu), "",
      fmt("%.2f", t.fbx.wall / t.glb.wall) + fmt(" / %.2fx GLB", t.fbx.cpu / t.glb.cpu));
  return t;
}

// GLB, then FBX at --fbx-compress-level 1 (the default), 0 (stored) and 6:
// serialisation time and file size (what the README's FBX level table shows).
void compareWrite(const BodyModel& model) {
  Result<Asset> asset = buildAsset(model, ExportOptions());
  if (!asset) return row("in-process write", asset.message(), "", "");
  const Writer* glb = writerForPath("x.glb");
  size_t glb_size = 0;
  const Timing g = medianSeconds(5, [&] {
    Result<std::string> b = glb->serialize(*asset, WriterOptions());
    glb_size = b ? b->size() : 0;
  });
  row("in-process write GLB", fmt("%.0f", 1e3 * g.wall) + fmt(" / %.0f ms", 1e3 * g.cpu),
      fmt("%.1f MB", glb_size / 1e6), "");
  const Writer* fbx = writerForPath("x.fbx");
  for (int level : {1, 0, 6}) {
    WriterOptions o;
    o.fbx_compress_level = level;
    size_t size = 0;
    const Timing t = medianSeconds(5, [&] {
      Result<std::string> b = fbx->serialize(*asset, o);
      size = b ? b->size() : 0;
    });
    const std::string what = "in-process write FBX, --fbx-compress-level " + std::to_string(level) +
                             (level == 1 ? " (default)" : "");
    row(what.c_str(), fmt("%.0f", 1e3 * t.wall) + fmt(" / %.0f ms", 1e3 * t.cpu),
        fmt("%.1f MB", size / 1e6),
        fmt("%.1f", t.wall / g.wall) + fmt(" / %.1fx GLB", t.cpu / g.cpu));
  }
}

// Timed loops of independent multiply-adds, 12 accumulators (more than
// FMA latency x ports on current cores), `iters` x 12 x lanes in all; the
// asm barrier keeps the compiler from folding the loop. Returns a value
// that depends on every accumulator.
__attribute__((target("avx512f,fma"), noinline)) float fmaLoopAvx512(long iters) {
  const __m512 a = _mm512_set1_ps(0.999999f), b = _mm512_set1_ps(1e-7f);
  __m512 c0 = _mm512_set1_ps(1.0f), c1 = c0, c2 = c0, c3 = c0, c4 = c0, c5 = c0, c6 = c0, c7 = c0,
         c8 = c0, c9 = c0, c10 = c0, c11 = c0;
  for (long i = 0; i < iters; ++i) {
    c0 = _mm512_fmadd_ps(c0, a, b), c1 = _mm512_fmadd_ps(c1, a, b), c2 = _mm512_fmadd_ps(c2, a, b);
    c3 = _mm512_fmadd_ps(c3, a, b), c4 = _mm512_fmadd_ps(c4, a, b), c5 = _mm512_fmadd_ps(c5, a, b);
    c6 = _mm512_fmadd_ps(c6, a, b), c7 = _mm512_fmadd_ps(c7, a, b), c8 = _mm512_fmadd_ps(c8, a, b);
    c9 = _mm512_fmadd_ps(c9, a, b), c10 = _mm512_fmadd_ps(c10, a, b);
    c11 = _mm512_fmadd_ps(c11, a, b);
    __asm__ volatile(""
                     : "+v"(c0), "+v"(c1), "+v"(c2), "+v"(c3), "+v"(c4), "+v"(c5), "+v"(c6),
                       "+v"(c7), "+v"(c8), "+v"(c9), "+v"(c10), "+v"(c11));
  }
  const __m512 s =
      _mm512_add_ps(_mm512_add_ps(_mm512_add_ps(_mm512_add_ps(c0, c1), _mm512_add_ps(c2, c3)),
                                  _mm512_add_ps(_mm512_add_ps(c4, c5), _mm512_add_ps(c6, c7))),
                    _mm512_add_ps(_mm512_add_ps(c8, c9), _mm512_add_ps(c10, c11)));
  alignas(64) float out[16];
  _mm512_store_ps(out, s);
  return out[0] + out[15];
}

__attribute__((target("avx2,fma"), noinline)) float fmaLoopAvx2(long iters) {
  const __m256 a = _mm256_set1_ps(0.999999f), b = _mm256_set1_ps(1e-7f);
  __m256 c0 = _mm256_set1_ps(1.0f), c1 = c0, c2 = c0, c3 = c0, c4 = c0, c5 = c0, c6 = c0, c7 = c0,
         c8 = c0, c9 = c0, c10 = c0, c11 = c0;
  for (long i = 0; i < iters; ++i) {
    c0 = _mm256_fmadd_ps(c0, a, b), c1 = _mm256_fmadd_ps(c1, a, b), c2 = _mm256_fmadd_ps(c2, a, b);
    c3 = _mm256_fmadd_ps(c3, a, b), c4 = _mm256_fmadd_ps(c4, a, b), c5 = _mm256_fmadd_ps(c5, a, b);
    c6 = _mm256_fmadd_ps(c6, a, b), c7 = _mm256_fmadd_ps(c7, a, b), c8 = _mm256_fmadd_ps(c8, a, b);
    c9 = _mm256_fmadd_ps(c9, a, b), c10 = _mm256_fmadd_ps(c10, a, b);
    c11 = _mm256_fmadd_ps(c11, a, b);
    __asm__ volatile(""
                     : "+x"(c0), "+x"(c1), "+x"(c2), "+x"(c3), "+x"(c4), "+x"(c5), "+x"(c6),
                       "+x"(c7), "+x"(c8), "+x"(c9), "+x"(c10), "+x"(c11));
  }
  const __m256 s =
      _mm256_add_ps(_mm256_add_ps(_mm256_add_ps(_mm256_add_ps(c0, c1), _mm256_add_ps(c2, c3)),
                                  _mm256_add_ps(_mm256_add_ps(c4, c5), _mm256_add_ps(c6, c7))),
                    _mm256_add_ps(_mm256_add_ps(c8, c9), _mm256_add_ps(c10, c11)));
  alignas(32) float out[8];
  _mm256_store_ps(out, s);
  return out[0] + out[7];
}

// Baseline x86-64 (what the portable kernels get): SSE2 multiply then add,
// counted as one multiply-add per lane.
__attribute__((noinline)) float fmaLoopSse2(long iters) {
  const __m128 a = _mm_set1_ps(0.999999f), b = _mm_set1_ps(1e-7f);
  __m128 c0 = _mm_set1_ps(1.0f), c1 = c0, c2 = c0, c3 = c0, c4 = c0, c5 = c0, c6 = c0, c7 = c0,
         c8 = c0, c9 = c0, c10 = c0, c11 = c0;
  for (long i = 0; i < iters; ++i) {
    c0 = _mm_add_ps(_mm_mul_ps(c0, a), b), c1 = _mm_add_ps(_mm_mul_ps(c1, a), b);
    c2 = _mm_add_ps(_mm_mul_ps(c2, a), b), c3 = _mm_add_ps(_mm_mul_ps(c3, a), b);
    c4 = _mm_add_ps(_mm_mul_ps(c4, a), b), c5 = _mm_add_ps(_mm_mul_ps(c5, a), b);
    c6 = _mm_add_ps(_mm_mul_ps(c6, a), b), c7 = _mm_add_ps(_mm_mul_ps(c7, a), b);
    c8 = _mm_add_ps(_mm_mul_ps(c8, a), b), c9 = _mm_add_ps(_mm_mul_ps(c9, a), b);
    c10 = _mm_add_ps(_mm_mul_ps(c10, a), b), c11 = _mm_add_ps(_mm_mul_ps(c11, a), b);
    __asm__ volatile(""
                     : "+x"(c0), "+x"(c1), "+x"(c2), "+x"(c3), "+x"(c4), "+x"(c5), "+x"(c6),
                       "+x"(c7), "+x"(c8), "+x"(c9), "+x"(c10), "+x"(c11));
  }
  const __m128 s = _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_add_ps(c0, c1), _mm_add_ps(c2, c3)),
                                         _mm_add_ps(_mm_add_ps(c4, c5), _mm_add_ps(c6, c7))),
                              _mm_add_ps(_mm_add_ps(c8, c9), _mm_add_ps(c10, c11)));
  return _mm_cvtss_f32(s);
}

// This thread's multiply-adds per second with the kernel set's vectors:
// the best of 5 loops of ~0.1 s of thread CPU time each.
double measurePeak(Kernels kernels) {
  const int lanes = kernels == Kernels::Avx512 ? 16 : kernels == Kernels::Avx2 ? 8 : 4;
  auto loop = [&](long iters) {
    return kernels == Kernels::Avx512 ? fmaLoopAvx512(iters)
           : kernels == Kernels::Avx2 ? fmaLoopAvx2(iters)
                                      : fmaLoopSse2(iters);
  };
  long iters = 1 << 16;
  volatile float sink = 0;
  for (double t = 0; t < 0.02; iters *= 2) {  // calibrate: ~20 ms or more
    const double start = threadCpuSeconds();
    sink = sink + loop(iters);
    t = threadCpuSeconds() - start;
  }
  iters *= 4;  // ~0.1 s
  double best = 0;
  for (int r = 0; r < 5; ++r) {
    const double start = threadCpuSeconds();
    sink = sink + loop(iters);
    best = std::max(best, 12.0 * lanes * iters / (threadCpuSeconds() - start));
  }
  return best;
}

void compareForward(const BodyModel& model, const CompareOptions& o, const std::string& npz) {
  std::vector<Rotations> frames;
  for (const Eigen::VectorXd& pose : samplePoses(model.numJoints(), o.frames, 5))
    frames.push_back(rotationsFromAxisAngle(pose));
  Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  BatchInput in{&*body, &frames, nullptr, 1, o.batch};
  // Best of 3 passes. The row: posedirs packed once beforehand (as smplx
  // builds its model before timing), into one result matrix (the first
  // pass faults its pages in; smplx reuses its buffers too). Then the plain
  // call as it was measured before: packing and a fresh result each call.
  auto bestMsPerFrame = [&](const std::function<void()>& pass) {
    std::vector<double> cpu;
    for (int r = 0; r < 3; ++r) {
      const double start = threadCpuSeconds();
      pass();
      cpu.push_back(threadCpuSeconds() - start);
    }
    return 1e3 * *std::min_element(cpu.begin(), cpu.end()) / o.frames;
  };
  const double pack_start = threadCpuSeconds();
  const batch::PackedPosedirs packed = packPosedirs(model);
  const double pack_ms = 1e3 * (threadCpuSeconds() - pack_start);
  BatchInput prepared = in;
  prepared.posedirs = &packed;
  // The limit: the multiply-adds of one frame (corrective product 3N P, the
  // blend 12 per non-zero weight, the final transform 12 per vertex) at the
  // measured multiply-add peak of the kernel set forwardBatch runs, measured
  // just before our row (a core's clock follows the load on the others).
  const Kernels kernels = batch::resolveKernels(in.kernels);
  const double n = model.numVertices(), p = model.numPoseFeatures();
  const double nonzero = static_cast<double>((model.weights.array() != 0.0).count());
  const double madds = 3 * n * p + 12 * nonzero + 12 * n;
  const double peak = measurePeak(kernels);
  const double limit = 1e3 * madds / peak;
  Eigen::MatrixXd result;
  const double ours = bestMsPerFrame([&] { forwardBatch(model, prepared, &result); });
  const double fresh = bestMsPerFrame([&] { (void)forwardBatch(model, in); });
  if (o.smplx.empty()) {
    row("forward, CPU ms/frame, 1 thread", fmt("%.3f ms", ours), "smplx: absent (--smplx PATH)",
        "-");
  } else {
    std::string out;
    const int rc =
        run("OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 /usr/bin/python3 " +
                quote(std::string(SMPL_SOURCE_DIR) + "/tools/bench/smplx_forward_time.py") + " " +
                quote(o.smplx) + " " + quote(npz) + " " + std::to_string(o.frames) + " " +
                std::to_string(o.batch),
            &out);
    const double peer = field(out, "SMPLX_FORWARD");
    if (rc != 0 || peer <= 0) {
      row("forward, CPU ms/frame, 1 thread", fmt("%.3f ms", ours), "smplx: failed to run", "-");
      std::fprintf(stderr, "smpl-bench: smplx run failed: %s\n", out.c_str());
    } else {
      row("forward, CPU ms/frame, 1 thread", fmt("%.3f ms", ours), fmt("smplx/torch %.3f ms", peer),
          fmt("%.1fx", peer / ours));
    }
  }
  row("  plain call: packing + fresh 3N x T result each call", fmt("%.3f ms", fresh),
      fmt("packing alone %.1f ms", pack_ms), "");
  row("forward, multiply-adds per frame (3NP + 12 nnz(W) + 12N)", fmt("%.2f M", madds / 1e6),
      fmt("%.0f nonzero weights", nonzero), "");
  row((std::string("multiply-add peak, 1 thread, measured (") + batch::kernelsName(kernels) + ")")
          .c_str(),
      fmt("%.1f G/s", peak / 1e9), "", "");
  row("forward, limit at measured peak, ms/frame", fmt("%.3f ms", limit), "",
      fmt("ours / limit %.2f", ours / limit));
}

void compareBlender(const CompareOptions& o, const CliTimes& cli, const std::string& dir) {
  std::string out;
  if (cli.glb.wall <= 0 || run(quote(o.blender) + " --version", &out) != 0) {
    row("Blender glTF exporter", "", "Blender: absent", "-");
    return row("Blender FBX exporter", "", "Blender: absent", "-");
  }
  const int rc =
      run(quote(o.blender) + " -b --factory-startup --python-exit-code 1 --python " +
              quote(std::string(SMPL_SOURCE_DIR) + "/tools/bench/blender_export_time.py") + " -- " +
              quote(cli.glb_path) + " " + quote(dir),
          &out);
  const Timing gltf{field(out, "BLENDER_EXPORT gltf"), field(out, "BLENDER_EXPORT gltf", 1)},
      fbx{field(out, "BLENDER_EXPORT fbx"), field(out, "BLENDER_EXPORT fbx", 1)};
  if (rc != 0 || gltf.wall <= 0 || fbx.wall <= 0) {
    std::fprintf(stderr, "smpl-bench: Blender run failed: %s\n", out.c_str());
    row("Blender glTF exporter", "", "Blender: failed to run", "-");
    return row("Blender FBX exporter", "", "Blender: failed to run", "-");
  }
  row("Blender glTF exporter vs whole-process CLI",
      fmt("%.2f", cli.glb.wall) + fmt(" / %.2f s", cli.glb.cpu),
      fmt("Blender 3.4 %.2f", gltf.wall) + fmt(" / %.2f s", gltf.cpu),
      fmt("%.1f", gltf.wall / cli.glb.wall) + fmt(" / %.1fx", gltf.cpu / cli.glb.cpu));
  row("Blender glTF exporter vs CLI, truncated weights",
      fmt("%.2f", cli.glb_truncated.wall) + fmt(" / %.2f s", cli.glb_truncated.cpu),
      fmt("Blender 3.4 %.2f", gltf.wall) + fmt(" / %.2f s", gltf.cpu),
      fmt("%.1f", gltf.wall / cli.glb_truncated.wall) +
          fmt(" / %.1fx", gltf.cpu / cli.glb_truncated.cpu));
  row("Blender FBX exporter vs whole-process CLI",
      fmt("%.2f", cli.fbx.wall) + fmt(" / %.2f s", cli.fbx.cpu),
      fmt("Blender 3.4 %.2f", fbx.wall) + fmt(" / %.2f s", fbx.cpu),
      fmt("%.1f", fbx.wall / cli.fbx.wall) + fmt(" / %.1fx", fbx.cpu / cli.fbx.cpu));
}

// Runs argv (no shell) and waits for it: exit status, wall seconds and the
// child's own peak resident set in bytes (wait4's ru_maxrss, KiB on Linux).
struct Measured {
  int status = -1;
  double wall = 0;
  double peak_bytes = 0;
};
Measured runMeasured(const std::vector<std::string>& argv) {
  Measured m;
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const auto start = Clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    execv(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (pid < 0 || wait4(pid, &status, 0, &usage) != pid) return m;
  m.wall = seconds(start);
  m.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  m.peak_bytes = double(usage.ru_maxrss) * 1024.0;
  return m;
}

void compareLongClip(const std::string& dir) {
  const std::string out = (fs::path(dir) / "long_clip.glb").string();
  const Measured m =
      runMeasured({SMPL_EXPORT_BIN, "--model", (fs::path(dir) / kStandins[0]).string(), "--motion",
                   (fs::path(dir) / kStandins[3]).string(), "--out", out, "-q"});
  std::error_code ec;
  const double size = m.status == 0 ? double(fs::file_size(out, ec)) : 0;
  if (m.status != 0 || size <= 0)
    return row("10-minute clip, 120 fps: peak RSS / output", "smpl-export failed", "", "-");
  row("10-minute clip, 120 fps (.pkl + AMASS .npz -> .glb)", fmt("%.1f s", m.wall),
      fmt("%.0f MB GLB", size / 1e6), "");
  row("  its peak resident memory", fmt("%.0f MB", m.peak_bytes / 1e6), "",
      fmt("%.2fx the output", m.peak_bytes / size));
  fs::remove(out, ec);
}

}  // namespace

int runCompare(const CompareOptions& o) {
  const std::string dir =
      o.standin.empty() ? (fs::temp_directory_path() / "smpl-bench-standin").string() : o.standin;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!ensureStandins(dir)) return 1;
  const std::string npz = (fs::path(dir) / kStandins[1]).string();
  Result<BodyModel> model = loadModel(npz);
  if (!model) return std::fprintf(stderr, "smpl-bench: %s\n", model.message().c_str()), 1;
  std::printf(
      "Side by side: full-size SMPL stand-in (%lld vertices, %d pose features), %d forward "
      "frames.\n"
      "Times are wall / CPU (user + system, all threads); ratios are peer / smpl-export.\n\n",
      static_cast<long long>(model->numVertices()), model->numPoseFeatures(), o.frames);
  row("measure", "smpl-export", "peer", "ratio");
  std::printf("|%s|%s|%s|%s|\n", std::string(58, '-').c_str(), std::string(18, '-').c_str(),
              std::string(28, '-').c_str(), std::string(18, '-').c_str());
  compareLoad(dir);
  const CliTimes cli = compareCli(dir);
  compareWrite(*model);
  compareForward(*model, o, npz);
  compareBlender(o, cli, dir);
  compareLongClip(dir);
  return 0;
}

}  // namespace smpl
