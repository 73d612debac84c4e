// A let-go drag keeps turning and slows down, as a physical turntable does: the rule of the
// native window's Inertia (client/viewer/window_input.hpp), pinned to it by
// tests/golden/warp-vectors.json ("inertia", written by WarpVectorsTest).

export const kMaxTurnSpeed = 360;   // degrees a second a fling may keep: a turn a second
export const kInertiaSeconds = 0.4; // the speed falls by a factor e in this long
export const kInertiaStop = 2;      // degrees a second below which it stops
export const kDegreesPerPixel = 0.4;  // a drag turns the view this far a pixel, either way

// The speed a drag leaves (degrees a second): the last moments of the drag, smoothed, a drag of
// `degrees` in `seconds` the newest, at most a turn a second either way.
export function draggedVelocity(velocity, degrees, seconds) {
  return Math.min(Math.max(0.7 * velocity + 0.3 * (degrees / seconds), -kMaxTurnSpeed), kMaxTurnSpeed);
}

// `seconds` of coasting at `velocity`: how far it turns and the speed left (0 once too slow).
export function coast(velocity, seconds) {
  if (Math.abs(velocity) <= kInertiaStop) return { turn: 0, velocity: 0 };
  return { turn: velocity * seconds, velocity: velocity * Math.exp(-seconds / kInertiaSeconds) };
}
