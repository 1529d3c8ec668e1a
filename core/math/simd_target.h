// Which vector instructions the fixed-order kernels (core/math/fixed_order_gemm.h)
// run: scalar, SSE4 (2 doubles a register), AVX2 (4) or AVX-512 (8). The
// kernels' arithmetic does not depend on the target (every output is summed
// in one fixed order, multiply then add, never fused), so every target gives
// the same bits and the choice is only about speed. By default the widest
// the CPU runs; the environment variable SMPL_EXPORT_SIMD forces one, for
// tests and benchmarks (docs/development.md).
#pragma once

#include <string>
#include <vector>

#include "core/result.h"

namespace smpl {

enum class SimdTarget { Scalar, Sse4, Avx2, Avx512 };

// "scalar", "sse4", "avx2", "avx512".
const char* simdTargetName(SimdTarget target);
// True if this CPU (and its OS) runs `target`; Scalar always. In builds
// without x86-64 kernels (WebAssembly) only Scalar.
bool cpuRunsSimd(SimdTarget target);
// The targets this CPU runs, narrowest first (Scalar first).
std::vector<SimdTarget> supportedSimdTargets();
// The target the kernels run now: the widest the CPU runs, or the one set
// by selectSimdTarget / useSimdTargetFromEnvironment.
SimdTarget activeSimdTarget();
// Makes the kernels run `target`. Errors: an unknown name (names the known
// ones); a target this CPU cannot run ("not available on this CPU").
Status selectSimdTarget(const std::string& name);
// selectSimdTarget(SMPL_EXPORT_SIMD) when the variable is set and not
// empty; nothing otherwise. The message starts with "SMPL_EXPORT_SIMD=...".
Status useSimdTargetFromEnvironment();

}  // namespace smpl
