#pragma once
// The grid that finds vcm's photons (light_vertices.hpp) near a camera vertex (SmallVCM's hash
// grid): one flat array of pointers to the photons, sorted by cell with a counting sort, and a
// table of where each cell's run starts. Cells are cubes of side 2 r, hashed into as many slots as there are photons, so a ball
// of radius r touches 8 cells (27 when it ends on a cell's face); cells that share a slot share its run (the distance test
// drops the strangers) and a slot is visited once per query however many of its cells the ball
// touches. Building allocates nothing once the arrays have grown to an iteration's photon count
// (they keep their capacity), computes the slots, counts and scatters in parallel, and is stable:
// a cell's photons stay in the order given, so the merges add them in the same order at any
// thread count.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "raytracer/render/integrators/light_vertices.hpp"

namespace sweeptrace {

class PhotonGrid {
public:
    // Sorts the photons of `runs`, in their order, into cells of side cell_size (finite, > 0).
    // They must stay where they are until the next build.
    void build(const std::vector<std::span<const Photon>>& runs, float cell_size);

    // f(photon) for every photon in a slot of a cell that the box [p - r, p + r] touches: every
    // photon within r of p, and others (the caller tests the distance).
    template <class F>
    void for_each_near(const glm::vec3& p, float r, F&& f) const {
        if (photons_.empty()) return;
        std::uint32_t slots[27];
        const int n = near_slots(p, r, slots);
        for (int i = 0; i < n; ++i)
            for (std::uint32_t k = start_[slots[i]]; k < start_[slots[i] + 1]; ++k) f(*photons_[k]);
    }

    std::size_t size() const { return photons_.size(); }

private:
    std::uint32_t slot_of(const glm::vec3& p) const;
    // The distinct slots of the cells [p - r, p + r] touches (cell side >= 2 r: at most 27).
    int near_slots(const glm::vec3& p, float r, std::uint32_t* slots) const;

    double cell_size_ = 1.0;
    std::vector<const Photon*> photons_;  // by slot
    std::vector<std::uint32_t> start_;  // slot s holds photons_[start_[s] .. start_[s + 1])
    std::vector<std::uint32_t> slot_;   // scratch: each given photon's slot
};

}  // namespace sweeptrace
