// The denoiser's tasks run with subnormals flushed (denoise/subnormals.hpp), and only they: the
// thread that calls it, and so the renderer, keeps IEEE subnormals.
#include <catch2/catch.hpp>

#include <atomic>
#include <cfloat>
#include <vector>

#include <tbb/global_control.h>

#include "raytracer/denoise/tiles.hpp"

using namespace sweeptrace::denoise;

namespace {

// A product below the smallest normal float: 2^-130 with IEEE subnormals, 0 flushed. volatile, so
// the compiler computes it at run time, in the thread's mode.
float subnormal_product() {
    volatile float a = 0x1p-100f, b = 0x1p-30f;
    return a * b;
}

}  // namespace

TEST_CASE("denoise tasks flush subnormals, the calling thread keeps them", "[denoise]") {
    REQUIRE(subnormal_product() > 0.0f);  // IEEE before
    const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
    std::atomic<int> kept{0};
    std::vector<float> products(64, -1.0f);
    for_each_chunk(products.size(), 1, [&](std::size_t i0, std::size_t i1) {
        for (std::size_t i = i0; i < i1; ++i) products[i] = subnormal_product();
    });
    for_each_tile(image_tiles(256, 256), [&](std::size_t, const Rect&) {
        if (subnormal_product() != 0.0f) ++kept;
    });
    for (float p : products) CHECK(p == 0.0f);
    CHECK(kept == 0);
    CHECK(subnormal_product() == 0x1p-130f);  // and after
}
