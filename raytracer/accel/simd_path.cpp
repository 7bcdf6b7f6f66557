#include "raytracer/accel/simd_path.hpp"

#include <cstdlib>
#include <cstring>

namespace sweeptrace {

bool cpu_has_avx2() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2");
}

SimdPath default_simd_path() {
    const char* forced = std::getenv("SWEEPTRACE_SIMD");
    if (forced && std::strcmp(forced, "scalar") == 0) return SimdPath::Scalar;
    return cpu_has_avx2() ? SimdPath::Avx2 : SimdPath::Scalar;
}

std::string simd_path_name(SimdPath path) { return path == SimdPath::Avx2 ? "avx2" : "scalar"; }

}  // namespace sweeptrace
