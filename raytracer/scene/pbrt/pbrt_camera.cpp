// pbrt-v4's Camera, Film, Sampler, PixelFilter and Integrator as our "camera" and "film".
//
// Field of view: pbrt's "fov" spans the shorter image axis, ours the vertical one. pbrt's screen
// window is [-a, a] x [-1, 1] for an aspect a = "frameaspectratio" (default x/y resolution) >= 1
// and [-1, 1] x [-1/a, 1/a] otherwise, at tan(fov/2) per unit on the plane z = 1, so our vertical
// half-angle is atan(tan(fov/2) * (window's y extent / 2)). Depth: pbrt's "maxdepth" counts
// scattering events (0: emitted light only, 1: direct lighting), ours counts path vertices after
// the camera (1: emitted only), so ours = maxdepth + 1. Thin lens: our aperture is the lens
// diameter, 2 "lensradius", focused on the plane at "focaldistance" (pbrt's default 1e6).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include "raytracer/input_error.hpp"
#include "raytracer/scene/film_limits.hpp"
#include "raytracer/scene/pbrt/pbrt_transform.hpp"
#include "raytracer/scene/pbrt/pbrt_world.hpp"

namespace sweeptrace::pbrt {

using nlohmann::json;

namespace {


long long clamped(Diagnostics& d, const Where& at, const std::string& what, long long v, long long lo, long long hi) {
    if (v >= lo && v <= hi) return v;
    const long long c = std::clamp(v, lo, hi);
    d.warn(at, what + " range", what + " " + std::to_string(v) + " is outside our [" + std::to_string(lo) + ", " +
                                    std::to_string(hi) + "]: " + std::to_string(c) + " used");
    return c;
}

// What we render in place of pbrt-v4's integrators; empty for "path" and "volpath" (our path
// tracer), "bdpt" (our bidirectional one, film.integrator "bdpt") and "sppm" (our vertex
// connection and merging, film.integrator "vcm": its merges are progressive photon mapping with
// the same radius schedule, its connections add what sppm leaves to noise, and it converges to
// the same image). The other light-tracing methods (mlt, lightpath) reach paths our unidirectional path tracer cannot: light that
// leaves a small source, passes a specular surface and lands on a diffuse one (a caustic) is found
// only when a camera path happens to hit the source after the specular bounce, so it stays black
// or extremely noisy; a delta light can never be hit at all, so light from pbrt's distant, point,
// spot, goniometric or projection light arriving through or off a specular surface is missing,
// whatever the spp. Saying "the same image with other noise" hid both.
std::string integrator_warning(const std::string& type) {
    if (type == "path" || type == "volpath" || type == "bdpt" || type == "sppm") return {};
    if (type == "mlt" || type == "lightpath")
        return " is not supported: our unidirectional path tracer renders instead (Integrator \"bdpt\" or \"sppm\" would "
               "select our bidirectional ones, which reach these paths), and converges to the same image only "
               "where light reaches a diffuse surface without passing a specular one (mirror, smooth glass or metal) "
               "first: caustics from small lights through or off specular surfaces stay black or extremely noisy "
               "at any spp, and light from a delta light (\"distant\", \"point\", \"spot\", \"goniometric\", "
               "\"projection\") seen through or reflected in a specular surface is never reached at all (black)";
    if (type == "ambientocclusion" || type == "aov")
        return " is not supported: it renders a different quantity (ambient occlusion or geometry buffers), "
               "a path-traced image is rendered instead";
    if (type == "simplepath" || type == "simplevolpath" || type == "randomwalk")
        return " is not supported: our path tracer renders instead, the same converged image with other noise "
               "(pbrt's own image lacks delta lights where its light sampling is off; ours has them)";
    return " is not a pbrt-v4 integrator: our unidirectional path tracer renders instead";
}

json filter_json(WorldContext& w) {
    Diagnostics& d = w.diag;
    if (!w.scene.filter) return {{"type", "gaussian"}, {"radius", 1.5}, {"sigma", 0.5}};  // pbrt-v4's default
    const Statement& s = *w.scene.filter;
    const ParamList& p = s.params;
    const std::string what = "PixelFilter \"" + excerpt(s.type) + "\"";
    auto radius = [&](double fallback) {
        double x = p.get_float("xradius", p.get_float("xwidth", fallback, d), d);
        const double y = p.get_float("yradius", p.get_float("ywidth", x, d), d);
        if (x != y) d.warn(s.where, "filter xy radius", what + ": different x and y radii: the x radius is used for both");
        if (x < 0.05 || x > 16.0) {
            d.warn(s.where, "filter radius", what + ": radius outside our [0.05, 16] pixels: clamped");
            x = std::clamp(x, 0.05, 16.0);
        }
        return x;
    };
    json f;
    if (s.type == "box") {
        f = {{"type", "box"}, {"radius", radius(0.5)}};
    } else if (s.type == "triangle") {
        f = {{"type", "tent"}, {"radius", radius(2.0)}};
    } else if (s.type == "gaussian") {
        f = {{"type", "gaussian"}, {"radius", radius(1.5)}, {"sigma", std::clamp(p.get_float("sigma", 0.5, d), 0.05, 16.0)}};
    } else if (s.type == "mitchell") {
        f = {{"type", "mitchell"}, {"radius", radius(2.0)}, {"b", std::clamp(p.get_float("B", 1.0 / 3.0, d), 0.0, 1.0)},
             {"c", std::clamp(p.get_float("C", 1.0 / 3.0, d), 0.0, 1.0)}};
    } else {
        d.warn(s.where, "filter " + s.type, what + " is not supported: approximated by a Mitchell filter with b 0, c 0.5 (Catmull-Rom) of its radius");
        p.find("tau");
        f = {{"type", "mitchell"}, {"radius", radius(4.0)}, {"b", 0.0}, {"c", 0.5}};
    }
    p.warn_unused(what, d);
    return f;
}

}  // namespace

void write_camera_and_film(WorldContext& w, std::string& film_filename) {
    Diagnostics& d = w.diag;
    const PbrtScene& sc = w.scene;
    json film = json::object();

    // Film.
    long long xres = 1280, yres = 720;
    double iso = 100.0, film_scale = 1.0, film_exposure = -1.0;
    film_filename = "pbrt.exr";
    if (sc.film) {
        const Statement& s = *sc.film;
        const ParamList& p = s.params;
        const std::string what = "Film \"" + excerpt(s.type) + "\"";
        if (s.type != "rgb" && s.type != "gbuffer")
            d.warn(s.where, "film " + s.type, what + " is not supported: an rgb film instead");
        xres = clamped(d, s.where, "Film xresolution", p.get_int("xresolution", 1280, d), 1, 16384);
        yres = clamped(d, s.where, "Film yresolution", p.get_int("yresolution", 720, d), 1, 16384);
        film_filename = p.get_string("filename", "pbrt.exr", d);
        iso = p.get_float("iso", 100.0, d);
        // Earlier pbrt-v4 (and pbrt-v3) films: "scale" multiplies every pixel, and "exposuretime"
        // stands where the camera's shutter interval stands now; scenes of that time still use them.
        film_scale = p.get_float("scale", 1.0, d);
        film_exposure = p.get_float("exposuretime", -1.0, d);
        if (const double m = p.get_float("maxcomponentvalue", 0.0, d); m > 0.0 && std::isfinite(m)) film["clamp_sample"] = m;
        for (const char* q : {"cropwindow", "pixelbounds", "whitebalance", "sensor"})
            if (p.has(q)) {
                p.find(q);
                d.warn(s.where, std::string("film ") + q, what + ": \"" + q + "\" is not supported (ignored)");
            }
        // Storage and the realistic camera's sensor size: nothing to translate.
        p.find("savefp16");
        p.find("diagonal");
        if (s.type == "gbuffer") p.find("coordinatesystem");
        p.warn_unused(what, d);
    }
    film["width"] = xres;
    film["height"] = yres;

    // Sampler.
    long long spp = 16;
    if (sc.sampler) {
        const Statement& s = *sc.sampler;
        const ParamList& p = s.params;
        const std::string what = "Sampler \"" + excerpt(s.type) + "\"";
        if (s.type == "stratified") {
            spp = p.get_int("xsamples", 4, d) * p.get_int("ysamples", 4, d);
            // Without jitter every sample sits at its stratum's centre: a biased (aliased) image,
            // not the one our sampler converges to.
            if (!p.get_bool("jitter", true, d))
                d.warn(s.where, "sampler unjittered", what + ": \"jitter\" false (samples at stratum centres) is not reproduced: jittered samples instead");
        } else {
            spp = p.get_int("pixelsamples", 16, d);
        }
        // Every pbrt-v4 sampler of unbiased, well-distributed samples (halton, pmj02bn, the Sobol
        // variants, jittered stratified) estimates the same image; ours, an Owen-scrambled Sobol
        // sampler, is one more of them: other noise, the same converged image, nothing to warn.
        if (s.type == "independent") film["sampler"] = "independent";
        else {
            film["sampler"] = "sobol";
            const bool known = s.type == "sobol" || s.type == "zsobol" || s.type == "paddedsobol" || s.type == "halton" ||
                               s.type == "pmj02bn" || s.type == "stratified";
            if (!known) d.warn(s.where, "sampler " + s.type, what + " is not a pbrt-v4 sampler: our Owen-scrambled Sobol sampler instead");
            p.find("randomization");
        }
        // pbrt-v4's seed is any int; ours is unsigned 64-bit (written as such: a signed JSON
        // integer is refused as "must be >= 0"), a negative one taken modulo 2^64.
        if (p.has("seed")) w.doc["seed"] = static_cast<std::uint64_t>(p.get_int("seed", 0, d));
        p.warn_unused(what, d);
        spp = clamped(d, s.where, "Sampler pixelsamples", spp, 1, 1 << 20);
    }
    film["spp"] = spp;

    // Integrator.
    long long depth = 5;
    if (sc.integrator) {
        const Statement& s = *sc.integrator;
        const ParamList& p = s.params;
        const std::string what = "Integrator \"" + excerpt(s.type) + "\"";
        if (s.type == "bdpt") film["integrator"] = "bdpt";
        if (s.type == "sppm") {
            film["integrator"] = "vcm";
            // A stated initial search radius is our first iteration's. Without one, pbrt starts
            // at 1 scene unit and shrinks it per pixel by the photons it collects, within a few
            // iterations; our schedule, (i + 1)^((alpha - 1) / 2), would keep a 1 m blur for the
            // whole render, so our pixel-footprint default (vcm.hpp) takes pbrt's place. The photon
            // count per iteration and the iteration count are the render's: one light subpath per
            // pixel per sample (spp), which changes the noise, not the converged image.
            if (p.has("radius")) {
                const double radius = p.get_float("radius", 1.0, d);
                const RadiusRange range = vcm_radius_range();
                const auto format_g = [](double v) {
                    char t[32];
                    std::snprintf(t, sizeof t, "%g", v);
                    return std::string(t);
                };
                if (!(radius > 0.0 && std::isfinite(radius)))
                    d.warn(s.where, "sppm radius", what + ": \"radius\" " + std::to_string(radius) + " is not > 0: our default used");
                else if (radius < range.lo || radius > range.hi)  // said here, not at the Film it is translated to
                    d.fail(s.where, what + ": \"float radius\" must be in [" + format_g(range.lo) + ", " + format_g(range.hi) +
                                        "] (a merging radius whose schedule stays a finite, non-zero float), got " + format_g(radius));
                else film["vcm_radius"] = radius;
            }
            p.find("photonsperiteration");
            p.find("iterations");
            p.find("seed");
        }
        if (const std::string why = integrator_warning(s.type); !why.empty())
            d.warn(s.where, "integrator " + s.type, what + why);
        depth = p.get_int("maxdepth", 5, d);
        if (p.get_bool("regularize", false, d)) d.warn(s.where, "regularize", what + ": \"regularize\" is not supported (ignored)");
        p.find("lightsampler");  // which light is sampled: changes noise, not the image
        p.warn_unused(what, d);
        depth = clamped(d, s.where, "Integrator maxdepth", depth, 0, 1023);
    }
    film["max_depth"] = depth + 1;
    film["filter"] = filter_json(w);

    // Camera.
    double fov = 90.0, lens_radius = 0.0, focal = 1e6, shutter_open = 0.0, shutter_close = 1.0;
    double frame = double(xres) / double(yres);
    double window[4];
    bool window_given = false;
    if (sc.camera) {
        const Statement& s = *sc.camera;
        const ParamList& p = s.params;
        const std::string what = "Camera \"" + excerpt(s.type) + "\"";
        if (s.type != "perspective") {
            d.warn(s.where, "camera " + s.type, what + " is not supported: a perspective camera of its position instead");
            for (const Param& q : p.params) q.used = true;
        }
        fov = p.get_float("fov", 90.0, d);
        lens_radius = p.get_float("lensradius", 0.0, d);
        focal = p.get_float("focaldistance", 1e6, d);
        frame = p.get_float("frameaspectratio", frame, d);
        const std::vector<double> sw = p.get_floats("screenwindow", d);
        if (!sw.empty()) {
            if (sw.size() != 4) d.fail(s.where, what + ": \"screenwindow\" takes 4 numbers: x0 x1 y0 y1");
            std::copy(sw.begin(), sw.end(), window);
            window_given = true;
        }
        shutter_open = p.get_float("shutteropen", 0.0, d);
        shutter_close = p.get_float("shutterclose", 1.0, d);
        p.warn_unused(what, d);
        if (!(fov > 0.0 && fov < 180.0)) d.fail(s.where, what + ": \"fov\" must be strictly between 0 and 180 degrees");
        if (lens_radius < 0.0) d.fail(s.where, what + ": \"lensradius\" must be >= 0");
        if (!(focal > 0.0)) d.fail(s.where, what + ": \"focaldistance\" must be > 0");
        if (!(frame > 0.0)) d.fail(s.where, what + ": \"frameaspectratio\" must be > 0");
    }
    if (!window_given) {
        if (frame > 1.0) {
            window[0] = -frame, window[1] = frame, window[2] = -1.0, window[3] = 1.0;
        } else {
            window[0] = -1.0, window[1] = 1.0, window[2] = -1.0 / frame, window[3] = 1.0 / frame;
        }
    }
    const Where cam_at = sc.camera ? sc.camera->where : Where{std::make_shared<const std::string>(sc.main_file.string()), 1};
    if (!(window[1] > window[0] && window[3] > window[2])) d.fail(cam_at, "Camera: \"screenwindow\" must have x0 < x1 and y0 < y1");
    if (window[0] != -window[1] || window[2] != -window[3])
        d.warn(cam_at, "off-centre screen window", "Camera: an off-centre \"screenwindow\" is centred (our camera looks through the image centre)");
    const double wy = 0.5 * (window[3] - window[2]), wx = 0.5 * (window[1] - window[0]);
    if (std::fabs(wx / wy - double(xres) / double(yres)) > 1e-6 * (wx / wy))
        d.warn(cam_at, "non-square pixels", "Camera: the screen window's aspect differs from the image's (non-square pixels): the vertical field of view is kept");
    const double half = std::tan(0.5 * fov * kPi / 180.0) * wy;
    // A window of height 2 (the usual case) keeps the fov as written, not its round trip through tan.
    const double vfov = wy == 1.0 ? fov : 2.0 * std::atan(half) * 180.0 / kPi;
    if (!(vfov > 0.0 && vfov < 180.0)) d.fail(cam_at, "Camera: the vertical field of view comes out outside (0, 180) degrees");

    // Pose: world-from-camera. Its columns are pbrt's image right, image up and forward in the
    // world; when they form a right-handed frame (det > 0) the image's right is up x forward,
    // which is our left-handed camera (pbrt_world.hpp).
    const glm::dmat4 wfc = glm::inverse(sc.camera_from_world);
    const glm::dvec3 eye(wfc[3]);
    const glm::dvec3 forward = glm::normalize(glm::dvec3(wfc * glm::dvec4(0, 0, 1, 0)));
    glm::dvec3 up = glm::dvec3(wfc * glm::dvec4(0, 1, 0, 0));
    up = up - glm::dot(up, forward) * forward;
    if (!(glm::length(up) > 0.0) || !std::isfinite(eye.x + eye.y + eye.z + forward.x + forward.y + forward.z))
        d.fail(cam_at, "the camera transform is degenerate (its y axis is parallel to its z axis, or not finite)");
    up = glm::normalize(up);
    // Far enough that look_at - position survives rounding to float; only the direction matters
    // for a pinhole.
    const double look_distance = lens_radius > 0.0 ? focal : std::max(1.0, glm::length(eye));
    const glm::dvec3 look = eye + look_distance * forward;
    json camera{{"position", {eye.x, eye.y, eye.z}}, {"look_at", {look.x, look.y, look.z}}, {"up", {up.x, up.y, up.z}}, {"fov", vfov}};
    if (det3(wfc) > 0.0) camera["handedness"] = "left";
    if (lens_radius > 0.0) {
        camera["aperture"] = 2.0 * lens_radius;
        camera["focus_distance"] = focal;
    }
    w.doc["camera"] = camera;
    w.doc["film"] = film;

    // The sensor's imaging ratio (pbrt_world.hpp), applied to the emitters once they are written.
    const double ratio = (film_exposure >= 0.0 ? film_exposure : shutter_close - shutter_open) * iso / 100.0 * film_scale;
    if (ratio > 0.0 && std::isfinite(ratio)) {
        w.imaging_ratio = ratio;
    } else {
        d.warn(sc.film ? sc.film->where : cam_at, "imaging ratio",
               "Film: exposure time (shutterclose - shutteropen) x iso / 100 (x scale) is not positive, a black image in pbrt: 1 used instead");
    }
}

}  // namespace sweeptrace::pbrt
