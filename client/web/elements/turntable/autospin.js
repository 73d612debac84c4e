// <inkwire-turntable>'s motion between touches: auto-spin until the first touch (never under
// prefers-reduced-motion, nor with auto-rotate="off"), inertia after a drag. One animation loop
// while the element is in the page, whatever its attributes do.
import { coast } from '../../common/inertia.js';

const kAutoSpin = 20;  // degrees per second until the first touch

export const AutoSpinMixin = (Base) => class extends Base {
  connectedCallback() {
    super.connectedCallback();
    this.spin(this.connection);
  }

  // Auto-spin until the first touch, unless motion is unwelcome; then inertia after a drag. One
  // loop while the element is in the page, whatever its attributes do; it ends with `signal`.
  spin(signal) {
    const reduced = window.matchMedia?.('(prefers-reduced-motion: reduce)').matches;
    let last = performance.now();
    const step = (now) => {
      const dt = Math.min((now - last) / 1000, 0.1);
      last = now;
      if (signal.aborted) return;
      if (!this.touched && !reduced && this.getAttribute('auto-rotate') !== 'off' && this.hasAttribute('loaded')) this.azimuth = this._azimuth + kAutoSpin * dt;
      else if (this.velocity !== 0 && this.pointers.size === 0) {
        const { turn, velocity } = coast(this.velocity, dt);
        this.velocity = velocity;
        if (turn !== 0) this.azimuth = this._azimuth + turn;
      }
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  }

};
