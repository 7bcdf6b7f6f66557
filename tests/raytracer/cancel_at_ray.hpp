#pragma once
// An Accel that counts the rays traced through it and sets a cancel flag at the `after`-th: a
// cancel at a known point of a render (with one thread, a known point of a known sample), for
// the tests of what a cancel keeps and how soon it stops.
#include <atomic>
#include <cstdint>
#include <string>

#include "raytracer/accel/accel.hpp"

namespace sweeptrace::test {

class CancelAtRay final : public Accel {
public:
    // `after` 0: never sets the flag, only counts.
    CancelAtRay(const Accel& inner, std::atomic<bool>& flag, std::uint64_t after) : inner_(inner), flag_(flag), after_(after) {}
    bool intersect(const collision::Ray& r, SurfaceHit& h) const override {
        tick();
        return inner_.intersect(r, h);
    }
    bool occluded(const collision::Ray& r) const override {
        tick();
        return inner_.occluded(r);
    }
    std::size_t memory_bytes() const override { return 0; }
    std::string name() const override { return "cancel-at-ray"; }
    std::uint64_t rays() const { return count_.load(); }

private:
    void tick() const {
        if (count_.fetch_add(1) + 1 == after_) flag_.store(true);
    }
    const Accel& inner_;
    std::atomic<bool>& flag_;
    std::uint64_t after_;
    mutable std::atomic<std::uint64_t> count_{0};
};

}  // namespace sweeptrace::test
