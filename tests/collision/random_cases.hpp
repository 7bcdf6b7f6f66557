#pragma once
// Seeded random inputs shared by the collision tests. std::mt19937 is specified bit for bit by
// the standard; the values drawn are reproducible for a given standard library.
#include <cstdint>
#include <random>

#include <glm/vec3.hpp>

#include "collision/shapes.hpp"

namespace testing {

struct SeededRng {
    std::mt19937 gen;
    explicit SeededRng(std::uint32_t seed) : gen(seed) {}
    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(gen); }
    glm::vec3 vec(float lo, float hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(gen); }
    collision::Triangle triangle(const glm::vec3& around, float spread) {
        return {around + vec(-spread, spread), around + vec(-spread, spread), around + vec(-spread, spread)};
    }
};

}  // namespace testing
