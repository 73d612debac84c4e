// Presenter mode (SPEC T13), mirroring client/viewer/turntable_view.cpp TurntableOrbit::pose()
// and from_pose(): a visitor's view shared with the session as the object pose that turns the
// product (without roll) so that the first sample's direction, (0, 0, 1), sees it as this view
// does; the zoom as its scale. Angles in degrees; quaternions [x, y, z, w].
const kRadiansPerHalfDegree = Math.PI / 360;
// How far a visitor zooms (TurntableOrbit::kMinZoom, kMaxZoom): the element's wheel and pinch and
// shared poses alike.
export const kMinZoom = 0.5, kMaxZoom = 4;

export function poseOfView(azimuth, elevation, zoom, sequence = 0) {
  // Turning by -azimuth about the vertical, then by elevation about the horizontal.
  const e = elevation * kRadiansPerHalfDegree, a = -azimuth * kRadiansPerHalfDegree;
  const ex = Math.sin(e), ew = Math.cos(e), ay = Math.sin(a), aw = Math.cos(a);
  return { type: 'object-pose', sequence, rotation: [ex * aw, ew * ay, ex * ay, ew * aw], translation: [0, 0, 0], scale: zoom };
}

// {azimuth, elevation, zoom} of a pose (the decoder has checked it is a unit quaternion).
export function viewOfPose({ rotation: [x, y, z, w], scale }) {
  // (0, 0, 1) turned back by the pose's rotation.
  const d = [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)];
  const length = Math.hypot(d[0], d[1], d[2]);
  return {
    azimuth: (Math.atan2(d[0], d[2]) * 180) / Math.PI,
    elevation: (Math.asin(Math.min(Math.max(d[1] / length, -1), 1)) * 180) / Math.PI,
    zoom: Math.min(Math.max(scale, kMinZoom), kMaxZoom),
  };
}
