// One cell of tween data, as a tween-data message carries it: the cell layout of
// common/tween/tween_data.cpp (protocol/SPEC.md "Tween data"), read against the product's image
// size and sample count, with the same limits and the same one-line reasons. A point is three
// [x, y] positions in pixels: in the first sample, halfway, in the second (a ring pair), or in
// each of three samples (a sphere triangle).

export const kTweenFractionBits = 4;
export const kMaxTweenPointsPerCell = 4096;
export const kMaxTweenCellBytes = 16 * 1024;
const kStreams = 6;
const kMaxBits = 17;

export class TweenError extends Error {
  constructor(reason) {
    super(`tween data: ${reason}`);
    this.name = 'TweenError';
  }
}

class Reader {
  constructor(bytes) {
    this.b = bytes;
    this.pos = 0;
    this.bit = 0;
  }
  remaining() { return this.b.length - this.pos; }
  need(n, what) { if (this.remaining() < n) throw new TweenError(`truncated in ${what}`); }
  u8(what) { this.need(1, what); return this.b[this.pos++]; }
  u16(what) { this.need(2, what); const v = this.b[this.pos] | (this.b[this.pos + 1] << 8); this.pos += 2; return v; }
  varint(what) {
    let z = 0;
    for (let shift = 0; ; shift += 7) {
      if (shift > 28) throw new TweenError(`over-long number in ${what}`);
      const byte = this.u8(what);
      z += (byte & 0x7f) * 2 ** shift;
      if (!(byte & 0x80)) break;
    }
    z = z >>> 0;
    return (z >>> 1) ^ -(z & 1);
  }
  bits(count) {
    let v = 0;
    for (let i = 0; i < count; ++i) {
      v += ((this.b[this.pos] >> this.bit) & 1) * 2 ** i;
      if (++this.bit === 8) this.bit = 0, ++this.pos;
    }
    return v;
  }
  endBits() { if (this.bit !== 0) ++this.pos; this.bit = 0; }
}

class Writer {
  constructor() { this.bytes = []; this.bit = 0; }
  u8(v) { this.bytes.push(v & 0xff); }
  u16(v) { this.u8(v); this.u8(v >> 8); }
  varint(v) {
    let z = ((v << 1) ^ (v >> 31)) >>> 0;
    while (z >= 0x80) { this.u8((z & 0x7f) | 0x80); z >>>= 7; }
    this.u8(z);
  }
  bits(value, count) {
    for (let i = 0; i < count; ++i) {
      if (this.bit === 0) this.bytes.push(0);
      this.bytes[this.bytes.length - 1] |= (Math.floor(value / 2 ** i) & 1) << this.bit;
      this.bit = (this.bit + 1) % 8;
    }
  }
  endBits() { this.bit = 0; }
}

const quantise = (pixels, side) => Math.min(Math.max(Math.round(pixels * (1 << kTweenFractionBits)), 0), side << kTweenFractionBits);
const dequantise = (q) => q / (1 << kTweenFractionBits);
const half = (v) => Math.trunc(v / 2);  // C++ integer division truncates toward zero

// The six stream values of a point's quantised positions, and back.
function predict(x, y, pair) {
  if (pair) return [x[0], y[0], x[2] - x[0], y[2] - y[0], x[1] - half(x[0] + x[2]), y[1] - half(y[0] + y[2])];
  return [x[0], y[0], x[1] - x[0], y[1] - y[0], x[2] - x[0], y[2] - y[0]];
}
function unpredict(s, pair) {
  if (pair) {
    const x2 = s[0] + s[2], y2 = s[1] + s[3];
    return { x: [s[0], s[4] + half(s[0] + x2), x2], y: [s[1], s[5] + half(s[1] + y2), y2] };
  }
  return { x: [s[0], s[0] + s[2], s[0] + s[4]], y: [s[1], s[1] + s[3], s[1] + s[5]] };
}

