#include "raytracer/accuracy/render_studies.hpp"

#include <cmath>
#include <cstdio>
#include <variant>

#include "raytracer/accel/accel.hpp"
#include "raytracer/accuracy/tessellate.hpp"
#include "raytracer/accuracy/thread_timer.hpp"
#include "raytracer/image/diff.hpp"
#include "raytracer/render/renderer.hpp"
#include "raytracer/scene/load_scene.hpp"

namespace sweeptrace::accuracy {

namespace {

double linear_rmse(const Image& a, const Image& b) {
    DiffOptions o;
    o.space = DiffSpace::Linear;
    return compare_images(a, b, o).rmse;
}

struct Timed {
    RenderResult result;
    double seconds = 0.0;
    std::size_t accel_bytes = 0;
};

Timed render_timed(const Scene& scene, AccelKind kind, int spp, Sampling sampling, unsigned seed) {
    Timed t;
    const double start = process_seconds();
    const auto accel = make_accel(kind, scene);
    RenderOptions o;
    o.spp = spp;
    o.max_depth = scene.film.max_depth;
    o.seed = seed;
    o.sampling = sampling;
    t.result = render(scene, *accel, o);
    t.seconds = process_seconds() - start;
    t.accel_bytes = accel->memory_bytes();
    return t;
}

// One object at the origin under a sky, on a grey ground plane quad for contact shading.
Scene study_scene(const Shape& shape, int width) {
    Scene s;
    s.camera.position = {0.0f, 1.2f, 4.5f};
    s.camera.look_at = {0.0f, 0.0f, 0.0f};
    s.camera.vfov_degrees = 35.0f;
    s.film.width = width;
    s.film.height = width * 3 / 4;
    s.film.max_depth = 4;
    s.background.kind = Background::Kind::Sky;
    Material object;
    object.albedo = {0.75f, 0.45f, 0.3f};
    object.name = "object";
    Material ground;
    ground.albedo = glm::vec3(0.5f);
    ground.name = "ground";
    s.materials = {object, ground};
    s.objects.push_back(Object{shape, Transform{}, 0, "object", {}, {}});
    s.objects.push_back(
        Object{collision::Quad{{-4.0f, -1.0f, 4.0f}, {8.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -8.0f}}, Transform{}, 1, "ground", {}, {}});
    return s;
}

template <class S>
void study_shape(const S& shape, int size, int spp, int reference_spp, int max_exponent,
                 unsigned seed, std::vector<TessellationRow>& rows) {
    const Scene analytic = study_scene(shape, size);
    const Timed reference = render_timed(analytic, AccelKind::Bvh, reference_spp, Sampling::NeeMis, seed + 1);
    Image analytic_image;
    for (AccelKind kind : {AccelKind::Bvh, AccelKind::Embree}) {
        const Timed t = render_timed(analytic, kind, spp, Sampling::NeeMis, seed);
        if (kind == AccelKind::Bvh) analytic_image = t.result.image;
        TessellationRow row;
        row.shape = std::string(Shapes::HomeOf<S>::kType);
        row.representation = "analytic";
        row.accel = kind == AccelKind::Bvh ? "bvh" : "embree";
        row.seconds = t.seconds;
        row.rmse = linear_rmse(t.result.image, analytic_image);
        row.noise_rmse = linear_rmse(t.result.image, reference.result.image);
        row.accel_bytes = t.accel_bytes;
        rows.push_back(row);
    }
    for (int e = 2; e <= max_exponent; ++e) {
        const auto wanted = static_cast<std::size_t>(std::pow(10.0, e));
        Scene meshed = study_scene(MeshInstance{0}, size);
        meshed.meshes.push_back(tessellate(shape, wanted));
        const Mesh& m = meshed.meshes.back();
        for (AccelKind kind : {AccelKind::Bvh, AccelKind::Embree}) {
            const Timed t = render_timed(meshed, kind, spp, Sampling::NeeMis, seed);
            TessellationRow row;
            row.shape = std::string(Shapes::HomeOf<S>::kType);
            row.representation = "mesh";
            row.accel = kind == AccelKind::Bvh ? "bvh" : "embree";
            row.triangles = m.triangles.triangle_count();
            row.seconds = t.seconds;
            row.rmse = linear_rmse(t.result.image, analytic_image);
            row.noise_rmse = linear_rmse(t.result.image, reference.result.image);
            row.accel_bytes = t.accel_bytes;
            row.mesh_bytes = m.triangles.vertices.size() * sizeof(glm::vec3) +
                             m.vertex_normals.size() * sizeof(glm::vec3) +
                             m.triangles.indices.size() * sizeof(glm::uvec3);
            rows.push_back(row);
        }
    }
}

}  // namespace

std::vector<TessellationRow> tessellation_study(int size, int spp, int reference_spp, int max_exponent, unsigned seed) {
    std::vector<TessellationRow> rows;
    study_shape(collision::Sphere{{0.0f, 0.0f, 0.0f}, 1.0f}, size, spp, reference_spp, max_exponent, seed, rows);
    study_shape(collision::Cylinder{{0.0f, 0.0f, 0.0f}, 0.8f, 1.8f}, size, spp, reference_spp, max_exponent,
                seed, rows);
    study_shape(collision::Capsule{{0.0f, 0.0f, 0.0f}, 0.6f, 0.8f}, size, spp, reference_spp, max_exponent,
                seed, rows);
    study_shape(collision::Ellipsoid{{0.0f, 0.0f, 0.0f}, {1.3f, 0.7f, 0.9f}}, size, spp, reference_spp,
                max_exponent, seed, rows);
    return rows;
}

std::vector<ConvergenceRow> convergence_study(const std::vector<std::filesystem::path>& scenes, int size, int max_spp,
                                              int reference_spp) {
    std::vector<ConvergenceRow> rows;
    for (const auto& path : scenes) {
        Scene scene = load_scene(path);
        const int w = scene.film.width, h = scene.film.height;
        scene.film.width = size;
        scene.film.height = std::max(1, size * h / std::max(1, w));
        const Timed reference = render_timed(scene, AccelKind::Embree, reference_spp, Sampling::NeeMis, 12345);
        for (Sampling sampling : {Sampling::NeeMis, Sampling::BsdfOnly}) {
            for (AccelKind kind : {AccelKind::Bvh, AccelKind::Embree}) {
                for (int spp = 1; spp <= max_spp; spp *= 2) {
                    const Timed t = render_timed(scene, kind, spp, sampling, 1);
                    ConvergenceRow row;
                    row.scene = path.stem().string();
                    row.sampling = sampling == Sampling::NeeMis ? "nee-mis" : "bsdf-only";
                    row.accel = kind == AccelKind::Bvh ? "bvh" : "embree";
                    row.spp = spp;
                    row.seconds = t.seconds;
                    row.rmse = linear_rmse(t.result.image, reference.result.image);
                    rows.push_back(row);
                }
            }
        }
    }
    return rows;
}

void write_tessellation_csv(std::ostream& out, const std::vector<TessellationRow>& rows) {
    out << "shape,representation,accel,triangles,seconds,rmse_vs_analytic,rmse_vs_converged,accel_bytes,mesh_bytes\n";
    char buf[256];
    for (const auto& r : rows) {
        std::snprintf(buf, sizeof buf, "%s,%s,%s,%zu,%.6g,%.6g,%.6g,%zu,%zu\n", r.shape.c_str(), r.representation.c_str(),
                      r.accel.c_str(), r.triangles, r.seconds, r.rmse, r.noise_rmse, r.accel_bytes, r.mesh_bytes);
        out << buf;
    }
}

void write_tessellation_markdown(std::ostream& out, const std::vector<TessellationRow>& rows) {
    out << "| shape | representation | accel | triangles | CPU s | RMSE vs analytic (same seed) "
           "| RMSE vs converged | accel MB | mesh MB |\n|---|---|---|---:|---:|---:|---:|---:|---:|\n";
    char buf[256];
    for (const auto& r : rows) {
        std::snprintf(buf, sizeof buf, "| %s | %s | %s | %zu | %.3g | %.3g | %.3g | %.3g | %.3g |\n", r.shape.c_str(),
                      r.representation.c_str(), r.accel.c_str(), r.triangles, r.seconds, r.rmse, r.noise_rmse,
                      double(r.accel_bytes) / 1e6, double(r.mesh_bytes) / 1e6);
        out << buf;
    }
}

void write_convergence_csv(std::ostream& out, const std::vector<ConvergenceRow>& rows) {
    out << "scene,sampling,accel,spp,seconds,rmse\n";
    char buf[256];
    for (const auto& r : rows) {
        std::snprintf(buf, sizeof buf, "%s,%s,%s,%d,%.6g,%.6g\n", r.scene.c_str(), r.sampling.c_str(), r.accel.c_str(),
                      r.spp, r.seconds, r.rmse);
        out << buf;
    }
}

void write_convergence_markdown(std::ostream& out, const std::vector<ConvergenceRow>& rows) {
    out << "| scene | sampling | accel | spp | CPU s | RMSE vs reference |\n|---|---|---|---:|---:|---:|\n";
    char buf[256];
    for (const auto& r : rows) {
        std::snprintf(buf, sizeof buf, "| %s | %s | %s | %d | %.3g | %.3g |\n", r.scene.c_str(), r.sampling.c_str(),
                      r.accel.c_str(), r.spp, r.seconds, r.rmse);
        out << buf;
    }
}

}  // namespace sweeptrace::accuracy
