#pragma once
// The one file that includes Embree (embree3/), and collision::Ray -> Embree's ray; the other
// Embree files include this header, so the API has a single entry point to check.
#include <limits>

#include <embree3/rtcore.h>

#include "collision/ray.hpp"

namespace sweeptrace {

inline RTCRay to_embree_ray(const collision::Ray& ray) {
    RTCRay r{};
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.dir.x;
    r.dir_y = ray.dir.y;
    r.dir_z = ray.dir.z;
    r.tnear = ray.tmin;
    r.tfar = ray.tmax;
    r.mask = std::numeric_limits<unsigned>::max();
    return r;
}

// A ray-hit record ready for rtcIntersect1: no hit yet.
inline RTCRayHit to_embree_ray_hit(const collision::Ray& ray) {
    RTCRayHit rh{};
    rh.ray = to_embree_ray(ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

}  // namespace sweeptrace
