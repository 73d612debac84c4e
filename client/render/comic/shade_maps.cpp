#include "client/render/comic/shade_maps.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "common/error.hpp"

namespace inkwire {
namespace {

constexpr int kWidth = 64, kHeight = 32;  // N.L resolution, R.V resolution

using Texel = glm::u8vec4;
// Fills the map from a function of (N.L, R.V), both in 0..1 at texel centres.
Image tabulate(const std::function<Texel(float, float)>& f, int width = kWidth, int height = kHeight) {
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float n_dot_l = (x + 0.5f) / width;
      const float r_dot_v = 1.0f - (y + 0.5f) / height;  // image rows run top-down
      const Texel t = f(n_dot_l, r_dot_v);
      std::copy(&t[0], &t[0] + 4, img.at(x, y));
    }
  return img;
}

Texel grey(float factor) {
  const uint8_t v = shade_texel(factor);
  return {v, v, v, 255};
}
Texel lifted(float toward_white) {
  const uint8_t v = lift_texel(toward_white);
  return {v, v, v, 255};
}

std::vector<float> edges_for(const ShadeMapOptions& o) {
  if (!o.band_edges.empty()) {
    if (int(o.band_edges.size()) != o.bands - 1)
      throw Error("shade map: " + std::to_string(o.bands) + " bands need " + std::to_string(o.bands - 1) + " band edges");
    for (size_t i = 0; i < o.band_edges.size(); ++i)
      if (o.band_edges[i] <= 0.0f || o.band_edges[i] >= 1.0f || (i > 0 && o.band_edges[i] <= o.band_edges[i - 1]))
        throw Error("shade map: band edges must rise strictly within 0..1");
    return o.band_edges;
  }
  std::vector<float> e;
  for (int i = 1; i < o.bands; ++i) e.push_back(float(i) / o.bands);
  return e;
}

// The band a given N.L falls in, 0 = darkest.
int band_of(float n_dot_l, const std::vector<float>& edges) {
  return int(std::upper_bound(edges.begin(), edges.end(), n_dot_l) - edges.begin());
}

// Brightness of band i of n: evenly from (1 - shadow) up to 1.
float band_factor(int i, int n, float shadow) { return n <= 1 ? 1.0f : 1.0f - shadow * float(n - 1 - i) / float(n - 1); }

bool in_highlight(float n_dot_l, float r_dot_v, const ShadeMapOptions& o) {
  return o.highlight_threshold > 0.0f && n_dot_l > 0.0f && r_dot_v >= o.highlight_threshold;
}

Image banded(const ShadeMapOptions& o) {
  if (o.bands < 1 || o.bands > 16) throw Error("shade map: bands must be 1..16");
  const std::vector<float> edges = edges_for(o);
  return tabulate([&](float nl, float rv) {
    if (in_highlight(nl, rv, o)) return lifted(o.highlight);
    return grey(band_factor(band_of(nl, edges), o.bands, o.shadow));
  });
}

}  // namespace

const std::vector<std::string>& shade_map_names() {
  static const std::vector<std::string> names = {"comic", "two-tone", "flat", "lines", "checker", "metal", "phong", "warm-cool"};
  return names;
}

ShadeMap make_shade_map(const std::string& name, const ShadeMapOptions& o) {
  if (o.shadow < 0.0f || o.shadow > 1.0f) throw Error("shade map: shadow must be 0..1");
  if (name == "comic") return {banded(o), false};
  if (name == "two-tone") {
    ShadeMapOptions two = o;
    two.bands = 2;
    if (two.band_edges.size() != 1) two.band_edges = {0.35f};
    return {banded(two), false};
  }
  if (name == "flat") return {tabulate([](float, float) { return grey(1.0f); }), false};
  if (name == "lines") {
    // Bands separated by thin black lines on the band edges, three texels (0.05 of N.L) wide:
    // thinner ones break up where N.L changes quickly across the screen.
    const std::vector<float> edges = edges_for(o);
    return {tabulate([&](float nl, float rv) {
              for (float e : edges)
                if (std::abs(nl - e) < 1.5f / kWidth) return grey(0.0f);
              if (in_highlight(nl, rv, o)) return lifted(o.highlight);
              return grey(band_factor(band_of(nl, edges), o.bands, o.shadow));
            }),
            false};
  }
  if (name == "checker") {
    // Checkerboard cross-over: diffuse and specular bands cross, alternating light and dark.
    return {tabulate([&](float nl, float rv) {
              const int cell = int(nl * 4.0f) + int(std::max(rv, 0.0f) * 4.0f);
              return cell % 2 ? grey(1.0f - o.shadow) : grey(1.0f);
            }),
            false};
  }
  if (name == "metal") {
    // Chrome: hard stripes of a reflected horizon that follow R.V far more than N.L, cool tint.
    return {tabulate([&](float nl, float rv) {
              const float r = 0.75f * rv + 0.25f * nl;
              static const float stripes[] = {0.25f, 0.55f, 0.35f, 0.85f, 0.6f, 1.0f};
              const float f = stripes[std::min(5, int(r * 6.0f))];
              if (r > 0.93f) return lifted(0.9f);
              const Texel t = grey(f);
              return Texel(t.r, t.g, shade_texel(std::min(1.0f, f * 1.08f)), 255);
            }),
            true};
  }
  if (name == "phong") {
    // Near-Phong: ambient + diffuse, and a specular lobe lifted toward white.
    return {tabulate([&](float nl, float rv) {
              const float spec = std::pow(std::max(rv, 0.0f), 24.0f) * (nl > 0.0f ? 1.0f : 0.0f);
              if (spec > 0.02f) return lifted(spec);
              return grey(0.25f + 0.75f * nl);
            }),
            true};
  }
  if (name == "warm-cool") {
    // Coloured light: a warm key light and a cool fill in the shadow band.
    const std::vector<float> edges = edges_for(o);
    return {tabulate([&](float nl, float rv) {
              if (in_highlight(nl, rv, o)) return Texel(lift_texel(o.highlight), lift_texel(o.highlight * 0.9f), lift_texel(o.highlight * 0.7f), 255);
              const float f = band_factor(band_of(nl, edges), o.bands, o.shadow);
              if (band_of(nl, edges) == 0) return Texel(shade_texel(f * 0.85f), shade_texel(f * 0.9f), shade_texel(f * 1.15f), 255);
              return Texel(lift_texel(0.06f * f), shade_texel(f), shade_texel(f * 0.9f), 255);
            }),
            false};
  }
  std::string known;
  for (const auto& n : shade_map_names()) known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown shade map '" + name + "' (known: " + known + ")");
}

ShadeMap load_shade_map(const std::string& file, bool smooth) {
  Image img = load_image(file);
  if (img.width < 2 || img.width > 4096 || img.height > 4096) throw Error(file + ": a shade map must be 2..4096 texels wide");
  return {std::move(img), smooth};
}

}  // namespace inkwire
