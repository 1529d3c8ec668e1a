// Eigen's matrix products (GEMM) split their inner dimension into blocks
// whose depth Eigen derives from the CPU's cache sizes (CPUID on x86-64, fixed
// defaults elsewhere: WebAssembly has no CPUID), and that split decides the
// order of the sums. So the same product rounds differently on CPUs with other
// caches and in the WebAssembly build. Fixed cache sizes make the blocking,
// and so the bytes of every output, the same on every machine and build.
#pragma once

namespace smpl {

// Sets Eigen's cache sizes to fixed values (L1 48 KiB, L2 1 MiB, L3 32 MiB:
// a current x86-64 core's) once per process; later calls do nothing. Call it
// before the first matrix product (main(), exportAsset()); thread-safe.
void useFixedEigenBlocking();

}  // namespace smpl