function checkCell(cell, samples) {
  if (samples < 2 || samples > 4096) throw new TweenError(`${samples} samples (2..4096 allowed)`);
  if (cell.samples.length !== 2 && cell.samples.length !== 3) throw new TweenError(`a cell has ${cell.samples.length} samples (2 or 3 allowed)`);
  cell.samples.forEach((s, i) => {
    if (s >= samples) throw new TweenError(`sample index ${s} out of range (${samples} samples)`);
    if (cell.samples.indexOf(s) !== i) throw new TweenError(`a cell names sample ${s} twice`);
  });
  if (cell.points.length > kMaxTweenPointsPerCell) throw new TweenError(`a cell has ${cell.points.length} points (at most ${kMaxTweenPointsPerCell})`);
}

// {samples: [a, b(, c)], points: [[[x, y], [x, y], [x, y]], ...]} from a cell's bytes.
export function decodeTweenCell(bytes, width, height, samples) {
  if (bytes.length > kMaxTweenCellBytes) throw new TweenError(`a cell of ${bytes.length} bytes is over the limit`);
  const r = new Reader(bytes);
  const maxQ = [width << kTweenFractionBits, height << kTweenFractionBits];
  const arity = r.u8('a cell header');
  if (arity !== 2 && arity !== 3) throw new TweenError(`cell 0 has arity ${arity} (2 or 3)`);
  const cell = { samples: [], points: [] };
  for (let k = 0; k < arity; ++k) cell.samples.push(r.u16('a cell header'));
  const count = r.u16('a cell header');
  if (count > kMaxTweenPointsPerCell) throw new TweenError(`cell 0 has ${count} points (at most ${kMaxTweenPointsPerCell})`);
  if (count > 0) {
    const lo = [], widths = [];
    let totalBits = 0;
    for (let s = 0; s < kStreams; ++s) {
      lo.push(r.varint('a stream header'));
      widths.push(r.u8('a stream header'));
      if (lo[s] < -65535 || lo[s] > 65535 || widths[s] > kMaxBits) throw new TweenError('cell 0 has a malformed stream header');
      totalBits += widths[s] * count;
    }
    r.need(Math.ceil(totalBits / 8), 'point data');
    const values = Array.from({ length: count }, () => new Array(kStreams));
    for (let s = 0; s < kStreams; ++s) for (const v of values) v[s] = lo[s] + r.bits(widths[s]);
    r.endBits();
    for (const v of values) {
      const q = unpredict(v, arity === 2);
      const point = [];
      for (let k = 0; k < 3; ++k) {
        if (q.x[k] < 0 || q.y[k] < 0 || q.x[k] > maxQ[0] || q.y[k] > maxQ[1]) throw new TweenError('cell 0 has a point outside the image');
        point.push([dequantise(q.x[k]), dequantise(q.y[k])]);
      }
      cell.points.push(point);
    }
  }
  if (r.remaining() !== 0) throw new TweenError(`${r.remaining()} bytes after the cell`);
  if (width < 1 || height < 1 || width > 4095 || height > 4095) throw new TweenError(`image size ${width}x${height} is outside 1..4095`);
  checkCell(cell, samples);
  return cell;
}

export function encodeTweenCell(cell, width, height, samples) {
  checkCell(cell, samples);
  const w = new Writer();
  w.u8(cell.samples.length);
  for (const s of cell.samples) w.u16(s);
  w.u16(cell.points.length);
  if (cell.points.length > 0) {
    const values = cell.points.map((p) => predict(p.map((v) => quantise(v[0], width)), p.map((v) => quantise(v[1], height)), cell.samples.length === 2));
    const lo = [], widths = [];
    for (let s = 0; s < kStreams; ++s) {
      const column = values.map((v) => v[s]);
      lo.push(Math.min(...column));
      const spread = Math.max(...column) - lo[s];
      widths.push(spread === 0 ? 0 : Math.floor(Math.log2(spread)) + 1);
      w.varint(lo[s]);
      w.u8(widths[s]);
    }
    for (let s = 0; s < kStreams; ++s) for (const v of values) w.bits(v[s] - lo[s], widths[s]);
    w.endBits();
  }
  return Uint8Array.from(w.bytes);
}

// Where a pair's point is at t in [0, 1]: the quadratic Bézier through the halfway position at
// t = 0.5, as weights of the three stored positions (common/tween/tween_data.cpp path_weights).
export function pathWeights(t) {
  const u = 1 - t;
  return [u * u - t * u, 4 * t * u, t * t - t * u];
}
