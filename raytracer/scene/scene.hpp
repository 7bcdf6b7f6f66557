#pragma once
// A validated scene, as the JSON loader produces it. Everything here has passed the loader's
// checks: finite numbers, positive sizes, valid indices.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raytracer/geometry/object.hpp"
#include "raytracer/image/image.hpp"
#include "raytracer/scene/medium.hpp"
#include "raytracer/scene/scene_light.hpp"

namespace sweeptrace {

struct Camera {
    glm::vec3 position{0.0f, 0.0f, 5.0f};
    glm::vec3 look_at{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float vfov_degrees = 40.0f;
    float aperture = 0.0f;        // lens diameter; 0 = pinhole
    float focus_distance = 0.0f;  // 0 = distance from position to look_at
    // Primary rays start on the plane this far ahead along the view axis (smallpt's camera sits
    // outside the room and starts its rays 140 units ahead); 0 = at the eye.
    float near_clip = 0.0f;
    // Which way the image's x runs (scene key "handedness"). Right-handed, ours: the image's right
    // is forward x up. Left-handed: up x forward, the mirror image, as pbrt's camera space (x right,
    // y up, z forward) sees the world through a plain LookAt; the pbrt importer sets it so that a
    // scene keeps its own world and still renders as pbrt draws it (docs/pbrt-import.md).
    bool left_handed = false;
    // The shutter (scene key "shutter", scene/load_motion.hpp): when set, each camera ray is traced
    // at a time drawn in [shutter_open, shutter_close] and moving objects are seen in their pose
    // then; unset, nothing moves and no time is drawn.
    bool shutter = false;
    float shutter_open = 0.0f, shutter_close = 0.0f;
    // The medium the camera sits in (scene key "medium"; index into Scene::media, -1 vacuum).
    std::int32_t medium = -1;
};

// Where a camera sample's numbers come from (render/sampling/sampler.hpp). SobolHalves: the Sobol
// construction run as two independently scrambled sequences, one for the even and one for the
// odd sample indices, so that the two half buffers of render --aovs are independent estimates
// (docs/aovs.md, "Independent halves").
enum class SamplerKind { Independent, Sobol, SobolHalves };
// Its name in the scene file and on the command line.
inline const char* sampler_name(SamplerKind k) {
    return k == SamplerKind::Independent ? "independent" : k == SamplerKind::SobolHalves ? "sobol-halves" : "sobol";
}

// Which light transport method renders the film (render/integrators/): the unidirectional path
// tracer (the default), bidirectional path tracing (Veach 1997, ch. 10), or vertex connection and
// merging (Georgiev et al. 2012: bdpt plus photon merging at camera vertices).
enum class IntegratorKind { Path, Bdpt, Vcm };
// Its name in the scene file and on the command line.
inline const char* integrator_name(IntegratorKind k) {
    return k == IntegratorKind::Vcm ? "vcm" : k == IntegratorKind::Bdpt ? "bdpt" : "path";
}

// The curve that takes exposed linear radiance to [0, 1] for 8-bit output (render/film/tone_map.hpp).
enum class ToneCurve { Clamp, Aces };

// The pixel reconstruction filter, as the scene gives it (render/film/pixel_filter.hpp samples it).
// Separable: the 2D filter is f(x) f(y) for offsets (x, y) in pixels from the pixel's centre.
struct FilterSpec {
    enum class Type { Box, Tent, Gaussian, Mitchell };
    Type type = Type::Box;
    float radius = 0.5f;              // support [-radius, radius] per axis, in pixels
    float sigma = 0.5f;               // Gaussian: standard deviation in pixels
    float b = 1.0f / 3.0f, c = 1.0f / 3.0f;  // Mitchell-Netravali's B and C
};

struct Film {
    int width = 320;
    int height = 240;
    int spp = 16;
    int max_depth = 8;  // path vertices after the camera; Russian roulette may stop earlier
    SamplerKind sampler = SamplerKind::Sobol;
    bool guiding = false;  // path guiding by default (render --guiding overrides)
    IntegratorKind integrator = IntegratorKind::Path;  // scene key "integrator" (render --integrator overrides)
    // Feature outputs beside the image (scene key "aovs", as render --aovs): albedo, normal, depth
    // and the half buffers a denoiser reads (image/feature_exr.hpp).
    bool aovs = false;
    // vcm's merging radius of the first iteration, world units (scene key "vcm_radius"); 0 = the
    // default, a fraction of the scene's extent (render/integrators/vcm.hpp says which and why).
    float vcm_radius = 0.0f;
    float exposure = 0.0f;  // stops: 8-bit output shows radiance x 2^exposure (linear outputs untouched)
    ToneCurve tone_curve = ToneCurve::Clamp;
    FilterSpec filter;  // box of radius 0.5: each sample uniform in its pixel
    // A biased, opt-in firefly guard (render/film/radiance_clamp.hpp): each contribution of a path of
    // three or more segments (light reaching the camera after two or more bounces) has its largest
    // component limited to this. 0 = off, the unbiased estimator.
    float clamp_indirect = 0.0f;
    // pbrt-v4's Film "maxcomponentvalue": each camera sample's whole radiance (direct light too)
    // scaled down so its largest component is at most this. Biased, opt-in; 0 = off.
    float clamp_sample = 0.0f;
};

struct Background {
    enum class Kind { Constant, Sky, Environment };
    Kind kind = Kind::Constant;
    glm::vec3 color{0.0f};               // Constant
    glm::vec3 horizon{1.0f};             // Sky: radiance toward the horizon and below
    glm::vec3 zenith{0.5f, 0.7f, 1.0f};  // Sky: radiance straight up (+Y), blended by dir.y
    // Environment: a radiance map (render/lights/environment_light.hpp states both layouts), shared,
    // not copied, by copies of the scene; turned about +Y by rotate_degrees (or, with `turned`, by
    // the rotation `turn`: a "rotate" given as an axis and degrees), its frame's x negated after
    // the turn when mirrored, and multiplied by scale.
    enum class EnvironmentMapping { Equirect, EqualArea };
    std::shared_ptr<const Image> environment;
    EnvironmentMapping mapping = EnvironmentMapping::Equirect;
    float rotate_degrees = 0.0f;
    bool turned = false;
    glm::mat3 turn{1.0f};  // map frame -> world, a rotation
    bool mirror = false;
    float scale = 1.0f;
    // Any kind: a window rectangle (corners in order round its edge) through which the
    // background lights the scene; it guides next event estimation only, the radiance is the
    // same without it (render/lights/portal.hpp).
    bool has_portal = false;
    std::array<glm::vec3, 4> portal{};
};

// A colour that varies over a surface with its uv coordinates (render/materials/texture.hpp evaluates it;
// each shape's home states its uv parameterisation). A constant colour is not a Texture: it is
// the material's plain value.
struct Texture {
    enum class Kind { Checker, Image };
    enum class Wrap { Repeat, Clamp, Mirror };
    Kind kind = Kind::Checker;
    glm::vec3 a{0.2f}, b{0.8f};  // Checker: the two colours; a at uv = (0, 0)
    float scale = 8.0f;          // Checker: squares per unit of u and of v
    std::shared_ptr<const Image> image;  // Image: linear RGB (an sRGB .png is decoded on load)
    std::filesystem::path image_file;    // Image: the file, canonical: one load however many textures use it
    Wrap wrap = Wrap::Repeat;
    // Image: the texel values are the file's stored numbers (a data map: roughness, normals), not
    // sRGB-decoded colours; scene/load_texture.hpp says which parameters read data.
    bool linear_data = false;
    // Both kinds, as pbrt-v4's uv mapping and image texture have them: a lookup at uv reads the
    // pattern at (uv_scale.x u + uv_offset.x, uv_scale.y v + uv_offset.y); an image's value is then
    // multiplied by `multiply` (any sign), turned to 1 - value with `invert`, and kept in
    // [min_value, max_value] (the parameter's range: a bump map's height has none). The defaults
    // change nothing.
    glm::vec2 uv_scale{1.0f}, uv_offset{0.0f};
    glm::vec3 multiply{1.0f};
    bool invert = false;
    float min_value = 0.0f, max_value = 1.0f;
};

// What a surface does with light: every parameter the BSDF, emission and textures read. A hit's
// textured copy (render/materials/texture.hpp) is one of these, so the hot paths copy no name.
struct MaterialParameters {
    enum class Type { Diffuse, Metal, Dielectric, Emissive, ThinDielectric, RoughDielectric, CoatedDiffuse, Conductor, Interface };
    // Interface (pbrt-v4's "interface"): no surface at all for light, only the boundary between
    // the media on its two sides (Object::media); rays pass through it unchanged. It takes no
    // other key (no emission).
    // RoughDielectric reads roughness, ior and albedo (the transmission tint) like Metal and
    // Dielectric; CoatedDiffuse reads albedo (the base under the coating), ior and roughness (the
    // coating's; 0 = a smooth coat); Conductor reads eta, k, roughness (as Metal's) and albedo (a
    // tint, 1 by default).
    Type type = Type::Diffuse;
    glm::vec3 albedo{0.8f};    // Diffuse reflectance / Metal tint / (Thin)Dielectric transmission tint
    int albedo_texture = -1;   // index into Scene::textures replacing `albedo` at each hit, or -1
    // Diffuse: the diffuse transmission T (pbrt-v4's diffusetransmission), f = T / pi on the far
    // side of the surface beside albedo / pi on wo's side; 0 (the default) is an opaque Lambertian.
    glm::vec3 transmittance{0.0f};
    float roughness = 0.0f;    // Metal: 0 = perfect mirror
    // Conductor: the microfacet distribution of its rough lobe. GGX (the default, pbrt-v4's only
    // one) or Beckmann, which Tungsten and Mitsuba scenes name and whose far narrower tails pbrt-v4
    // cannot express (docs/reference-deviations-veach-bidir.md). Both take alpha = roughness^2.
    enum class Microfacet { Ggx, Beckmann };
    Microfacet microfacet = Microfacet::Ggx;
    float ior = 1.5f;          // Dielectric, ThinDielectric
    // Conductor: the complex index of refraction eta + i k per RGB channel, relative to the
    // outside (scene/named_metals.hpp holds the named metals'); albedo tints its Fresnel term.
    glm::vec3 eta{1.0f};
    glm::vec3 k{0.0f};
    glm::vec3 emission{0.0f};  // radiance leaving the front side; any material may emit
    // Emit from the back side too (e.g. the inside of a closed emissive sphere). The front is the
    // side the outward geometric normal points to: outside of closed shapes, edge_u x edge_v for
    // quads, the disk's normal, (b - a) x (c - a) for triangles and mesh faces.
    bool two_sided_emission = false;
    // Textures on the other parameters (indices into Scene::textures, or -1), evaluated at each
    // hit by render/materials/texture.hpp. With emission_texture, `emission` holds the texture's mean (the
    // light's selection weight; each hit and light sample reads the texture itself).
    int roughness_texture = -1;  // the mean of the texel's three channels
    int emission_texture = -1;
    // A tangent-space normal map (render/materials/shading_frame.hpp): replaces the shading normal.
    int normal_texture = -1;
    // A height field (the mean of a texel's channels, times bump_scale, in world units along the
    // normal) whose slope tilts the shading normal (render/materials/shading_frame.hpp), after any normal map.
    int bump_texture = -1;
    float bump_scale = 1.0f;
};

// A scene's material: its parameters and its name (for messages and statistics).
struct Material : MaterialParameters {
    std::string name;
};

// Whether any parameter of `m` is read from a texture (the renderer then evaluates them per hit).
inline bool reads_texture(const MaterialParameters& m) {
    return m.albedo_texture >= 0 || m.roughness_texture >= 0 || m.emission_texture >= 0 || m.normal_texture >= 0 ||
           m.bump_texture >= 0;
}

struct Scene {
    Camera camera;
    Film film;
    Background background;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Mesh> meshes;
    std::vector<Object> objects;
    std::vector<SceneLight> lights;  // the "lights" key: point, spot, directional
    std::vector<Medium> media;       // the "media" key (scene/load_media.hpp); objects and the camera name them
    std::uint64_t seed = 0;
    std::filesystem::path source;  // the scene file, for messages
    // The material libraries (.mtl) the meshes named, read for their materials: with the scene
    // file, the meshes' files and the images, what a farm part's identity hashes.
    std::vector<std::filesystem::path> material_libraries;
    // Every file the load read (read_files.hpp): the scene, meshes, libraries, images, spectra,
    // pbrt Includes. No output may be one of them.
    std::vector<std::filesystem::path> input_files;
};

// Whether light in `scene` meets anything but vacuum and surfaces: a medium the camera sits in or
// a surface bounds, or an interface surface. The integrators that do not render media refuse such
// a scene (render/renderer.cpp).
inline bool uses_media(const Scene& scene) {
    if (scene.camera.medium >= 0) return true;
    for (const Object& o : scene.objects)
        if (o.media.inside >= 0 || o.media.outside >= 0 || scene.materials[o.material].type == Material::Type::Interface)
            return true;
    return false;
}

}  // namespace sweeptrace
