#include "core/common/blas_kernels.h"

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>

namespace sagrid {

namespace {

// OpenBLAS's kernel family for an x86-64 CPU it does not recognise.
constexpr const char* kFallbackKernels = "Prescott";

const char* newestKernelsRunHere() {
#if defined(__x86_64__) && defined(__GNUC__)
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
      __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl"))
    return "SkylakeX";
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return "Haswell";
#endif
  return nullptr;
}

// OpenBLAS built with run-time kernel choice (Debian's) exports its kernel table pointer and the
// function that fills it from OPENBLAS_CORETYPE when the pointer is empty.
const char* chooseNewerKernels() {
  if (std::getenv("OPENBLAS_CORETYPE")) return nullptr;  // the user's choice stands
  using CoreName = char* (*)();
  using DynamicInit = void (*)();
  const auto coreName = reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  const auto choose = reinterpret_cast<DynamicInit>(dlsym(RTLD_DEFAULT, "gotoblas_dynamic_init"));
  auto* const table = static_cast<void**>(dlsym(RTLD_DEFAULT, "gotoblas"));
  if (!coreName || !choose || !table || !*table) return nullptr;
  if (std::strcmp(coreName(), kFallbackKernels) != 0) return nullptr;  // OpenBLAS knew this CPU
  const char* kernels = newestKernelsRunHere();
  if (!kernels || setenv("OPENBLAS_CORETYPE", kernels, 0) != 0) return nullptr;
  *table = nullptr;
  choose();
  return std::strcmp(coreName(), kernels) == 0 ? kernels : nullptr;
}

// Before main: no product has run yet and no other thread multiplies.
const char* const g_named = chooseNewerKernels();

}  // namespace

const char* blasKernelsNamed() { return g_named; }

}  // namespace sagrid
