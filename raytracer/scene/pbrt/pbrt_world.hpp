#pragma once
// PbrtScene -> our scene JSON document.
//
// Handedness. pbrt's camera space is left-handed (x to the image's right, y up, z forward: a
// plain `LookAt` puts world +x on the right when looking down +z with +y up); ours is
// right-handed (right = forward x up), which would draw the mirror image. The world is never
// changed for this: the camera is. When pbrt's world-from-camera matrix keeps orientation (det > 0,
// a plain LookAt, pbrt-v4's own test scenes) our camera is written left-handed
// (camera.handedness "left": right = up x forward), which is pbrt's camera exactly; exporters that
// start with `Scale -1 1 1` (det < 0; Bitterli's scenes, Blender's exporter) get our right-handed
// camera. Shapes, lights and mesh files therefore stay where pbrt puts them.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raytracer/scene/pbrt/pbrt_diagnostics.hpp"
#include "raytracer/scene/pbrt/pbrt_materials.hpp"
#include "raytracer/scene/pbrt/pbrt_scene.hpp"

namespace sweeptrace::pbrt {

// At most this many triangles given inline in all (trianglemesh, bilinearmesh), written as our
// inline meshes: about 200 bytes each while the JSON document is built and read. The text limits
// (pbrt_parser.hpp: 64 MiB) allow about as many; larger meshes belong in PLY files.
inline constexpr std::size_t kMaxInlineTriangles = 4000000;

// The pbrt statement a part of the JSON was written for, so that the JSON loader's complaint
// about it (a corrupt PLY file, a light's intensity that overflowed once scaled, a texture's bad
// image) can be said at the pbrt file and line (pbrt_import.cpp): the user never saw the JSON.
struct ObjectOrigin {
    Where where;
    std::string what;  // `Shape "plymesh"`
};

struct DocumentOrigins {
    std::vector<ObjectOrigin> objects, lights;  // objects[i], lights[i]
    std::map<std::string, ObjectOrigin> materials;  // by the material's name in the JSON
    std::map<std::string, ObjectOrigin> media;      // by the medium's name
    std::optional<ObjectOrigin> background, camera, film;
};

struct WorldContext {
    const PbrtScene& scene;
    MaterialTranslator& materials;
    const FileNames& files;
    Diagnostics& diag;
    nlohmann::json doc;
    std::size_t triangles = 0;
    // pbrt-v4's sensor response: the film records radiance x exposure time (shutterclose -
    // shutteropen) x ISO / 100 (its PixelSensor's imaging ratio). Light transport is linear in the
    // emitted radiance, so the writer multiplies every emitter by it: the same pixels, in every
    // output format, as pbrt's film.
    double imaging_ratio = 1.0;

    // The output name of the material a shape uses, with its area light's emission added (a new
    // material per material and light); nullopt when the shape is invisible (pbrt's "interface").
    // `area` is the shape's world area, for "power".
    std::optional<std::string> material_for(const ShapeRecord& s, double area);
    DocumentOrigins* origins = nullptr;  // where material_for's emitting materials came from
};

// Our JSON for the scene; `film_filename` gets the Film's "filename" (pbrt's default "pbrt.exr"),
// `origins` where each part came from.
nlohmann::json write_world(const PbrtScene& scene, MaterialTranslator& materials, const FileNames& files, Diagnostics& diag,
                           std::string& film_filename, DocumentOrigins& origins);

// Parts, each in its own file: camera, film, sampler, filter, integrator (pbrt_camera.cpp);
// one shape (pbrt_shapes.cpp); one light (pbrt_lights.cpp).
void write_camera_and_film(WorldContext& w, std::string& film_filename);
void write_shape(WorldContext& w, const ShapeRecord& shape);
void write_light(WorldContext& w, const LightRecord& light);

// Every emitter of a written document (materials' emission, lights' intensity and irradiance,
// the background) multiplied by k.
void scale_emitters(nlohmann::json& doc, double k);

// A transform's JSON steps (rotate, scale, rotate, translate; identities left out), nullopt
// when it mirrors or is singular.
std::optional<nlohmann::json> transform_json(const glm::dmat4& m);

}  // namespace sweeptrace::pbrt
