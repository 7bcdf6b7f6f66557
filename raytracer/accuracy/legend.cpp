#include "raytracer/accuracy/legend.hpp"

namespace sweeptrace::accuracy {

void write_legend(std::ostream& out) {
    out << "\nColumns:\n"
           "- rays: rays scored (surface families: secondary rays spawned from the routine's own hits).\n"
           "- exact touch: the long double reference cannot decide (the exact ray touches an edge, a silhouette\n"
           "  or its start, within 2^-46 of the magnitudes): either answer is right, left out of the counts.\n"
           "- within rounding: decided, but within 2^-16 (256 float ulps): any answer is defensible.\n"
           "- wrong hit/miss: hit where the reference misses or the reverse, of the decided rays (and its share).\n"
           "- wrong beyond rounding: of those, the ones outside the rounding band: defects, not rounding.\n"
           "- t rel. err.: |t - t_ref| / t_ref where both hit: median, 99th percentile, max.\n"
           "- self-hits: surface families: the secondary ray hit the surface it left.\n"
           "- leaks: edges family: a ray from inside a closed shape or mesh got out.\n"
           "- Mrays/s: millions of rays per second of one thread's CPU time (timing, not accuracy; '-' when scored\n"
           "  from a results file).\n";
}

}  // namespace sweeptrace::accuracy
