#include "raytracer/render/guiding/guiding_sampler.hpp"

namespace sweeptrace {

bool sample_guided(const MaterialParameters& m, const ShadingContext& ctx, const DirectionalQuadtree& guide, float u_select,
                   float u0, float u1, float u2, BsdfSample& out, float& bsdf_pdf) {
    glm::vec3 wi;
    float guide_pdf = -1.0f;  // the guide's density of wi, when its descent gave it
    if (u_select < kBsdfFraction) {
        if (!sample_bsdf(m, ctx, u0, u1, u2, out)) return false;
        if (out.delta) {  // not a guided lobe: the BSDF alone
            bsdf_pdf = out.pdf;
            return true;
        }
        wi = out.wi;
    } else {
        wi = guide.sample(u1, u2, &guide_pdf);
    }
    // One evaluation for both branches, so f and the BSDF density are the same expressions
    // whichever strategy drew wi.
    const BsdfEval e = eval_bsdf(m, ctx, wi);
    if (!(e.pdf > 0.0f)) return false;
    const float pdf = guide_pdf >= 0.0f ? kBsdfFraction * e.pdf + (1.0f - kBsdfFraction) * guide_pdf
                                        : guided_pdf(guide, e.pdf, wi);
    bsdf_pdf = e.pdf;
    out = BsdfSample{wi, e.f_cos / pdf, pdf, false};
    return true;
}

}  // namespace sweeptrace
