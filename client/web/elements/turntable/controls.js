// <inkwire-turntable>'s controls (SPEC W2): drag with mouse, touch or pen (with inertia; up and
// down as far as the product has rows of photos, SPEC T17), wheel or pinch to zoom, arrow keys
// step one photo left and right, one row up and down. Handlers are added with the connection's
// AbortSignal and go when the element leaves the page, so an element moved in the
// page turns once as far, never twice.

import { draggedVelocity } from '../../common/inertia.js';
import { kMaxZoom, kMinZoom } from '../../common/turntable_pose.js';

const kDegreesPerPixel = 0.4;  // as the C++ window turns

function nearestIndex(values, value) {
  let best = 0;
  values.forEach((v, i) => { if (Math.abs(v - value) < Math.abs(values[best] - value)) best = i; });
  return best;
}

export const ControlsMixin = (Base) => class extends Base {
  connectedCallback() {
    super.connectedCallback();
    this.listen(this.connection);
  }

  // Pointer, wheel and key handlers, removed with `signal` (when the element leaves the page).
  listen(signal) {
    const c = this.canvas, options = { signal };
    c.addEventListener('pointerdown', (e) => {
      this.touched = true;
      this.velocity = 0;
      c.setPointerCapture(e.pointerId);
      this.pointers.set(e.pointerId, { x: e.clientX, y: e.clientY, t: e.timeStamp });
      c.classList.add('dragging');
    }, options);
    c.addEventListener('pointermove', (e) => {
      const p = this.pointers.get(e.pointerId);
      if (!p) return;
      if (this.pointers.size === 2) {  // pinch: zoom by the change in the pointers' spread
        const [a, b] = [...this.pointers.values()];
        const before = Math.hypot(a.x - b.x, a.y - b.y);
        p.x = e.clientX, p.y = e.clientY;
        const after = Math.hypot(a.x - b.x, a.y - b.y);
        if (before > 0) this.setZoom(this.zoom * (after / before));
        return;
      }
      const dx = e.clientX - p.x, dy = e.clientY - p.y, dt = Math.max((e.timeStamp - p.t) / 1000, 1e-3);
      this.elevation = this.withinRows(this.elevation + dy * kDegreesPerPixel);
      this.azimuth = this._azimuth - dx * kDegreesPerPixel;
      this.velocity = draggedVelocity(this.velocity, -dx * kDegreesPerPixel, dt);
      Object.assign(p, { x: e.clientX, y: e.clientY, t: e.timeStamp });
    }, options);
    const up = (e) => {
      this.pointers.delete(e.pointerId);
      if (this.pointers.size === 0) c.classList.remove('dragging');
    };
    c.addEventListener('pointerup', up, options);
    c.addEventListener('pointercancel', up, options);
    c.addEventListener('wheel', (e) => {
      e.preventDefault();
      this.touched = true;
      this.setZoom(this.zoom * Math.pow(0.9, Math.sign(e.deltaY)));
    }, { passive: false, signal });
    this.addEventListener('keydown', (e) => {
      if (!e.key.startsWith('Arrow') || !this.snapshot) return;
      e.preventDefault();
      this.touched = true;
      this.velocity = 0;
      if (e.key === 'ArrowUp' || e.key === 'ArrowDown') {
        const rows = this.rowElevations(), i = nearestIndex(rows, this.elevation);
        this.elevation = rows[Math.min(Math.max(i + (e.key === 'ArrowUp' ? 1 : -1), 0), rows.length - 1)];
        this.redraw();
        return;
      }
      const dirs = this.snapshot.product.directions, d = this.direction();
      let nearest = 0;
      dirs.forEach((s, i) => { if (s[0] * d[0] + s[2] * d[2] > dirs[nearest][0] * d[0] + dirs[nearest][2] * d[2]) nearest = i; });
      const next = dirs[(nearest + (e.key === 'ArrowRight' ? 1 : -1) + dirs.length) % dirs.length];
      this.azimuth = (Math.atan2(next[0], next[2]) * 180) / Math.PI;
    }, options);
  }

  // The product's rows' elevations (degrees, lowest first): one for a single ring, a few for
  // rows, many on a geodesic sphere. Directions travel as i16: rows within half a degree are one.
  // Worked out once a product (every pointer move asks).
  rowElevations() {
    const { directions } = this.snapshot.product;
    if (this.rows?.directions !== directions) {
      const heights = directions.map((d) => (Math.asin(Math.min(Math.max(d[1], -1), 1)) * 180) / Math.PI).sort((a, b) => a - b);
      this.rows = { directions, elevations: heights.reduce((rows, h) => (rows.length && h - rows[rows.length - 1] < 0.5 ? rows : [...rows, h]), []) };
    }
    return this.rows.elevations;
  }

  // `elevation` kept where there are photos to synthesise the view from.
  withinRows(elevation) {
    if (!this.snapshot) return 0;
    const rows = this.rowElevations();
    return Math.min(Math.max(elevation, rows[0]), rows[rows.length - 1]);
  }

  setZoom(zoom) {
    this.zoom = Math.min(Math.max(zoom, kMinZoom), kMaxZoom);
    this.redraw();
  }
};
