#pragma once
// How bright a colour is, by either of the two weightings in use, each named where it is used:
// Rec. 709's (the sRGB primaries' luminance: what the painterly styles shade and wash by) and
// Rec. 601's luma (video's: what OpenCV's grey, the face analysis, the landmark finder and the
// picture metrics read, so their figures compare with the libraries' own). Both take the channels
// in whatever scale they come (0-255 or 0-1) and answer in the same.
namespace inkwire {

template <typename T>
constexpr T rec709_luminance(T r, T g, T b) {
  return T(0.2126) * r + T(0.7152) * g + T(0.0722) * b;
}

template <typename T>
constexpr T rec601_luma(T r, T g, T b) {
  return T(0.299) * r + T(0.587) * g + T(0.114) * b;
}

}  // namespace inkwire
