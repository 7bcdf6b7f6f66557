#include "raytracer/render/media/medium_model.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace sweeptrace {

MediumModel::MediumModel(const Medium& m, int majorant_res) : m_(&m) {
    const glm::vec3 st = m.sigma_a + m.sigma_s;
    max_sigma_t_ = std::max(st.x, std::max(st.y, st.z));
    emits_ = medium_emits(m);
    if (m.kind == Medium::Kind::Grid) {
        const glm::vec3 extent = m.p1 - m.p0;
        to_grid_ = glm::scale(glm::mat4(1.0f), 1.0f / extent) * glm::translate(glm::mat4(1.0f), -m.p0) * m.to_medium;
        majorant_ = MajorantGrid(m.density, m.nx, m.ny, m.nz, majorant_res);
    }
}

glm::vec3 MediumModel::to_grid(const glm::vec3& world) const { return glm::vec3(to_grid_ * glm::vec4(world, 1.0f)); }

float MediumModel::sample(int x, int y, int z, const std::vector<float>& v) const {
    if (x < 0 || y < 0 || z < 0 || x >= m_->nx || y >= m_->ny || z >= m_->nz) return 0.0f;
    return v[(static_cast<std::size_t>(z) * m_->ny + y) * m_->nx + x];
}

float MediumModel::lookup(const glm::vec3& grid, const std::vector<float>& v) const {
    const glm::vec3 s(grid.x * static_cast<float>(m_->nx) - 0.5f, grid.y * static_cast<float>(m_->ny) - 0.5f,
                      grid.z * static_cast<float>(m_->nz) - 0.5f);
    const glm::vec3 f = glm::floor(s);
    const int x = static_cast<int>(f.x), y = static_cast<int>(f.y), z = static_cast<int>(f.z);
    const glm::vec3 w = s - f;
    auto lerp = [](float a, float b, float t) { return (1.0f - t) * a + t * b; };
    const float c00 = lerp(sample(x, y, z, v), sample(x + 1, y, z, v), w.x);
    const float c10 = lerp(sample(x, y + 1, z, v), sample(x + 1, y + 1, z, v), w.x);
    const float c01 = lerp(sample(x, y, z + 1, v), sample(x + 1, y, z + 1, v), w.x);
    const float c11 = lerp(sample(x, y + 1, z + 1, v), sample(x + 1, y + 1, z + 1, v), w.x);
    return lerp(lerp(c00, c10, w.y), lerp(c01, c11, w.y), w.z);
}

float MediumModel::density(const glm::vec3& grid) const {
    // Outside the unit cube every sample the lookup would blend is outside the grid too, but for
    // the outer half voxel; test the cube itself so a far point costs nothing.
    if (!(grid.x >= 0.0f && grid.x <= 1.0f && grid.y >= 0.0f && grid.y <= 1.0f && grid.z >= 0.0f && grid.z <= 1.0f))
        return 0.0f;
    return lookup(grid, m_->density);
}

MediumPoint MediumModel::at(const glm::vec3& world) const {
    if (homogeneous()) return {m_->sigma_a, m_->sigma_s, m_->emission};
    const glm::vec3 g = to_grid(world);
    const float d = density(g);
    MediumPoint p{m_->sigma_a * d, m_->sigma_s * d, m_->emission};
    if (emits_ && !m_->emission_scale.empty()) p.emission *= lookup(g, m_->emission_scale);
    return p;
}

}  // namespace sweeptrace
