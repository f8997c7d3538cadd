// The BLAS kernels the networks' matrix products run on. Debian's libtorch multiplies through
// OpenBLAS, which picks its kernels from the CPU model when it is loaded; OpenBLAS 0.3.21 does not
// know recent Xeons (e.g. Sapphire Rapids) and falls back to its oldest x86-64 kernels (Prescott,
// SSE3): the networks' products then take about 3x as long (model_bench
// BM_SparseConvolutionLayer, run with and without OPENBLAS_CORETYPE). Where OpenBLAS fell back so
// and the user has not chosen (OPENBLAS_CORETYPE unset), the executable's start-up (before main,
// before any product) names the newest kernel family the CPU and the OS run — SkylakeX with
// AVX-512 (F, DQ, BW, VL), Haswell with AVX2 and FMA — and has OpenBLAS choose again. Elsewhere
// (OpenBLAS knew the CPU, another BLAS, not x86-64) nothing changes.
#pragma once

namespace sagrid {

// The kernel family named at start-up, or nullptr where nothing was named. Calling it links the
// start-up choice into the executable (it is made in the object file that defines it).
const char* blasKernelsNamed();

}  // namespace sagrid
