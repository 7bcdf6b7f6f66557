#pragma once
// What one camera path teaches the guide (Müller, Gross, Novák 2017, §3.4): at each guided
// vertex, the radiance that arrived along the direction the path continued in, divided by the
// density it was drawn with; and each next-event sample's light, weighted by its MIS weight and
// divided by its density. The two are the two halves of the MIS estimate of incident radiance
// (the BSDF-side half of direct light already carries its MIS weight in the path's radiance), so
// summed over a cell they estimate the radiance integrated over it. Each is weighted by the
// cosine to the shading normal: the guide then learns L_i cos, the part of the integrand a
// diffuse vertex does not sample well by itself (a light near the horizon matters less than
// one overhead), and which also keeps the guide from spending samples below the surface.
//
// The radiance along a vertex's continuation is read off the path's total at the end: what was
// added after the vertex's BSDF sample, divided (per channel) by the throughput just after that
// sample (before Russian roulette, whose 1/q keeps the continuation's estimate unbiased).
// Vertices past kMaxVertices are not recorded (paths that long carry little light).
//
// The sky guide (sky_guide.hpp) learns the sky's share of the same records: a next-event sample
// of the guided sky, and a vertex whose continuation escaped to a sky without a portal (its MIS
// weighted radiance, cos / density as the vertex's own record).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "raytracer/render/guiding/guiding_sd_tree.hpp"

namespace sweeptrace {

class GuidePathRecorder {
public:
    static constexpr int kMaxVertices = 16;

    explicit GuidePathRecorder(std::vector<GuideRecord>* out) : out_(out) {}
    bool on() const { return out_ != nullptr; }
    // The spatial leaf of the vertex the next add_* calls are about.
    void at_leaf(std::uint32_t leaf) { leaf_ = leaf; }

    // A next-event sample from `point`: `contribution` = MIS weight x radiance / density, zero when
    // the shadow ray was blocked; `square` the sample's point on the light's sample square and
    // `unweighted` = radiance / density, zero when blocked or not drawn on a square (light_guide.hpp).
    // `sky`: the sample was the guided sky's (LightSample::guided_sky).
    void add_light_sample(const glm::vec3& point, const glm::vec3& normal, const glm::vec3& wi,
                          const glm::vec3& contribution, const glm::vec2& square, const glm::vec3& unweighted,
                          bool sky = false) {
        push(point, wi, mean(contribution) * cosine(normal, wi), true);
        GuideRecord& r = out_->back();
        r.light_uv = square;
        r.light_value = learnable(mean(unweighted) * cosine(normal, wi));
        if (sky) r.sky_value = r.value;
    }
    // The path continued from `point` along wi drawn with density `pdf`; `throughput` is the
    // path's throughput after the sample's weight, `total` the path's radiance so far.
    void add_vertex(const glm::vec3& point, const glm::vec3& normal, const glm::vec3& wi, float pdf,
                    const glm::vec3& throughput, const glm::vec3& total) {
        last_stored_ = count_ < kMaxVertices;
        if (last_stored_) vertices_[count_++] = Vertex{point, wi, cosine(normal, wi) / pdf, throughput, total, leaf_, 0.0f};
    }
    // The continuation of the last add_vertex escaped to a sky without a portal, which gave it
    // `radiance` (its MIS weight applied, before the path's throughput).
    void add_sky_found(const glm::vec3& radiance) {
        if (last_stored_) vertices_[count_ - 1].sky = mean(radiance) * vertices_[count_ - 1].weight;
        last_stored_ = false;
    }
    // The path's final radiance: turns the vertices into records.
    void finish(const glm::vec3& total) {
        for (int i = 0; i < count_; ++i) {
            const Vertex& v = vertices_[i];
            const glm::vec3 after = total - v.total_before;
            glm::vec3 li(0.0f);
            for (int c = 0; c < 3; ++c)
                if (v.throughput[c] > 0.0f) li[c] = after[c] / v.throughput[c];
            leaf_ = v.leaf;
            push(v.point, v.wi, mean(li) * v.weight);
            out_->back().sky_value = learnable(v.sky);
        }
        count_ = 0;
        last_stored_ = false;
    }

private:
    struct Vertex {
        glm::vec3 point, wi;
        float weight;  // cos / density
        glm::vec3 throughput, total_before;
        std::uint32_t leaf;
        float sky;  // the sky's estimate along wi (add_sky_found), cos / density included
    };
    static float mean(const glm::vec3& c) { return (c.r + c.g + c.b) * (1.0f / 3.0f); }
    static float cosine(const glm::vec3& n, const glm::vec3& w) { return std::max(0.0f, glm::dot(n, w)); }
    // A non-finite or negative estimate (a degenerate path) teaches nothing.
    static float learnable(float v) { return std::isfinite(v) && v > 0.0f ? v : 0.0f; }
    void push(const glm::vec3& point, const glm::vec3& wi, float value, bool light_sample = false) {
        // One that teaches nothing still counts as a record.
        out_->push_back(GuideRecord{point, wi, learnable(value), leaf_, light_sample});
    }

    std::vector<GuideRecord>* out_;
    std::uint32_t leaf_ = 0;
    Vertex vertices_[kMaxVertices];
    int count_ = 0;
    bool last_stored_ = false;  // the last add_vertex was stored (and nothing came after it)
};

}  // namespace sweeptrace
