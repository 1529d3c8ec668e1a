#include "core/math/simd_target.h"

#include <atomic>
#include <cstdlib>

#include "core/math/fixed_order_gemm_targets.h"

namespace smpl {
namespace {

constexpr SimdTarget kAll[] = {SimdTarget::Scalar, SimdTarget::Sse4, SimdTarget::Avx2,
                               SimdTarget::Avx512};

// -1: not chosen yet (the widest, decided at the first use).
std::atomic<int> g_active{-1};

}  // namespace

const char* simdTargetName(SimdTarget target) {
  switch (target) {
    case SimdTarget::Sse4:
      return "sse4";
    case SimdTarget::Avx2:
      return "avx2";
    case SimdTarget::Avx512:
      return "avx512";
    default:
      return "scalar";
  }
}

bool cpuRunsSimd(SimdTarget target) {
#if SMPL_FIXED_ORDER_X86
  // libgcc's checks include the OS saving the ymm / zmm state.
  switch (target) {
    case SimdTarget::Sse4:
      return __builtin_cpu_supports("sse4.1");
    case SimdTarget::Avx2:
      return __builtin_cpu_supports("avx2");
    case SimdTarget::Avx512:
      return __builtin_cpu_supports("avx512f");
    default:
      return true;
  }
#else
  return target == SimdTarget::Scalar;
#endif
}

std::vector<SimdTarget> supportedSimdTargets() {
  std::vector<SimdTarget> out;
  for (SimdTarget t : kAll)
    if (cpuRunsSimd(t)) out.push_back(t);
  return out;
}

SimdTarget activeSimdTarget() {
  int v = g_active.load(std::memory_order_relaxed);
  if (v < 0) {
    v = int(supportedSimdTargets().back());  // the widest: scalar is always there
    g_active.store(v, std::memory_order_relaxed);
  }
  return SimdTarget(v);
}

Status selectSimdTarget(const std::string& name) {
  for (SimdTarget t : kAll) {
    if (name != simdTargetName(t)) continue;
    if (!cpuRunsSimd(t))
      return makeError(
          name + " is not available on this CPU (it runs: " +
              [] {
                std::string s;
                for (SimdTarget u : supportedSimdTargets())
                  s += (s.empty() ? "" : ", ") + std::string(simdTargetName(u));
                return s;
              }() +
              ")",
          ErrorKind::Usage);
    g_active.store(int(t), std::memory_order_relaxed);
    return Status::success();
  }
  return makeError("unknown target '" + name + "' (expected scalar, sse4, avx2 or avx512)",
                   ErrorKind::Usage);
}

Status useSimdTargetFromEnvironment() {
  const char* value = std::getenv("SMPL_EXPORT_SIMD");
  if (!value || !*value) return Status::success();
  Status st = selectSimdTarget(value);
  if (st) return st;
  std::string shown;  // the variable's text, short and printable, for the error line
  for (const char* v = value; *v && shown.size() < 40; ++v)
    shown += (*v >= 0x20 && *v < 0x7f) ? *v : '?';
  return makeError("SMPL_EXPORT_SIMD=" + shown + ": " + st.message(), ErrorKind::Usage);
}

}  // namespace smpl
