// How the turntable frames its photos in an element of any shape (common/camera.hpp
// fit_scale, pinned by tests/golden/warp-vectors.json "framing"): drawn at the element's full
// height where it is at least as wide as they are, scaled down to its width where it is
// narrower (a phone held upright), so the whole product shows either way.
export function fitScale(viewportAspect, pictureAspect) {
  if (!(viewportAspect > 0) || !(pictureAspect > 0)) return 1;
  return Math.min(1, viewportAspect / pictureAspect);
}
