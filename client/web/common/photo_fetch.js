// Which product photo the element fetches next (SPEC T12, T18), as the C++ client does
// (client/viewer/photo_fetch.cpp), pinned by tests/golden/warp-vectors.json: the first level of
// the photos the view is drawn from, then their finer level when the view shows them larger than
// the first, then the other photos' first level, nearest the view first, then (zoomed in) the
// finer level of the photos nearest the view, up to kFinerKept, so a zoomed-in turn finds the
// next photo sharp.
import { nearestSample, nearness } from './view_sphere.js';

export const kLevelSlack = 1.25;  // a level is enough while shown at most this many times its size
export const kFinerKept = 6;  // samples keeping a finer level at most (a 2048-pixel level is 16 MB on the GPU)

// The level a view needs whose photos are `shown` device pixels high: 0 while the first level
// (`firstHeight`) is enough, else the smallest of `levelHeights` that is, else the finest.
export function wantedLevel(firstHeight, levelHeights, shown) {
  if (shown <= kLevelSlack * firstHeight) return 0;
  const enough = levelHeights.findIndex((h) => shown <= kLevelSlack * h);
  return enough < 0 ? levelHeights.length : enough + 1;
}

// What to fetch next, {sample, level}, for a view from `direction` drawn from `drawnFrom`
// (viewSamples()); `hasFirst(i)` says whether sample i's first level is there, `finerLevel(i)`
// which finer level it has (0: none); `wanted` the view's level. Null when all of that is there.
export function nextPhotoFetch(directions, direction, drawnFrom, hasFirst, finerLevel, wanted) {
  // Nearest first; of two as near, the one the view's cell lists first (the sort is stable).
  const sorted = [...drawnFrom].sort((a, b) => nearness(directions[b], direction) - nearness(directions[a], direction));
  const first = sorted.find((s) => !hasFirst(s));
  if (first !== undefined) return { sample: first, level: 0 };
  const finer = wanted > 0 ? sorted.find((s) => finerLevel(s) < wanted) : undefined;
  if (finer !== undefined) return { sample: finer, level: wanted };
  const other = nearestSample(directions, direction, (i) => !hasFirst(i));
  if (other >= 0) return { sample: other, level: 0 };
  if (wanted === 0) return null;
  // Zoomed in, the photos a turn comes to next: the finer level of the nearest lacking it, while
  // fewer than kFinerKept hold one, or in place of the holder it would push out (finerToDrop())
  // when that one is farther from the view and not drawn from. Each such swap brings the holders
  // nearer the view, so a still view stops fetching.
  const ahead = nearestSample(directions, direction, (i) => finerLevel(i) < wanted);
  if (ahead < 0) return null;
  const holders = directions.map((_, i) => i).filter((i) => i === ahead || finerLevel(i) > 0);
  const pushedOut = finerToDrop(directions, ahead, holders);
  if (pushedOut < 0) return { sample: ahead, level: wanted };
  if (!drawnFrom.includes(pushedOut) && nearness(directions[ahead], direction) > nearness(directions[pushedOut], direction))
    return { sample: ahead, level: wanted };
  return null;
}

// When sample `added` has just taken a finer level and more than kFinerKept hold one (`holders`,
// their indices): the holder that gives way, the farthest from `added` (zoomed-in views turn
// slowly: it is needed last), the lowest index on a tie; -1 while none need give way.
export function finerToDrop(directions, added, holders) {
  if (holders.length <= kFinerKept) return -1;
  let farthest = -1, farthestNearness = 0;
  for (const s of [...holders].sort((a, b) => a - b)) {
    const n = nearness(directions[s], directions[added]);
    if (farthest < 0 || n < farthestNearness) farthest = s, farthestNearness = n;
  }
  return farthest;
}
