#include "raytracer/accel/time_slices.hpp"

namespace sweeptrace {

int choose_time_slices(const std::vector<std::vector<collision::Bounds3>>& fine_boxes) {
    // The mean over primitives of the area of its box over each of `slices` slices (the union of
    // its fine boxes there), averaged over the slices, relative to the fine boxes' average.
    auto ratio = [&](int slices) {
        const int per = kMaxTimeSlices / slices;
        double sum = 0.0;
        std::size_t counted = 0;
        for (const auto& boxes : fine_boxes) {
            double coarse = 0.0, fine = 0.0;
            for (int k = 0; k < slices; ++k) {
                collision::Bounds3 b;
                for (int j = 0; j < per; ++j) {
                    const collision::Bounds3& f = boxes[static_cast<std::size_t>(k * per + j)];
                    b.extend(f);
                    fine += f.half_area();
                }
                coarse += b.half_area();
            }
            if (!(fine > 0.0)) continue;  // flat or empty: no area to shrink
            sum += (coarse / slices) / (fine / kMaxTimeSlices);
            ++counted;
        }
        return counted ? sum / static_cast<double>(counted) : 1.0;
    };
    for (int slices = 1; slices < kMaxTimeSlices; slices *= 2)
        if (ratio(slices) <= kSliceSlack) return slices;
    return kMaxTimeSlices;
}

}  // namespace sweeptrace
