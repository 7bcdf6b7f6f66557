#pragma once
// Embree's build quality, for the bench: Embree 3 does not expose the BVH that rtcCommitScene
// builds, but its BVH builder (rtcBuildBVH, user callbacks) runs the same binned-SAH build on
// the triangles' boxes. We let it build an 8-wide tree with leaves of up to 4 (its BVH8 /
// Triangle4 shape) and score it with the cost in sah_cost.hpp, so the two figures compare.
// This header does not include Embree; only embree_sah.cpp does.
#include "collision/mesh.hpp"

namespace sweeptrace {

struct EmbreeSah {
    double cost = 0.0;
    std::size_t inner_nodes = 0, leaves = 0;
};

// Throws std::runtime_error when Embree reports an error.
EmbreeSah embree_builder_sah(const collision::TriangleMesh& mesh);

}  // namespace sweeptrace
