#pragma once
// Stroke textures for the textured-stroke sketchers (SPEC S5): pencil, charcoal and chalk, each
// a few variants of a strip that tiles along its length (u) with the stroke's cross-section
// across it (v). Alpha carries the mark; colour is the medium's. Generated from tileable noise
// with real grain and ragged edges, or loaded from image files.
#include <string>
#include <vector>

#include "common/image.hpp"

namespace inkwire {

enum class Medium { Pencil, Charcoal, Chalk };

// `variants` strips of `length` x `width` texels (length a power of two, tiling along u).
std::vector<Image> make_stroke_textures(Medium medium, int variants = 4, int length = 256, int width = 32, uint32_t seed = 7);

}  // namespace inkwire
