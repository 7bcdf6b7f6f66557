#pragma once
// The directional albedo of a rough dielectric coat's reflection, for the coated diffuse with a
// rough coat (bsdf.hpp states the model): E(mu) = integral of the GGX reflection lobe's f cos
// over the hemisphere, Fresnel at the microfacet (exact, for index eta), single scattering,
// for light arriving at cos theta = mu; and its cosine-weighted mean 2 int E(mu) mu dmu.
//
// Tabulated per eta on first use (64 x 64: mu = t^2 on a uniform t grid, and roughness, every
// entry a 32 x 32 stratified visible-normal quadrature; 16 kB and ~0.2 s per distinct eta in a
// scene, kept for the process's life), then read bilinearly.
// Tables are shared by all threads (built once under a lock; a thread remembers its last one)
// and depend on nothing but eta, so images stay deterministic.
//
// Error: against a 256 x 256 quadrature at 41 x 51 points off the grid (mu >= 1e-3), for eta
// 1.2, 1.5 and 2.2, the raw table is within 1.9e-3 of the lobe's albedo and at most 1.3e-3 below
// it; closer to grazing at low roughness (mu = 0.003, roughness 0.04) it is 8.5e-3 above. Every
// entry is raised by kCoatAlbedoMargin = 2e-3 so that the table never falls below the lobe: the
// coated diffuse then hands the base at most what the coat lets through, and never gains energy
// (it loses up to ~4e-3 of the light for it, ~1e-2 within a degree of grazing).
// test_render_coated_diffuse.cpp checks the bracket.
namespace sweeptrace {

inline constexpr float kCoatAlbedoMargin = 2e-3f;

struct CoatAlbedo {
    float albedo = 0.0f;       // E(mu)
    float mean_albedo = 0.0f;  // 2 int_0^1 E(mu) mu dmu, at the same roughness
};

CoatAlbedo coat_albedo(float eta, float roughness, float mu);

// The same albedo computed directly on a strata x strata grid (the table's entries use 32).
float coat_lobe_albedo(float eta, float alpha, float mu, int strata);

// GGX alpha for a coat of this roughness: roughness^2 clamped below like the metal's.
float coat_alpha(float roughness);

}  // namespace sweeptrace
